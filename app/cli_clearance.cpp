// linkage-cli clearance: the distance between two moving things (two points, or a point and a
// slot of another body) over a turn of the crank, every local minimum and the closest approach
// (linkage/clearance.h).
#include <iostream>

#include "cli_common.h"
#include "design_options.h"
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
  std::vector<std::string> between;
  std::optional<double> min;
  long long steps = 360;
};

// Reads argv into o; kOk to go on, else the exit status.
std::optional<int> readOptions(int argc, char** argv, Options& o) {
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    if (isHelp(a)) {
      std::cout << kHelp;
      return kOk;
    }
    if (a == "--between") {
      if (i + 2 >= argc) {
        error("--between: needs two values, A B");
        return kBadInput;
      }
      o.between = {argv[i + 1], argv[i + 2]};
      i += 2;
    } else if (a == "--min" || a == "--steps") {
      std::optional<std::string> v = optionValue(argc, argv, i);
      if (!v) return kBadInput;
      if (a == "--min") {
        if (!(o.min = number(a, *v))) return kBadInput;
      } else {
        std::optional<long long> n = wholeNumberIn(a, *v, 4, 1'000'000);
        if (!n) return kBadInput;
        o.steps = *n;
      }
    } else if (!modelArgument("clearance", a, o.model)) {
      return kBadInput;
    }
  }
  if (!modelGiven("clearance", o.model)) return kBadInput;
  if (o.between.empty()) {
    error("clearance: give --between A B");
    return kBadInput;
  }
  return std::nullopt;
}

}  // namespace

int clearance(int argc, char** argv) {
  Options o;
  if (std::optional<int> e = readOptions(argc, argv, o)) return *e;
  std::optional<Mechanism> m = openDrivenModel(o.model);
  if (!m) return kBadInput;
  const std::optional<ClearanceItem> a = item(*m, o.between[0]), b = item(*m, o.between[1]);
  if (!a || !b) return kBadInput;
  Kinematics k;
  if (int e = prepare(k, *m); e != kOk) return e;
  ClearanceOptions opt;
  opt.steps = static_cast<int>(o.steps);
  const Clearance c = findClearance(k, *a, *b, opt);
  if (!c.status.ok()) {
    error("--between " + o.between[0] + " " + o.between[1] + ": " + c.status.message);
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

}  // namespace linkage::cli
