// linkage-cli clearance: the distance between two moving things (two points, or a point and a
// slot of another body) over a turn of the crank, every local minimum and the closest approach
// (linkage/clearance.h).
#include <iostream>

#include "cli_common.h"
#include "cli_parser.h"
#include "linkage/clearance.h"
#include "linkage/io/numbers.h"

namespace linkage::cli {

namespace {

const char* kHelp = R"(usage: linkage-cli clearance MODEL --between A B [--min MM] [--steps N]

The distance between A and B over one turn of the crank of MODEL: every local minimum, found
to 1e-9 degree of crank by root finding on the distance's exact derivative, and the closest
approach. A and B are points (body.point) or one of them a slot of another body (body.slot):
the distance from the point to the slot's line or, for an arc slot, its circle, continued
beyond the slot's drawn ends.

  --between A B  the two things
  --min MM       the least clearance allowed: exit 4 when the closest is under it
  --steps N      sampling intervals that bracket the minima (default 360)

Output, CSV: event,crank_deg,distance_mm; a "min" row per local minimum in crank order (crank
angles in [0, 360)), then "closest,CRANK,DIST". 17 significant digits.

Exit status: 0 success, 4 the closest is under --min (the rows are still written), 2 bad
input (the message names the argument), 3 the crank cannot turn fully.
)";

constexpr int kTooClose = 4;

// "body.point" or "body.slot" (a point first when a body has both of that name).
std::optional<ClearanceItem> item(const Mechanism& m, const std::string& text) {
  if (std::optional<PointId> p = m.findPoint(text)) return ClearanceItem::of(*p);
  const size_t dot = text.rfind('.');
  if (dot != std::string::npos) {
    if (const Body* b = m.bodyNamed(text.substr(0, dot)))
      if (const Slot* s = m.slotNamed(b->id, text.substr(dot + 1))) return ClearanceItem::of(s->id);
  }
  error("--between " + text + ": no point or slot of that name (body.point or body.slot)");
  return std::nullopt;
}

struct Options {
  std::string model;
  std::pair<std::string, std::string> between;
  std::optional<double> min;
  int steps = 360;
};

// The options, read into `o`.
CLI::App* addOptions(Parser& parser, Options& o) {
  CLI::App& c = parser.command("clearance", kHelp);
  addModel(c, o.model);
  required(addTextPair(c, "--between", o.between, "A B"));
  addNumber(c, "--min", o.min, NumberRule::NotNegative);
  addWhole(c, "--steps", o.steps, 4, 1'000'000);
  return &c;
}

int clearance(const Options& o) {
  std::optional<Mechanism> m = openDrivenModel(o.model);
  if (!m) return kBadInput;
  const std::optional<ClearanceItem> a = item(*m, o.between.first), b = item(*m, o.between.second);
  if (!a || !b) return kBadInput;
  Kinematics k;
  if (int e = prepare(k, *m); e != kOk) return e;
  ClearanceOptions opt;
  opt.steps = o.steps;
  const Clearance c = findClearance(k, *a, *b, opt);
  if (!c.status.ok()) {
    error("--between " + o.between.first + " " + o.between.second + ": " + c.status.message);
    return exitFor(c.status);
  }
  std::string out = "event,crank_deg,distance_mm\n";
  for (const ClearanceEvent& e : c.minima)
    out += "min," + formatNumber(e.crankDeg) + "," + formatNumber(e.distance) + "\n";
  out +=
      "closest," + formatNumber(c.closest.crankDeg) + "," + formatNumber(c.closest.distance) + "\n";
  std::cout << out << std::flush;
  if (!c.periodic)
    note("the motion does not repeat after one turn: the ends of the turn count as well");
  if (o.min && c.closest.distance < *o.min) {
    error("the closest approach, " + formatNumber(c.closest.distance, 6) + " mm at crank " +
          formatNumber(c.closest.crankDeg, 6) + " deg, is under --min " + formatNumber(*o.min, 6));
    return kTooClose;
  }
  return kOk;
}

}  // namespace

Command clearanceCommand(Parser& parser) {
  auto o = std::make_shared<Options>();
  return {addOptions(parser, *o), [o] { return clearance(*o); }};
}

}  // namespace linkage::cli
