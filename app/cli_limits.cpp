// linkage-cli limits: the extreme positions of a point along a direction, or of a body's angle,
// and the stroke, each found by root finding on the exact velocity (linkage/limits.h).
#include <iostream>

#include "cli_common.h"
#include "cli_parser.h"
#include "linkage/io/numbers.h"
#include "linkage/limits.h"
#include "linkage/space.h"
#include "linkage/timing_text.h"

namespace linkage::cli {

namespace {

const char* kHelp =
    R"(usage: linkage-cli limits MODEL --point body.point [--direction DX,DY[,DZ]] [--steps N]
       linkage-cli limits MODEL --body NAME [--steps N]
       linkage-cli limits MODEL --output OUTPUT [--steps N]

The limit positions of MODEL over one turn of the crank: every crank angle where the point's
velocity along the direction (or the body's angular velocity) is zero, found to 1e-9 degree by
root finding on the exact velocity and acceleration, with the value there; then the stroke, the
largest value minus the smallest. Every local extreme is listed (a dwell shows as several).

  --point B.P       the point; its position along the direction, in mm
  --direction DX,DY the direction (any length; default: the ground slot the point runs in,
                    pointing up, or right when horizontal; else +y); DX,DY,DZ on a machine
                    in space
  --body NAME       instead of a point: the body's angle from the drawing, in degrees (ccw)
  --output OUTPUT   instead: any output a timing window takes (docs/timing.md), such as
                    body.point:y, body.point:distance:body.point, and on a machine in space
                    body.point:z or body.point:DX,DY,DZ (world)
On a machine in space a point's position is the world's: --direction DX,DY,DZ (DX,DY is
(DX, DY, 0)) in the world, +y by default.
  --steps N         sampling intervals that bracket the roots (default 360)

Output, CSV: event,crank_deg,value; one row "min" or "max" per local extreme in crank order
(crank angles in [0, 360)), then "stroke,,VALUE". 17 significant digits.

Exit status: 0 success, 2 bad input (options, file, a point the driver does not determine),
3 the crank cannot turn fully (the message says where it stops).
)";

struct Options {
  std::string model, point, body, output;
  std::optional<Vec3> direction;
  int steps = 360;
};

// The options, read into `o`.
CLI::App* addOptions(Parser& parser, Options& o) {
  CLI::App& c = parser.command("limits", kHelp);
  addModel(c, o.model);
  addText(c, "--point", o.point);
  addText(c, "--body", o.body);
  addText(c, "--output", o.output);
  addDirection(c, "--direction", o.direction);
  addWhole(c, "--steps", o.steps, 4, 1'000'000);
  return &c;
}

std::optional<int> checkOptions(const Options& o) {
  if (o.point.empty() + o.body.empty() + o.output.empty() != 2) {
    error("limits: give one of --point body.point, --body NAME or --output OUTPUT");
    return kBadInput;
  }
  if (o.direction && o.point.empty()) {
    error("limits: --direction goes with --point");
    return kBadInput;
  }
  return std::nullopt;
}

// What is measured: the point along the direction, or the body's angle; nullopt after the error.
std::optional<LimitMeasure> measure(const Mechanism& m, const Options& o) {
  if (!o.output.empty()) {
    std::string why;
    std::optional<LimitMeasure> x = parseMeasure(m, o.output, &why);
    if (!x) error("--output " + o.output + ": " + why);
    return x;
  }
  if (!o.point.empty()) {
    std::optional<std::vector<PointId>> ids = outputPoints(m, {o.point});
    if (!ids) return std::nullopt;
    const PointId p = ids->front();
    // In space a slot's direction is in its plane, not the world's: +y there by default.
    if (o.direction && o.direction->z() != 0 && !isSpatial(m)) {
      error("--direction: a DZ is of a machine in space (planes); this one is planar: give DX,DY");
      return std::nullopt;
    }
    if (o.direction) return LimitMeasure::alongInSpace(p, *o.direction);
    return LimitMeasure::along(p, isSpatial(m) ? Vec2(0, 1) : defaultDirection(m, p));
  }
  const Body* b = m.bodyNamed(o.body);
  if (!b) {
    error("--body " + o.body + ": no body of that name");
    return std::nullopt;
  }
  return LimitMeasure::angleOf(b->id);
}

int limits(const Options& o) {
  if (std::optional<int> e = checkOptions(o)) return *e;
  std::optional<Mechanism> m = openDrivenModel(o.model);
  if (!m) return kBadInput;
  const std::optional<LimitMeasure> what = measure(*m, o);
  if (!what) return kBadInput;
  Kinematics k;
  if (int e = prepare(k, *m); e != kOk) return e;
  LimitOptions opt;
  opt.steps = o.steps;
  const Limits r = findLimits(k, *what, opt);
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

}  // namespace

Command limitsCommand(Parser& parser) {
  auto o = std::make_shared<Options>();
  return {addOptions(parser, *o), [o] { return limits(*o); }};
}

}  // namespace linkage::cli
