// linkage-cli transmission: the transmission angle at every joint where a link drives another
// body, over a turn of the crank, checked against a band (linkage/transmission.h).
#include <cstdio>
#include <iostream>

#include "cli_common.h"
#include "cli_parser.h"
#include "linkage/io/numbers.h"
#include "linkage/transmission.h"

namespace linkage::cli {

namespace {

const char* kHelp = R"(usage: linkage-cli transmission MODEL [--steps N] [--band LO,HI]

The transmission angles of MODEL over one turn of the crank, at every joint where a link drives
another body: in a pin-pin-pin dyad the angle between its two links at their middle pin (0 to
180 degrees); where a rod drives a slider block, or its own end runs in a slot, 90 degrees minus
the angle between the rod and the slot. The joints are found from the mechanism's structure.

  --steps N     rows per turn: crank angles 0, 360/N, ..., 360 (default 360)
  --band LO,HI  the band every angle should stay in, degrees (default 30,150)

Output, CSV: crank_deg, then one column per joint, headed mu:<a> with the joint's `a` point as
in the file (e.g. mu:coupler.B), degrees, 17 significant digits. On standard error, for each
joint: its exact minimum and maximum with their crank angles (root finding to 1e-9 degree) and
the stretches of crank angle where it is outside the band.

Exit status: 0 every angle stays in the band, 4 some leave it (the rows are still written),
2 bad input, 3 the crank cannot turn fully (the rows up to there are written, then the reason).
)";

constexpr int kOutOfBand = 4;

std::string deg(double v) {
  return formatShown(v, 360);
}

std::string describe(const Mechanism& m, const TransmissionJoint& t) {
  if (t.kind == TransmissionKind::Dyad)
    return "dyad " + m.body(t.link)->name + "-" + m.body(t.other)->name;
  return std::string(toString(t.kind)) + " " + m.body(t.link)->name + " in " + m.slotLabel(t.slot);
}

struct Options {
  std::string model;
  int steps = 360;
  std::optional<Vec2> band;
};

int transmission(const Options& o) {
  TransmissionOptions opt;
  opt.steps = o.steps;
  if (o.band) opt.band = {o.band->x(), o.band->y()};
  std::optional<Mechanism> m = openDrivenModel(o.model);
  if (!m) return kBadInput;
  Kinematics k;
  if (int e = prepare(k, *m); e != kOk) return e;
  const TransmissionSweep s = sweepTransmission(k, opt);
  std::string out = "crank_deg";
  // append, not operator+: g++ 12 -Wrestrict false alarm (as in motion_table.cpp)
  for (const TransmissionJoint& t : s.joints) out.append(",").append(t.label);
  out += "\n";
  for (size_t i = 0; i < s.crankDeg.size(); ++i) {
    out += formatNumber(s.crankDeg[i]);
    for (const std::vector<double>& v : s.values) out.append(",").append(formatNumber(v[i]));
    out += "\n";
  }
  std::fwrite(out.data(), 1, out.size(), stdout);
  std::fflush(stdout);
  if (!s.status.ok()) {
    error(s.status.message);
    return exitFor(s.status);
  }
  if (s.joints.empty()) {
    note("no joint where a link drives another body through a pin or a slider: nothing to check");
    return kOk;
  }
  const std::string band = deg(opt.band.lo) + " to " + deg(opt.band.hi) + " degrees";
  for (size_t j = 0; j < s.joints.size(); ++j) {
    const TransmissionSummary& r = s.summaries[j];
    std::string line = s.joints[j].label + " (" + describe(*m, s.joints[j]) + "): min " +
                       deg(r.min) + " at " + deg(r.minDeg) + ", max " + deg(r.max) + " at " +
                       deg(r.maxDeg) + " deg of crank";
    if (r.inBand()) line += "; within " + band;
    for (const TransmissionStretch& x : r.outside)
      line += std::string("; ") + (x.below ? "below " : "above ") +
              deg(x.below ? opt.band.lo : opt.band.hi) + " from " + deg(x.fromDeg) + " to " +
              deg(x.toDeg) + " deg";
    std::cerr << line << "\n";
  }
  if (s.inBand()) {
    std::cerr << "every transmission angle stays within " << band << "\n";
    return kOk;
  }
  std::cerr << "some transmission angles leave " << band << "\n";
  return kOutOfBand;
}

}  // namespace

Command transmissionCommand(Parser& parser) {
  auto o = std::make_shared<Options>();
  CLI::App& c = parser.command("transmission", kHelp);
  addModel(c, o->model);
  addWhole(c, "--steps", o->steps, 4, 1'000'000);
  addPair(c, "--band", o->band, PairRule::Increasing);
  return {&c, [o] { return transmission(*o); }};
}

}  // namespace linkage::cli
