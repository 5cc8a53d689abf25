// linkage-cli study: one dimension varied over a range and the design measured at every value
// (linkage/study.h), in parallel, one solver per thread.
#include <cstdio>
#include <iostream>

#include "cli_common.h"
#include "design_options.h"
#include "linkage/io/numbers.h"
#include "linkage/study.h"
#include "linkage/tables/study_table.h"

namespace linkage::cli {

namespace {

const char* kHelp =
    R"(usage: linkage-cli study MODEL --move body.point (--by DX,DY | --about X,Y --angle DEG)
                         --from A --to B --steps N --point body.point [--direction DX,DY]
                         [--body NAME]... [--crank-steps M] [--threads T]

Varies one dimension of MODEL and measures the design at every value of t from A to B (N
values, both ends included). The point moved is a design point: every point pinned to it where
they are drawn together moves with it (moving the ground's pivot F moves the rocker's point F
pinned there), so the drawing stays assembled; each body's other points stay where they are.

  --move B.P        the point to move
  --by DX,DY        along a line: moved by t * (DX, DY) mm
  --about X,Y       on an arc about (X, Y) ...
  --angle DEG       ... turned by t * DEG degrees, counter-clockwise
  --from A --to B   the range of t
  --steps N         values of t (1 or more)
  --point B.P       the point whose stroke, extremes and peaks are measured
  --direction DX,DY the stroke's direction (default: the point's ground slot, else +y)
  --body NAME       a body whose swing (largest minus smallest angle) is measured; repeatable
  --crank-steps M   samples per turn of the crank (default 360)
  --threads T       threads (default: one per core)

Output, CSV, one row per value of t: t; turns (1 when the crank turns fully, else 0); lock_deg
(where the crank stops, from the drawing forwards; empty when it turns); then, for the point,
<point>.min_mm, <point>.max_mm and <point>.stroke_mm along the direction (exact extremes, by root
finding on the velocity), <point>.peak_speed_mm_s and <point>.peak_accel_mm_s2 (largest |v| and
|a| at the samples, at the file's speed); <body>.swing_deg for each --body; mu:<a>.min_deg and
mu:<a>.max_deg for each transmission angle (linkage-cli transmission names them). The measures
are empty where the crank does not turn fully; a variant that cannot be loaded or measured is
reported on standard error.

Exit status: 0 the study ran (rows whose crank locks are results, not errors), 2 bad input.
)";

}  // namespace

int study(int argc, char** argv) {
  std::string model, move, point;
  std::vector<std::string> bodies;
  std::optional<Vec2> by, about, direction;
  std::optional<double> angle, from, to;
  std::optional<long long> values;
  long long crankSteps = 360, threads = 0;
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    if (isHelp(a)) {
      std::cout << kHelp;
      return kOk;
    }
    if (!a.empty() && a[0] == '-' && a.size() > 1) {
      std::optional<std::string> v = optionValue(argc, argv, i);
      if (!v) return kBadInput;
      bool ok = true;
      if (a == "--move") {
        move = *v;
      } else if (a == "--point") {
        point = *v;
      } else if (a == "--body") {
        bodies.push_back(*v);
      } else if (a == "--by") {
        ok = (by = numberPair(a, *v)).has_value();
      } else if (a == "--about") {
        ok = (about = numberPair(a, *v)).has_value();
      } else if (a == "--direction") {
        ok = (direction = numberPair(a, *v, true)).has_value();
      } else if (a == "--angle") {
        ok = (angle = number(a, *v)).has_value();
      } else if (a == "--from") {
        ok = (from = number(a, *v)).has_value();
      } else if (a == "--to") {
        ok = (to = number(a, *v)).has_value();
      } else if (a == "--steps" || a == "--crank-steps" || a == "--threads") {
        // 100,000 variants take about half a minute of one core; 1024 threads are plenty.
        const long long lo = a == "--crank-steps" ? 4 : 1;
        const long long hi = a == "--steps" ? 100'000 : a == "--threads" ? 1024 : 1'000'000;
        std::optional<long long> n = wholeNumberIn(a, *v, lo, hi);
        if (!n) return kBadInput;
        if (a == "--steps")
          values = *n;
        else if (a == "--crank-steps")
          crankSteps = *n;
        else
          threads = *n;
      } else {
        error("study: unknown option " + a + " (see linkage-cli study --help)");
        return kBadInput;
      }
      if (!ok) return kBadInput;
    } else if (!modelArgument("study", a, model)) {
      return kBadInput;
    }
  }
  if (!modelGiven("study", model)) return kBadInput;
  for (const auto& [given, name] : {std::pair{!move.empty(), "--move"},
                                    {from.has_value(), "--from"},
                                    {to.has_value(), "--to"},
                                    {values.has_value(), "--steps"},
                                    {!point.empty(), "--point"}})
    if (!given) {
      error(std::string("study: ") + name + " is required (see linkage-cli study --help)");
      return kBadInput;
    }
  if (by.has_value() == (about.has_value() || angle.has_value())) {
    error("study: give either --by DX,DY or --about X,Y with --angle DEG");
    return kBadInput;
  }
  if (about.has_value() != angle.has_value()) {
    error("study: --about and --angle go together");
    return kBadInput;
  }
  std::optional<Mechanism> m = openDrivenModel(model);
  if (!m) return kBadInput;
  StudySpec spec;
  std::optional<std::vector<PointId>> ids = outputPoints(*m, {point});
  if (!ids) return kBadInput;
  spec.point = ids->front();
  ids = outputPoints(*m, {move});
  if (!ids) return kBadInput;
  spec.move.point = ids->front();
  if (by) {
    spec.move.by = *by;
  } else {
    spec.move.kind = PointMove::Kind::Arc;
    spec.move.centre = *about;
    spec.move.angleDeg = *angle;
  }
  for (const std::string& b : bodies) {
    const Body* body = m->bodyNamed(b);
    if (!body) {
      error("--body " + b + ": no body of that name");
      return kBadInput;
    }
    spec.bodies.push_back(body->id);
  }
  spec.from = *from;
  spec.to = *to;
  spec.values = static_cast<int>(*values);
  spec.direction = direction;
  spec.steps = static_cast<int>(crankSteps);
  spec.threads = static_cast<int>(threads);
  const Study s = runStudy(*m, spec);
  if (!s.status.ok()) {
    error(s.status.message);
    return kBadInput;
  }
  const std::string out = studyTableCsv(*m, spec, s);
  for (const StudyRow& r : s.rows)
    if (!r.status.ok())
      std::cerr << "linkage-cli: t = " << formatNumber(r.t) << ": " << r.status.message << "\n";
  std::fwrite(out.data(), 1, out.size(), stdout);
  std::fflush(stdout);
  return kOk;
}

}  // namespace linkage::cli
