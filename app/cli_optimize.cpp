// linkage-cli optimize: dimensions found for targets (linkage/optimize.h).
#include <cstdio>
#include <fstream>
#include <sstream>

#include "cli_common.h"
#include "cli_parser.h"
#include "linkage/io/model_file.h"
#include "linkage/io/numbers.h"
#include "linkage/optimize.h"
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
                                     direction: its ground slot's, else y)
     position:body.point@DEG=X,Y     the point at crank angle DEG
     path:body.point=FILE.csv        the point's path through the points of FILE (x,y a line, an
                                     optional header): each one's distance to the nearest point of
                                     the curve over the turn; lines starting with # are comments
     transmission:mu:body.point>=DEG a dyad's transmission angle (as `transmission` names it)
                                     within DEG to 180 - DEG over the turn
     shaking:fx<=N                   the peak of the shaking force's |fx| (fy, or force: |f|)
                                     over the turn at most N newtons (0: as low as it goes)
  A variable may also be a counterweight added to a body pinned to the ground:
     BODY.counterweight.x, BODY.counterweight.y   its static moment (kg mm) in the body's drawing
                                     from its pivot (as `balance` places it); not together
                                     with dimensions
  --starts K                  starts (default 16)
  --seed S                    seed of the starts (default 1)
  --steps N                   samples per turn for extremes and nearest points (default 360)
  --out FILE                  write the optimised model (atomically)

Output, CSV: quantity,name,before,after,target. A row a variable (variable,DIM); a row a target's
measure: stroke_mm (body.point), x_mm and y_mm (body.point@DEG), path_rms_mm and path_max_mm (the
given points' distances to the curve), shaking_peak_N and shaking_peak_deg (fx, fy or force);
a row a counterweight added (counterweight_kg,BODY: its mass, at the body's reach); the objective (mm^2, N^2, ...); the starts, those infeasible and
those that found the best (within 1e-9 mm^2 + 1e-6 of it). A design infeasible as drawn leaves
its before fields empty.

Exit status: 0 done, 1 the --out file could not be written, 2 bad input (an unknown dimension or
point, bad bounds or target, no start that assembles and turns fully).
)";

struct Options {
  std::string model, out;
  std::vector<std::string> vary, targets;
  int starts = 16, steps = 360;
  long long seed = 1;
};

std::optional<Vec2> parsePair(const std::string& s) {
  const size_t c = s.find(',');
  if (c == std::string::npos) return std::nullopt;
  auto x = parseNumber(s.substr(0, c)), y = parseNumber(s.substr(c + 1));
  if (!x || !y) return std::nullopt;
  return Vec2(*x, *y);
}

bool parseVary(const std::string& text, OptVariable& v) {
  const size_t eq = text.rfind('='), colon = text.rfind(':');
  if (eq == std::string::npos || colon == std::string::npos || colon < eq) return false;
  auto lo = parseNumber(text.substr(eq + 1, colon - eq - 1)),
       hi = parseNumber(text.substr(colon + 1));
  if (!lo || !hi) return false;
  v = {text.substr(0, eq), *lo, *hi};
  return true;
}

// FILE.csv: x,y a line; a first line that is not two numbers is a header.
bool readPath(const std::string& file, std::vector<Vec2>& out, std::string& why) {
  std::ifstream in(file);
  if (!in) {
    why = file + ": cannot be read";
    return false;
  }
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;  // comments (a source cited, as four-bar-rs does)
    std::optional<Vec2> p = parsePair(line);
    if (!p && n == 1) continue;
    if (!p) {
      why = file + ":" + std::to_string(n) + ": not two numbers x,y";
      return false;
    }
    out.push_back(*p);
  }
  if (out.empty()) why = file + ": no points";
  return !out.empty();
}

// transmission:[mu:]body.point>=DEG, the joint named as `transmission` names it.
bool parseTransmission(const Mechanism& m, const std::string& text, OptTarget& t,
                       std::string& why) {
  const size_t ge = text.find(">=");
  auto deg = ge == std::string::npos ? std::nullopt : parseNumber(text.substr(ge + 2));
  if (!deg) return why += "expected transmission:mu:body.point>=DEG", false;
  std::string name = text.substr(13, ge - 13);
  if (name.rfind("mu:", 0) != 0) name = "mu:" + name;
  const std::vector<TransmissionJoint> js = transmissionJoints(m);
  for (size_t j = 0; j < js.size(); ++j)
    if (js[j].label == name) {
      t.kind = OptTarget::Kind::Transmission;
      t.joint = j;
      t.limitDeg = *deg;
      t.point = m.joint(js[j].joint)->a;
      return true;
    }
  std::string known;
  for (const TransmissionJoint& j : js) known += (known.empty() ? "" : ", ") + j.label;
  return why += "no transmission angle '" + name + "' (the model's: " + known + ")", false;
}

// shaking:fx<=N (fy, force)
bool parseShaking(const std::string& text, OptTarget& t, std::string& why) {
  const std::string usage = "expected shaking:fx<=N (fx, fy or force; N >= 0)";
  const size_t le = text.find("<=");
  if (le == std::string::npos) return why += usage, false;
  const std::string what = text.substr(8, le - 8);
  const std::optional<double> n = parseNumber(text.substr(le + 2));
  if (!n.has_value() || !(n.value() >= 0) || (what != "fx" && what != "fy" && what != "force"))
    return why += usage, false;
  t.kind = OptTarget::Kind::Shaking;
  t.measure = what == "fx"   ? BalanceMeasure::Fx
              : what == "fy" ? BalanceMeasure::Fy
                             : BalanceMeasure::Force;
  t.limitN = n.value();
  return true;
}

// KIND:body.point=VALUE[*WEIGHT]
bool parseTarget(const Mechanism& m, std::string text, OptTarget& t, std::string& why) {
  why = "--target " + text + ": ";
  if (const size_t star = text.rfind('*'); star != std::string::npos) {
    auto w = parseNumber(text.substr(star + 1));
    if (!w || !(*w > 0)) return why += "the weight after * must be a positive number", false;
    t.weight = *w;
    text = text.substr(0, star);
  }
  if (text.rfind("transmission:", 0) == 0) return parseTransmission(m, text, t, why);
  if (text.rfind("shaking:", 0) == 0) return parseShaking(text, t, why);
  const size_t colon = text.find(':'), eq = text.find('=');
  if (colon == std::string::npos || eq == std::string::npos || eq < colon)
    return why += "expected KIND:body.point=VALUE", false;
  const std::string kind = text.substr(0, colon), value = text.substr(eq + 1);
  std::string point = text.substr(colon + 1, eq - colon - 1);
  if (kind == "position") {
    const size_t at = point.find('@');
    auto deg = at == std::string::npos ? std::nullopt : parseNumber(point.substr(at + 1));
    std::optional<Vec2> xy = parsePair(value);
    if (!deg || !xy) return why += "expected position:body.point@DEG=X,Y", false;
    t.kind = OptTarget::Kind::Position;
    t.crankDeg = *deg;
    t.at = *xy;
    point = point.substr(0, at);
  } else if (kind == "stroke") {
    auto mm = parseNumber(value);
    if (!mm || !(*mm >= 0)) return why += "the stroke must be a number >= 0", false;
    t.kind = OptTarget::Kind::Stroke;
    t.stroke = *mm;
  } else if (kind == "path") {
    t.kind = OptTarget::Kind::Path;
    std::string fileWhy;
    if (!readPath(value, t.path, fileWhy)) return why += fileWhy, false;
  } else {
    return why += "unknown kind '" + kind + "' (stroke, position, path, transmission, shaking)",
           false;
  }
  std::optional<PointId> p = m.findPoint(point);
  if (!p) return why += "no point '" + point + "' in the model", false;
  t.point = *p;
  return true;
}

std::string shakingName(BalanceMeasure m) {
  return m == BalanceMeasure::Fx ? "fx" : m == BalanceMeasure::Fy ? "fy" : "force";
}

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
    } else if (t.kind == OptTarget::Kind::Transmission) {
      row("transmission_min_deg", 0, ">=" + formatNumber(t.limitDeg));
      row("transmission_max_deg", 1, "<=" + formatNumber(180 - t.limitDeg));
    } else if (t.kind == OptTarget::Kind::Shaking) {
      row("shaking_peak_N", 0, "<=" + formatNumber(t.limitN));
      row("shaking_peak_deg", 1, "");
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
    if (!parseVary(v, var)) {
      error("--vary " + v + ": expected DIM=LO:HI");
      return kBadInput;
    }
    spec.variables.push_back(var);
  }
  std::vector<std::string> names;  // the table's: body.point, @DEG for a position
  for (const std::string& text : o.targets) {
    OptTarget t;
    std::string why;
    if (!parseTarget(*m, text, t, why)) {
      error(why);
      return kBadInput;
    }
    spec.targets.push_back(t);
    names.push_back(t.kind == OptTarget::Kind::Shaking ? shakingName(t.measure)
                                                       : m->pointLabel(t.point));
    if (t.kind == OptTarget::Kind::Position)
      names.back().append("@").append(formatNumber(t.crankDeg));
    if (t.kind == OptTarget::Kind::Transmission) names.back().insert(0, "mu:");
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
