// linkage-cli optimize: dimensions found for targets (linkage/optimize.h).
#include <cstdio>
#include <fstream>
#include <sstream>

#include "cli_common.h"
#include "cli_parser.h"
#include "linkage/io/model_file.h"
#include "linkage/io/numbers.h"
#include "linkage/optimize.h"
#include "linkage/optimize_text.h"
#include "linkage/sensitivity.h"
#include "linkage/transmission.h"

namespace linkage::cli {

namespace {

const char* kHelp =
    R"(usage: linkage-cli optimize MODEL --vary DIM=LO:HI [--vary ...] --target TARGET [--target ...]
                                [--starts K] [--seed S] [--steps N] [--out RESULT.linkage.json]

Finds the dimensions (named as `sensitivity` names them: crank.O2-A, ground.F.x, ...) within their
bounds that meet the targets best: the weighted sum of squares of the targets' residuals is
minimised by NLopt's SLSQP from K starts (the first the design as it is, the others uniform in
the bounds from the seed), fed by the exact sensitivities. A design that does not assemble or
whose crank does not turn fully is infeasible (never taken). Every design is solved from MODEL's
pose on MODEL's assembly branches.

  --vary DIM=LO:HI            a dimension to vary, and its bounds (repeatable)
  --target TARGET             (repeatable), each optionally followed by *WEIGHT (default 1):
     stroke:body.point=MM            the point's stroke (extremes over the turn along its default
                                     direction: its ground slot's, else y; in space the world's y)
     stroke:body.point@DIR=MM        along DIR instead: x, y, z or DX,DY[,DZ] (z and DZ a machine
                                     in space's, in the world)
     position:body.point@DEG=X,Y[,Z] the point at crank angle DEG (Z: a machine in space's world
                                     z; without it x and y only)
     path:body.point=FILE.csv        the point's path through the points of FILE (x,y a line, an
                                     optional header; in space x,y,z in the world, or x,y: the
                                     world's x and y only): each one's distance to the nearest
                                     point of the curve over the turn; lines starting with # are
                                     comments
     transmission:mu:body.point>=DEG a dyad's transmission angle (as `transmission` names it)
                                     within DEG to 180 - DEG over the turn
     shaking:fx<=N                   the peak of the shaking force's |fx| (fy, fz in space, or
                                     force: |f|)
                                     over the turn at most N newtons (0: as low as it goes)
     shaking:moment<=NM              the peak of the shaking moment's |m| about the drawing's
                                     origin (in space the world's m about its origin) at most NM
                                     newton metres (over dimensions or counterweights)
     force:JOINT<=N                  the peak over the turn of a joint's reaction |f| (JOINT as
                                     `dynamics` names it: pin:crank.A, slider:block.B) at most
                                     N newtons (over dimensions or counterweights); in space a
                                     body's bearing's load out of its plane, as well:
                                     force:JOINT:fn<=N its normal force |fn|, force:JOINT:tilt<=NM
                                     its tilts' |(mx, my)| (newton metres)
     clearance:N>=GAP                the file's watched clearance N (from 0) at least GAP mm at
                                     its closest approach
     window:NAME.start=DEG           the first interval of the file's timing window NAME opens
                                     (window:NAME.end=DEG: closes) at crank angle DEG
  A variable may also be a counterweight added to a body pinned to the ground:
     BODY.counterweight.x, BODY.counterweight.y   its static moment (kg mm) in the body's drawing
                                     from its pivot (as `balance` places it); with
                                     dimensions too, but for a force:JOINT target
  --starts K                  starts (default 16)
  --seed S                    seed of the starts (default 1)
  --steps N                   samples per turn for extremes and nearest points (default 360)
  --out FILE                  write the optimised model (atomically)

Output, CSV: quantity,name,before,after,target. A row a variable (variable,DIM); a row a target's
measure: stroke_mm (body.point), x_mm and y_mm (and z_mm) (body.point@DEG), path_rms_mm and path_max_mm (the
given points' distances to the curve), shaking_peak_N and shaking_peak_deg (fx, fy or force),
shaking_peak_Nm and shaking_peak_deg (moment),
force_peak_N and force_peak_deg (JOINT, JOINT:fn; force_peak_Nm with JOINT:tilt),
clearance_least_mm and clearance_least_deg (clearance N), window_deg (NAME.start or NAME.end);
a row a counterweight added (counterweight_kg,BODY: its mass, at the body's reach); the objective (mm^2, N^2, ...); the starts, those infeasible and
those that found the best (within 1e-9 mm^2 + 1e-6 of it). A design infeasible as drawn leaves
its before fields empty.

A machine in space (planes, docs/spatial.md): any dimension `sensitivity` lists may vary (depths,
ground z, ball rods' lengths, planes' origins), and counterweights; the
targets are in the world (a transmission angle in its plane), a reaction in its plane (a ball
rod's tension) with the counterweights' shares, and the shaking force and moment in the world
over counterweights too.

Exit status: 0 done, 1 the --out file could not be written, 2 bad input (an unknown dimension or
point, bad bounds or target, no start that assembles and turns fully).
)";

struct Options {
  std::string model, out;
  std::vector<std::string> vary, targets;
  int starts = 16, steps = 360;
  long long seed = 1;
};

std::string field(const Evaluation& e, size_t target, size_t k) {
  if (!e.feasible || target >= e.measures.size() || k >= e.measures[target].size()) return "";
  return formatNumber(e.measures[target][k]);
}

std::string table(const OptimizeSpec& spec, const std::vector<std::string>& names,
                  const OptimizeResult& r) {
  std::string out = "quantity,name,before,after,target\n";
  for (size_t i = 0; i < spec.variables.size(); ++i)
    out += "variable," + spec.variables[i].name + "," + formatNumber(r.before[i]) + "," +
           formatNumber(r.after[i]) + ",\n";
  for (size_t i = 0; i < spec.targets.size(); ++i) {
    const OptTarget& t = spec.targets[i];
    auto row = [&](const char* what, size_t k, const std::string& wanted) {
      out += std::string(what) + "," + names[i] + "," + field(r.atBefore, i, k) + "," +
             field(r.atAfter, i, k) + "," + wanted + "\n";
    };
    if (t.kind == OptTarget::Kind::Stroke) {
      row("stroke_mm", 0, formatNumber(t.stroke));
    } else if (t.kind == OptTarget::Kind::Position) {
      row("x_mm", 0, formatNumber(t.at.x()));
      row("y_mm", 1, formatNumber(t.at.y()));
      if (t.z) row("z_mm", 2, formatNumber(*t.z));
    } else if (t.kind == OptTarget::Kind::Transmission) {
      row("transmission_min_deg", 0, ">=" + formatNumber(t.limitDeg));
      row("transmission_max_deg", 1, "<=" + formatNumber(180 - t.limitDeg));
    } else if (t.kind == OptTarget::Kind::Shaking) {
      row(t.moment ? "shaking_peak_Nm" : "shaking_peak_N", 0, "<=" + formatNumber(t.limitN));
      row("shaking_peak_deg", 1, "");
    } else if (t.kind == OptTarget::Kind::Force) {
      const bool tilt = t.reaction == OptTarget::Reaction::Tilt;
      row(tilt ? "force_peak_Nm" : "force_peak_N", 0, "<=" + formatNumber(t.limitN));
      row("force_peak_deg", 1, "");
    } else if (t.kind == OptTarget::Kind::Clearance) {
      row("clearance_least_mm", 0, ">=" + formatNumber(t.gapMm));
      row("clearance_least_deg", 1, "");
    } else if (t.kind == OptTarget::Kind::Window) {
      row("window_deg", 0, formatNumber(t.crankDeg));
    } else {
      row("path_rms_mm", 0, "0");
      row("path_max_mm", 1, "0");
    }
  }
  for (const Counterweight& c : r.counterweights)
    out += "counterweight_kg," + r.design.body(c.body)->name + ",," + formatNumber(c.kg) + ",\n";
  out += "objective,," + (r.atBefore.feasible ? formatNumber(r.atBefore.objective) : "") + "," +
         formatNumber(r.atAfter.objective) + ",\n";
  out += "starts,," + std::to_string(r.starts) + ",,\n";
  out += "starts_infeasible,," + std::to_string(r.infeasibleStarts) + ",,\n";
  out += "starts_found_best,," + std::to_string(r.foundBest) + ",,\n";
  return out;
}

int optimizeModel(const Options& o) {
  std::optional<Mechanism> m = openDrivenModel(o.model);
  if (!m) return kBadInput;
  OptimizeSpec spec;
  spec.starts = o.starts;
  spec.steps = o.steps;
  spec.seed = static_cast<std::uint64_t>(o.seed);
  for (const std::string& v : o.vary) {
    OptVariable var;
    if (!parseOptVary(v, var)) {
      error("--vary " + v + ": expected DIM=LO:HI");
      return kBadInput;
    }
    spec.variables.push_back(var);
  }
  std::vector<std::string> names;  // the table's: body.point, @DEG for a position
  for (const std::string& text : o.targets) {
    OptTarget t;
    std::string why;
    if (!parseOptTarget(*m, text, t, why)) {
      error(why);
      return kBadInput;
    }
    spec.targets.push_back(t);
    names.push_back(optTargetName(*m, t));
  }
  Kinematics k;
  if (int e = prepare(k, *m); e != kOk) return e;
  const OptimizeResult r = optimize(k, spec);
  if (!r.status.ok()) {
    error("optimize: " + r.status.message);
    return kBadInput;
  }
  if (!r.atBefore.feasible) note("as drawn the design is infeasible: " + r.atBefore.why);
  std::fputs(table(spec, names, r).c_str(), stdout);
  if (!o.out.empty()) {
    const WriteResult w = saveMechanismFile(r.design, o.out);
    if (!w.ok) {
      error(w.error.rfind(o.out, 0) == 0 ? w.error : o.out + ": " + w.error);
      return kFailure;
    }
  }
  return kOk;
}

}  // namespace

Command optimizeCommand(Parser& parser) {
  auto o = std::make_shared<Options>();
  CLI::App& c = parser.command("optimize", kHelp);
  addModel(c, o->model);
  required(addTexts(c, "--vary", o->vary));
  required(addTexts(c, "--target", o->targets));
  addWhole(c, "--starts", o->starts, 1, 100'000);
  addWhole(c, "--seed", o->seed, 0, 1'000'000'000'000LL);
  addWhole(c, "--steps", o->steps, 4, 1'000'000);
  addText(c, "--out", o->out);
  return {&c, [o] { return optimizeModel(*o); }};
}

}  // namespace linkage::cli
