// linkage-cli analyze: the motion table of a mechanism over crank angles.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

#include "cli_common.h"
#include "cli_parser.h"
#include "linkage/io/numbers.h"
#include "linkage/tables/motion_table.h"

namespace linkage::cli {

namespace {

const char* kHelp =
    R"(usage: linkage-cli analyze MODEL [--steps N] [--revs R] [--rpm RPM] [--point body.point]...
                           [--out FILE]
       linkage-cli analyze MODEL --angle DEG [--rpm RPM] [--point body.point]... [--out FILE]

Writes the motion table of MODEL (a .linkage.json file, or an example name such as
wanzer-inversion-2): a header row, then one row per crank angle 0, 360/N, ..., 360*R (both ends
included) with t_s, crank_deg and, for each point, x_mm, y_mm, vx_mm_s, vy_mm_s, ax_mm_s2,
ay_mm_s2. Velocities and accelerations are exact (linear solves with the constraint Jacobian).

  --steps N         steps per revolution (default 360)
  --revs R          revolutions (default 1); N * R must be a whole number
  --rpm RPM         driver speed instead of the file's
  --point B.P       a point to report (repeatable); default: the file's outputs
  --out FILE        write the table to FILE (atomically) instead of standard output
  --angle DEG       only the row at this crank angle (header, then one row)

Exit status: 0 success, 2 bad input (options, file, or a mechanism the driver cannot move or
does not determine), 3 the mechanism cannot reach some crank angle: the rows up to there are
written, then the reason on standard error.
)";

constexpr long long kMaxRows = 50'000'000;

struct Options {
  std::string model, out;
  std::vector<std::string> points;
  MotionTableSpec spec;  // steps, revs, rpm (points later)
  std::optional<double> angle;
  const CLI::Option *steps = nullptr, *revs = nullptr;  // given: a sweep, not one --angle
};

// The options, read into `o`.
CLI::App* addOptions(Parser& parser, Options& o) {
  CLI::App& c = parser.command("analyze", kHelp);
  addModel(c, o.model);
  o.steps = addWhole(c, "--steps", o.spec.steps, 1);
  o.revs = addNumber(c, "--revs", o.spec.revs, NumberRule::Positive);
  addNumber(c, "--rpm", o.spec.rpm, NumberRule::Positive);
  addNumber(c, "--angle", o.angle);
  addTexts(c, "--point", o.points);
  addText(c, "--out", o.out);
  return &c;
}

// The options checked against each other; the exit status when they cannot be used.
std::optional<int> checkOptions(const Options& o) {
  if (o.angle && count(o.steps) + count(o.revs) > 0) {
    error("analyze: --angle gives one row; it cannot be combined with --steps or --revs");
    return kBadInput;
  }
  const long long rows = motionTableRows(o.spec);
  if (!o.angle && rows < 0) {
    error("analyze: --steps " + std::to_string(o.spec.steps) + " times --revs " +
          formatNumber(o.spec.revs) + " is not a whole number of steps");
    return kBadInput;
  }
  if (!o.angle && rows > kMaxRows) {
    error("analyze: " + std::to_string(rows) + " rows is more than the " +
          std::to_string(kMaxRows) + " this command writes; use fewer steps or revolutions");
    return kBadInput;
  }
  return std::nullopt;
}

// The table's rows, to standard output as they come (in blocks) or to `out` at the end
// (atomically); the status of the motion, or kFailure when the file cannot be written.
int writeTable(Kinematics& k, const Options& o, Status& s) {
  std::string buffer;
  auto sink = [&](const std::string& row) {
    buffer += row;
    buffer += '\n';
    if (o.out.empty() && buffer.size() > (1 << 16)) {
      std::fwrite(buffer.data(), 1, buffer.size(), stdout);
      buffer.clear();
    }
  };
  if (o.angle) {
    if (o.spec.rpm > 0) k.setRpm(o.spec.rpm);
    sink(motionTableHeader(k.mechanism(), o.spec.points));
    s = k.moveTo(*o.angle);
    if (s.ok()) sink(motionTableRow(k, *o.angle, o.spec.points));
  } else {
    s = sweepMotionTable(k, o.spec, sink);
  }
  return writeOutput(o.out, buffer);
}

int analyze(Options& o) {
  if (std::optional<int> e = checkOptions(o)) return *e;
  std::optional<Mechanism> m = openDrivenModel(o.model);
  if (!m) return kBadInput;
  std::optional<std::vector<PointId>> ids = outputPoints(*m, o.points);
  if (!ids) return kBadInput;
  o.spec.points = *ids;

  Kinematics k;
  if (int e = prepare(k, *m); e != kOk) return e;
  if (Status s = k.checkDetermined(o.spec.points); !s.ok()) {
    error(s.message);
    return exitFor(s);
  }
  Status s;
  if (int e = writeTable(k, o, s); e != kOk) return e;
  if (!s.ok()) {
    error(s.message);
    return exitFor(s);
  }
  return kOk;
}

}  // namespace

Command analyzeCommand(Parser& parser) {
  auto o = std::make_shared<Options>();
  return {addOptions(parser, *o), [o] { return analyze(*o); }};
}

}  // namespace linkage::cli
