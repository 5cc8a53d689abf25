// linkage-cli tolerance: a point's band over the cycle and its stroke's spread when dimensions
// vary within tolerances and pins have play (linkage/tolerance.h): first order and Monte Carlo.
#include <cmath>
#include <iostream>

#include "cli_common.h"
#include "cli_parser.h"
#include "linkage/cycle_spread.h"
#include "linkage/io/numbers.h"
#include "linkage/tolerance.h"

namespace linkage::cli {

namespace {

const char* kHelp =
    R"(usage: linkage-cli tolerance MODEL --point body.point --tol DIM=T [--tol DIM=T ...]
                                 [--play PIN=C ...] [--samples N] [--seed S] [--steps N]
                                 [--threads N] [--stroke-only]
       linkage-cli tolerance MODEL --clearance N | --window NAME --tol DIM=T [...]
                                 [--samples N] [--seed S]

The band of a point's x and y over one turn when dimensions of MODEL vary within symmetric
tolerances +-T and pins have a radial play C, and the spread of its stroke (the range of y over
the turn). A machine in space is carried in the world: the band of its x, y and z, its stroke
of the world's y; its dimensions include depths, the ground's z, ball rods' lengths and planes'
origins, each sample drawn exactly; a play of a pin whose free point is on the ground is
refused. First order from the exact sensitivities (as 'linkage-cli sensitivity'): worst case
sum |d/dp_k| T_k, root sum of squares sqrt(sum (d/dp_k T_k)^2); a play counts C times the
largest derivative over the direction its pin's point may sit. Monte Carlo: every dimension
uniform in [-T, T], every play's offset uniform over its disc (held over the turn), each
sample's design solved exactly at every crank angle on the nominal's branch, its stroke from
its own limit positions. Samples that do not assemble, lock or change branch are counted, not
used.

  --point body.point  the point (required)
  --tol DIM=T         a dimension (named as 'linkage-cli sensitivity' names them) and its
                      tolerance, in its unit (mm, degrees, ratio); repeat for more
  --play PIN=C        a pin's radial play C (mm), the pin named by its points body.P-body.Q
  --samples N         Monte Carlo samples (default 0: first order only)
  --seed S            the samples' seed (default 1); the same seed gives the same result on
                      any number of threads
  --steps N           crank angles per turn (default 360)
  --threads N         threads for the samples (default: every core)
  --stroke-only       Monte Carlo of the stroke alone (no band at each angle: faster)

Output, CSV: crank_deg,x_nominal_mm,y_nominal_mm,x_worst_mm,y_worst_mm,x_rss_mm,y_rss_mm,
x_mc_lo_mm,x_mc_hi_mm,y_mc_lo_mm,y_mc_hi_mm,x_mc_sd_mm,y_mc_sd_mm,first_order; a machine in
space has z's columns after y's in each group (z_nominal_mm, z_worst_mm, z_rss_mm, z_mc_lo_mm,
z_mc_hi_mm, z_mc_sd_mm). Worst and RSS
are half-widths about the nominal; the Monte Carlo columns the samples' least and greatest
positions and standard deviation (empty without samples or with --stroke-only); first_order is
'ok', 'fails' (the samples leave first order here: near a toggle) or 'unbounded' (a singular
position: worst and RSS empty). The stroke's spread, the samples that failed and the angles
where first order fails are written on standard error.

  --clearance N       instead, the spread of the file's watched clearance N's closest approach
                      ("timing"'s "clearances", from 0); --point not needed
  --window NAME       instead, the spread of the ends of the file's timing window NAME
With --clearance or --window (dimensions only, no --play): CSV
quantity,nominal,worst,rss,mc_lo,mc_hi,mc_mean,mc_sd, a row for the closest approach
(clearance_min_mm) or each interval's start and end (NAME_K_from_deg, NAME_K_to_deg).

Exit status: 0 done, 2 bad input (an unknown dimension, pin or point, a bad DIM=T), 3 the
nominal crank cannot turn fully.
)";

struct Options {
  std::string model, point;
  std::vector<std::string> tols, plays;
  int samples = 0, steps = 360, threads = 0;
  long long seed = 1;
  bool strokeOnly = false;
  int clearance = -1;
  std::string window;
};

bool parseTol(const std::string& text, bool play, ToleranceSpec& spec) {
  const size_t eq = text.rfind('=');
  const std::optional<double> t =
      eq == std::string::npos ? std::nullopt : parseNumber(text.substr(eq + 1));
  if (!t || eq == 0) {
    error(std::string(play ? "--play" : "--tol") + " " + text + ": expected " +
          (play ? "PIN=C" : "DIM=T") + " with a number after '='");
    return false;
  }
  spec.tolerances.push_back({text.substr(0, eq), *t, play});
  return true;
}

void field(std::string& out, double v, bool given = true) {
  out += ',';
  if (given) out += formatNumber(v);
}

// A machine in space's: the planar columns with z's after y's in each group.
std::string spaceRows(const ToleranceResult& r, bool mc) {
  std::string out =
      "crank_deg,x_nominal_mm,y_nominal_mm,z_nominal_mm,x_worst_mm,y_worst_mm,z_worst_mm,"
      "x_rss_mm,y_rss_mm,z_rss_mm,x_mc_lo_mm,x_mc_hi_mm,y_mc_lo_mm,y_mc_hi_mm,z_mc_lo_mm,"
      "z_mc_hi_mm,x_mc_sd_mm,y_mc_sd_mm,z_mc_sd_mm,first_order\n";
  for (const ToleranceRow& row : r.rows) {
    out += formatNumber(row.crankDeg);
    for (int c = 0; c < 3; ++c) field(out, row.nominal[c]);
    for (const Vec3* v : {&row.worst, &row.rss})
      for (int c = 0; c < 3; ++c) field(out, (*v)[c], row.firstOrder);
    for (int c = 0; c < 3; ++c) {
      field(out, row.lo[c], mc);
      field(out, row.hi[c], mc);
    }
    for (int c = 0; c < 3; ++c) field(out, row.sd[c], mc);
    out += !row.firstOrder ? ",unbounded\n" : row.nonlinear ? ",fails\n" : ",ok\n";
  }
  return out;
}

std::string rows(const ToleranceResult& r, bool mc) {
  if (r.space) return spaceRows(r, mc);
  std::string out =
      "crank_deg,x_nominal_mm,y_nominal_mm,x_worst_mm,y_worst_mm,x_rss_mm,y_rss_mm,x_mc_lo_mm,"
      "x_mc_hi_mm,y_mc_lo_mm,y_mc_hi_mm,x_mc_sd_mm,y_mc_sd_mm,first_order\n";
  for (const ToleranceRow& row : r.rows) {
    out += formatNumber(row.crankDeg);
    for (double v : {row.nominal.x(), row.nominal.y()}) field(out, v);
    for (double v : {row.worst.x(), row.worst.y(), row.rss.x(), row.rss.y()})
      field(out, v, row.firstOrder);
    for (double v : {row.lo.x(), row.hi.x(), row.lo.y(), row.hi.y(), row.sd.x(), row.sd.y()})
      field(out, v, mc);
    out += !row.firstOrder ? ",unbounded\n" : row.nonlinear ? ",fails\n" : ",ok\n";
  }
  return out;
}

void summary(const ToleranceResult& r, const ToleranceSpec& spec) {
  const StrokeSpread& s = r.stroke;
  std::string t = std::string(r.space ? "stroke of the world's y: " : "stroke of y: ") +
                  formatNumber(s.nominal) + " mm (largest at " + formatNumber(s.maxDeg) +
                  " deg, least at " + formatNumber(s.minDeg) + " deg)";
  if (s.firstOrder)
    t += "; first order: worst +-" + formatNumber(s.worst) + " mm, RSS +-" + formatNumber(s.rss);
  note(t);
  if (r.samples > 0) {
    note("Monte Carlo: " + std::to_string(r.samples) + " samples (uniform in the tolerances, " +
         "plays uniform over their discs), seed " + std::to_string(spec.seed) + ", " +
         std::to_string(r.used) + " used");
    if (r.used > 0)
      note("stroke over the samples: " + formatNumber(s.lo) + " to " + formatNumber(s.hi) +
           " mm, mean " + formatNumber(s.mean) + ", standard deviation " + formatNumber(s.sd) +
           (s.nonlinear ? " (first order fails for the stroke)" : ""));
  }
  if (r.failed > 0) {
    std::string f =
        std::to_string(r.failed) + " samples failed (not used); the first: " + r.firstFailure;
    if (!std::isnan(r.stopLoDeg))
      f += "; they stopped between crank angles " + formatNumber(r.stopLoDeg) + " and " +
           formatNumber(r.stopHiDeg) + " deg";
    note(f);
  }
  if (!r.nonlinearDeg.empty()) {
    std::string a;
    for (double d : r.nonlinearDeg) a += (a.empty() ? "" : " ") + formatNumber(d);
    note("first order is not enough at crank angles (deg): " + a);
  }
}

// A clearance's or a window's spread (linkage/cycle_spread.h).
int cycleSpread(const Mechanism& m, const Options& o, ToleranceSpec& spec) {
  SpreadResult r;
  std::vector<std::string> names;
  if (o.clearance >= 0) {
    if (o.clearance >= static_cast<int>(m.timing.clearances.size())) {
      error("--clearance " + std::to_string(o.clearance) + ": the file watches " +
            std::to_string(m.timing.clearances.size()) + " clearance(s), counted from 0");
      return kBadInput;
    }
    r = clearanceSpread(m, spec, m.timing.clearances[o.clearance]);
    names = {"clearance_min_mm"};
  } else {
    r = windowSpread(m, spec, o.window);
    for (size_t i = 0; i < r.values.size(); ++i)
      names.push_back(o.window + "_" + std::to_string(i / 2) + (i % 2 ? "_to_deg" : "_from_deg"));
  }
  if (!r.status.ok()) {
    error("tolerance: " + r.status.message);
    return exitFor(r.status);
  }
  std::string out = "quantity,nominal,worst,rss,mc_lo,mc_hi,mc_mean,mc_sd\n";
  for (size_t i = 0; i < r.values.size(); ++i) {
    const Spread& x = r.values[i];
    out += names[i];
    for (double v : {x.nominal, x.worst, x.rss}) field(out, v);
    for (double v : {x.lo, x.hi, x.mean, x.sd}) field(out, v, r.used > 0);
    out += '\n';
  }
  std::cout << out << std::flush;
  if (r.samples > 0)
    note("Monte Carlo: " + std::to_string(r.samples) + " samples, seed " +
         std::to_string(spec.seed) + ", " + std::to_string(r.used) + " used" +
         (r.firstFailure.empty() ? "" : "; the first not used: " + r.firstFailure));
  return kOk;
}

int tolerance(const Options& o) {
  std::optional<Mechanism> m = openDrivenModel(o.model);
  if (!m) return kBadInput;
  if (o.clearance >= 0 || !o.window.empty()) {
    ToleranceSpec spec;
    for (const std::string& t : o.tols)
      if (!parseTol(t, false, spec)) return kBadInput;
    for (const std::string& t : o.plays)
      if (!parseTol(t, true, spec)) return kBadInput;
    spec.samples = o.samples;
    spec.seed = static_cast<std::uint64_t>(o.seed);
    return cycleSpread(*m, o, spec);
  }
  if (o.point.empty()) {
    error("tolerance: --point body.point is required (or --clearance N, --window NAME)");
    return kBadInput;
  }
  std::optional<std::vector<PointId>> ids = outputPoints(*m, {o.point});
  if (!ids) return kBadInput;
  ToleranceSpec spec;
  spec.point = ids->front();
  for (const std::string& t : o.tols)
    if (!parseTol(t, false, spec)) return kBadInput;
  for (const std::string& t : o.plays)
    if (!parseTol(t, true, spec)) return kBadInput;
  spec.samples = o.samples;
  spec.seed = static_cast<std::uint64_t>(o.seed);
  spec.steps = o.steps;
  spec.threads = o.threads;
  spec.band = !o.strokeOnly;
  const ToleranceResult r = tolerances(*m, spec);
  if (!r.status.ok()) {
    error("tolerance: " + r.status.message);
    return exitFor(r.status);
  }
  std::cout << rows(r, o.samples > 0 && !o.strokeOnly) << std::flush;
  summary(r, spec);
  return kOk;
}

}  // namespace

Command toleranceCommand(Parser& parser) {
  auto o = std::make_shared<Options>();
  CLI::App& c = parser.command("tolerance", kHelp);
  addModel(c, o->model);
  addText(c, "--point", o->point);
  addTexts(c, "--tol", o->tols);
  addTexts(c, "--play", o->plays);
  addWhole(c, "--samples", o->samples, 0, 100'000'000);
  addWhole(c, "--seed", o->seed, 0, 9'000'000'000'000'000'000LL);
  addWhole(c, "--steps", o->steps, 4, 1'000'000);
  addWhole(c, "--threads", o->threads, 0, 256);
  addFlag(c, "--stroke-only", o->strokeOnly);
  addWhole(c, "--clearance", o->clearance, 0, 1'000'000);
  addText(c, "--window", o->window);
  return {&c, [o] { return tolerance(*o); }};
}

}  // namespace linkage::cli
