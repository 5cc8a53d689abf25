// linkage-cli study: one dimension varied over a range and the design measured at every value
// (linkage/study.h), in parallel, one solver per thread.
#include <cstdio>
#include <iostream>

#include "cli_common.h"
#include "cli_parser.h"
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

struct Options {
  std::string model, move, point;
  std::vector<std::string> bodies;
  std::optional<Vec2> by, about, direction;
  std::optional<double> angle;
  double from = 0, to = 0;
  int values = 0, crankSteps = 360, threads = 0;
};

// The options, read into `o`.
CLI::App* addOptions(Parser& parser, Options& o) {
  CLI::App& c = parser.command("study", kHelp);
  addModel(c, o.model);
  required(addText(c, "--move", o.move));
  addPair(c, "--by", o.by);
  addPair(c, "--about", o.about);
  addNumber(c, "--angle", o.angle);
  required(addNumber(c, "--from", o.from));
  required(addNumber(c, "--to", o.to));
  // 100,000 variants take about half a minute of one core; 1024 threads are plenty.
  required(addWhole(c, "--steps", o.values, 1, 100'000));
  required(addText(c, "--point", o.point));
  addPair(c, "--direction", o.direction, PairRule::NonZero);
  addTexts(c, "--body", o.bodies);
  addWhole(c, "--crank-steps", o.crankSteps, 4, 1'000'000);
  addWhole(c, "--threads", o.threads, 1, 1024);
  return &c;
}

std::optional<int> checkOptions(const Options& o) {
  if (o.by.has_value() == (o.about.has_value() || o.angle.has_value())) {
    error("study: give either --by DX,DY or --about X,Y with --angle DEG");
    return kBadInput;
  }
  if (o.about.has_value() != o.angle.has_value()) {
    error("study: --about and --angle go together");
    return kBadInput;
  }
  return std::nullopt;
}

// The study the options ask for on m; nullopt after the error.
std::optional<StudySpec> studySpec(const Mechanism& m, const Options& o) {
  StudySpec spec;
  std::optional<std::vector<PointId>> ids = outputPoints(m, {o.point});
  if (!ids) return std::nullopt;
  spec.point = ids->front();
  if (!(ids = outputPoints(m, {o.move}))) return std::nullopt;
  spec.move.point = ids->front();
  if (o.by) {
    spec.move.by = *o.by;
  } else {
    spec.move.kind = PointMove::Kind::Arc;
    spec.move.centre = *o.about;
    spec.move.angleDeg = *o.angle;
  }
  for (const std::string& b : o.bodies) {
    const Body* body = m.bodyNamed(b);
    if (!body) {
      error("--body " + b + ": no body of that name");
      return std::nullopt;
    }
    spec.bodies.push_back(body->id);
  }
  spec.from = o.from;
  spec.to = o.to;
  spec.values = o.values;
  spec.direction = o.direction;
  spec.steps = o.crankSteps;
  spec.threads = o.threads;
  return spec;
}

int study(const Options& o) {
  if (std::optional<int> e = checkOptions(o)) return *e;
  std::optional<Mechanism> m = openDrivenModel(o.model);
  if (!m) return kBadInput;
  const std::optional<StudySpec> spec = studySpec(*m, o);
  if (!spec) return kBadInput;
  const Study s = runStudy(*m, *spec);
  if (!s.status.ok()) {
    error(s.status.message);
    return kBadInput;
  }
  const std::string out = studyTableCsv(*m, *spec, s);
  for (const StudyRow& r : s.rows)
    if (!r.status.ok())
      std::cerr << "linkage-cli: t = " << formatNumber(r.t) << ": " << r.status.message << "\n";
  std::fwrite(out.data(), 1, out.size(), stdout);
  std::fflush(stdout);
  return kOk;
}

}  // namespace

Command studyCommand(Parser& parser) {
  auto o = std::make_shared<Options>();
  return {addOptions(parser, *o), [o] { return study(*o); }};
}

}  // namespace linkage::cli
