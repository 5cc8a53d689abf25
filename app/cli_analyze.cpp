// linkage-cli analyze: the motion table of a mechanism over crank angles.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

#include "cli_common.h"
#include "linkage/io/atomic_file.h"
#include "linkage/io/motion_table.h"
#include "linkage/io/numbers.h"

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

}  // namespace

int analyze(int argc, char** argv) {
  std::string model, out;
  std::vector<std::string> points;
  long long steps = 360;
  double revs = 1, rpm = 0;
  std::optional<double> angle;
  bool sweepOptions = false;
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    if (isHelp(a)) {
      std::cout << kHelp;
      return kOk;
    }
    auto value = [&](std::string& v) {
      if (i + 1 >= argc) {
        error(a + ": needs a value");
        return false;
      }
      v = argv[++i];
      return true;
    };
    std::string v;
    if (a == "--steps" || a == "--revs" || a == "--rpm" || a == "--angle" || a == "--point" ||
        a == "--out") {
      if (!value(v)) return kBadInput;
    }
    if (a == "--steps") {
      std::optional<long long> n = wholeNumber(a, v);
      if (!n) return kBadInput;
      if (*n < 1) {
        error("--steps: must be at least 1");
        return kBadInput;
      }
      steps = *n;
      sweepOptions = true;
    } else if (a == "--revs") {
      std::optional<double> r = positiveNumber(a, v);
      if (!r) return kBadInput;
      revs = *r;
      sweepOptions = true;
    } else if (a == "--rpm") {
      std::optional<double> r = positiveNumber(a, v);
      if (!r) return kBadInput;
      rpm = *r;
    } else if (a == "--angle") {
      angle = number(a, v);
      if (!angle) return kBadInput;
    } else if (a == "--point") {
      points.push_back(v);
    } else if (a == "--out") {
      out = v;
    } else if (!a.empty() && a[0] == '-' && a != "-") {
      error("analyze: unknown option " + a + " (see linkage-cli analyze --help)");
      return kBadInput;
    } else if (model.empty()) {
      model = a;
    } else {
      error("analyze: more than one MODEL given: " + model + ", " + a);
      return kBadInput;
    }
  }
  if (model.empty()) {
    error("analyze: no MODEL given (see linkage-cli analyze --help)");
    return kBadInput;
  }
  if (angle && sweepOptions) {
    error("analyze: --angle gives one row; it cannot be combined with --steps or --revs");
    return kBadInput;
  }
  MotionTableSpec spec;
  spec.steps = steps;
  spec.revs = revs;
  spec.rpm = rpm;
  const long long rows = motionTableRows(spec);
  if (!angle && rows < 0) {
    error("analyze: --steps " + std::to_string(steps) + " times --revs " + formatNumber(revs) +
          " is not a whole number of steps");
    return kBadInput;
  }
  if (!angle && rows > kMaxRows) {
    error("analyze: " + std::to_string(rows) + " rows is more than the " +
          std::to_string(kMaxRows) + " this command writes; use fewer steps or revolutions");
    return kBadInput;
  }

  std::optional<Mechanism> m = openModel(model);
  if (!m) return kBadInput;
  if (!m->driver) {
    error(model + ": the mechanism has no driver: add \"driver\": {\"joint\": <pin index>, ...}");
    return kBadInput;
  }
  std::optional<std::vector<PointId>> ids = outputPoints(*m, points);
  if (!ids) return kBadInput;
  spec.points = *ids;

  Kinematics k;
  if (int e = prepare(k, *m); e != kOk) return e;
  if (Status s = k.checkDetermined(spec.points); !s.ok()) {
    error(s.message);
    return exitFor(s);
  }

  std::string buffer;
  auto sink = [&](const std::string& row) {
    buffer += row;
    buffer += '\n';
    if (out.empty() && buffer.size() > (1 << 16)) {
      std::fwrite(buffer.data(), 1, buffer.size(), stdout);
      buffer.clear();
    }
  };
  Status s;
  if (angle) {
    if (rpm > 0) k.setRpm(rpm);
    sink(motionTableHeader(k.mechanism(), spec.points));
    s = k.moveTo(*angle);
    if (s.ok()) sink(motionTableRow(k, *angle, spec.points));
  } else {
    s = sweepMotionTable(k, spec, sink);
  }
  if (out.empty()) {
    std::fwrite(buffer.data(), 1, buffer.size(), stdout);
    std::fflush(stdout);
  } else {
    WriteResult w = writeFileAtomically(out, buffer);
    if (!w.ok) {
      error(w.error);
      return kFailure;
    }
  }
  if (!s.ok()) {
    error(s.message);
    return exitFor(s);
  }
  return kOk;
}

}  // namespace linkage::cli
