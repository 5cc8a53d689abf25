// linkage-cli limits: the extreme positions of a point along a direction, or of a body's angle,
// and the stroke, each found by root finding on the exact velocity (linkage/limits.h).
#include <iostream>

#include "cli_common.h"
#include "design_options.h"
#include "linkage/io/numbers.h"
#include "linkage/limits.h"

namespace linkage::cli {

namespace {

const char* kHelp =
    R"(usage: linkage-cli limits MODEL --point body.point [--direction DX,DY] [--steps N]
       linkage-cli limits MODEL --body NAME [--steps N]

The limit positions of MODEL over one turn of the crank: every crank angle where the point's
velocity along the direction (or the body's angular velocity) is zero, found to 1e-9 degree by
root finding on the exact velocity and acceleration, with the value there; then the stroke, the
largest value minus the smallest. Every local extreme is listed (a dwell shows as several).

  --point B.P       the point; its position along the direction, in mm
  --direction DX,DY the direction (any length; default: the ground slot the point runs in,
                    pointing up, or right when horizontal; else +y)
  --body NAME       instead of a point: the body's angle from the drawing, in degrees (ccw)
  --steps N         sampling intervals that bracket the roots (default 360)

Output, CSV: event,crank_deg,value; one row "min" or "max" per local extreme in crank order
(crank angles in [0, 360)), then "stroke,,VALUE". 17 significant digits.

Exit status: 0 success, 2 bad input (options, file, a point the driver does not determine),
3 the crank cannot turn fully (the message says where it stops).
)";

}  // namespace

int limits(int argc, char** argv) {
  std::string model, point, body;
  std::optional<Vec2> direction;
  long long steps = 360;
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    if (isHelp(a)) {
      std::cout << kHelp;
      return kOk;
    }
    if (a == "--point" || a == "--body" || a == "--direction" || a == "--steps") {
      std::optional<std::string> v = optionValue(argc, argv, i);
      if (!v) return kBadInput;
      if (a == "--point") {
        point = *v;
      } else if (a == "--body") {
        body = *v;
      } else if (a == "--direction") {
        if (!(direction = numberPair(a, *v, true))) return kBadInput;
      } else {
        std::optional<long long> n = wholeNumberIn(a, *v, 4, 1'000'000);
        if (!n) return kBadInput;
        steps = *n;
      }
    } else if (!modelArgument("limits", a, model)) {
      return kBadInput;
    }
  }
  if (!modelGiven("limits", model)) return kBadInput;
  if (point.empty() == body.empty()) {
    error("limits: give either --point body.point or --body NAME");
    return kBadInput;
  }
  if (direction && point.empty()) {
    error("limits: --direction goes with --point");
    return kBadInput;
  }
  std::optional<Mechanism> m = openDrivenModel(model);
  if (!m) return kBadInput;
  LimitMeasure what;
  if (!point.empty()) {
    std::optional<std::vector<PointId>> ids = outputPoints(*m, {point});
    if (!ids) return kBadInput;
    what =
        LimitMeasure::along(ids->front(), direction.value_or(defaultDirection(*m, ids->front())));
  } else {
    const Body* b = m->bodyNamed(body);
    if (!b) {
      error("--body " + body + ": no body of that name");
      return kBadInput;
    }
    what = LimitMeasure::angleOf(b->id);
  }
  Kinematics k;
  if (int e = prepare(k, *m); e != kOk) return e;
  LimitOptions opt;
  opt.steps = static_cast<int>(steps);
  const Limits r = findLimits(k, what, opt);
  if (!r.status.ok()) {
    error(r.status.message);
    return exitFor(r.status);
  }
  std::string out = "event,crank_deg,value\n";
  for (const LocalExtreme& e : r.extremes)
    out += std::string(e.max ? "max," : "min,") + formatNumber(e.crankDeg) + "," +
           formatNumber(e.value) + "\n";
  out += "stroke,," + formatNumber(r.stroke) + "\n";
  std::cout << out << std::flush;
  if (!r.moves) note("the value does not change with the crank: no extremes");
  if (!r.periodic)
    note("the motion does not repeat after one turn: extremes are those of crank 0 to 360");
  return kOk;
}

}  // namespace linkage::cli
