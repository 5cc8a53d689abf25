// linkage-cli dynamics: forces over crank angles at the driver's constant speed.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "cli_common.h"
#include "cli_parser.h"
#include "linkage/dynamics.h"
#include "linkage/elements.h"
#include "linkage/io/numbers.h"
#include "linkage/space.h"
#include "linkage/tables/force_table.h"

namespace linkage::cli {

namespace {

const char* kHelp =
    R"(usage: linkage-cli dynamics MODEL [--steps N] [--revs R] [--rpm RPM] [--out FILE]

Writes the forces of MODEL at its driver's constant speed (kinetostatics: from the exact
accelerations, one linear solve with the transpose of the constraint Jacobian per crank angle),
from the bodies' masses, the gravity ([gx, gy] or [gx, gy, gz], m/s^2: on a planar machine gz
is along the drawing's normal and changes no column) and the loads of the file: a header row,
then one row per crank angle 0, 360/N, ..., 360*R with

  t_s,crank_deg,driver_torque_Nm,shaking_fx_N,shaking_fy_N,shaking_moment_Nm

then for each joint in file order its reaction, the force on the body of its point a from the
other side: pin:<a>.fx_N,pin:<a>.fy_N; slider:<a>.fx_N,slider:<a>.fy_N,slider:<a>.m_Nm (with
the couple about a); pin-in-slot:<a>.fx_N,pin-in-slot:<a>.fy_N; gear:<a>.fx_N,gear:<a>.fy_N
(a gear pair's tooth force at the pitch point; a belt's pull along its run);
cam:<a>.fx_N,cam:<a>.fy_N,cam:<a>.m_Nm,cam:<a>.contact_N (the follower's force on the cam along
the common normal, its moment about the cam's centre, the contact force, + compression): <a>
is the joint's point a as "body.point". 17 significant digits. Reactions that the joints do not
determine (redundant joints) are left empty, and the joints are named on standard error.

A machine in space (planes, docs/spatial.md; docs/dynamics.md, "Machines in space"): the
shaking force and moment in the world, shaking_fx_N,shaking_fy_N,shaking_fz_N,shaking_mx_Nm,
shaking_my_Nm,shaking_mz_Nm (about the world's origin), in place of the three above; each
joint's force in its plane class's frame; a joint in a plane adds what it bears out of the plane,
<kind>:<a>.fn_N,<kind>:<a>.mx_Nm,<kind>:<a>.my_Nm (a body's out-of-plane load is borne by its one
joint with the ground); ball-rod:<a>.axial_N, the rod's tension (+ pulling its ends together);
a gear adds gear:<a>.m_Nm, the couple on a's body about its axis (a bevel pair: that alone, its
fx_N and fy_N empty and its other tooth-force components left out, said on standard error).

  --steps N         steps per revolution (default 360)
  --revs R          revolutions (default 1); N * R must be a whole number
  --rpm RPM         driver speed instead of the file's
  --out FILE        write the table to FILE (atomically) instead of standard output

Exit status: 0 success, 2 bad input (options, file, masses or loads, or a mechanism the driver
does not determine), 3 the mechanism cannot reach some crank angle: the rows up to there are
written, then the reason on standard error.
)";

struct Options {
  std::string model, out;
  long long steps = 360;
  double revs = 1, rpm = 0;
};

// The options, read into `o`.
CLI::App* addOptions(Parser& parser, Options& o) {
  CLI::App& c = parser.command("dynamics", kHelp);
  addModel(c, o.model);
  addWhole(c, "--steps", o.steps, 1);
  addNumber(c, "--revs", o.revs, NumberRule::Positive);
  addNumber(c, "--rpm", o.rpm, NumberRule::Positive);
  addText(c, "--out", o.out);
  return &c;
}

std::optional<int> checkOptions(const Options& o) {
  const double rows = o.steps * o.revs;
  if (std::abs(rows - std::round(rows)) > 1e-9 * rows || rows > 5e7) {
    error("dynamics: --steps " + std::to_string(o.steps) + " times --revs " + formatNumber(o.revs) +
          " is not a whole number of steps (or over 50 million)");
    return kBadInput;
  }
  return std::nullopt;
}

// A load on the ground acts on the frame itself, not through the mechanism: the forces leave it
// out, and say so rather than let a user believe it was applied.
void noteGroundLoads(const Mechanism& m) {
  for (size_t i = 0; i < m.loads.size(); ++i) {
    const Load& l = m.loads[i];
    const Point* p = l.point ? m.point(l.point) : nullptr;
    const Body* b = m.body(p ? p->body : l.body);
    if (!b || !b->ground) continue;
    error("note: loads[" + std::to_string(i) + "] " +
          (p ? "at " + m.pointLabel(l.point) : std::string("on the ground body")) +
          " acts on the frame itself, not through the mechanism: it is left out of the forces");
  }
}
// What the forces of a machine in space leave out, said rather than hidden in the numbers.
void noteSpace(const Mechanism& m, const Forces& f) {
  if (!isSpatial(m)) return;
  for (const Joint& j : m.joints) {
    const Point *a = m.point(j.a), *b = j.b ? m.point(j.b) : nullptr;
    if (kindOf(j).role != Role::Coupling || !a || !b ||
        parallel(planeOf(m, a->body), planeOf(m, b->body)))
      continue;
    error("note: the bevel pair " + jointLabel(m, j.id) +
          " transmits the couple about each axis (its m_Nm column); its tooth forces' other "
          "components (radial, axial) are left out, and so are their loads on the shafts' "
          "bearings");
  }
  for (BodyId b : f.outOfPlaneUnsupported)
    error("note: body \"" + m.body(b)->name +
          "\" has loads out of its plane (a rod's end, gravity, a point at a depth) and no "
          "single joint with the ground to bear them: they are in no reaction");
}

// A planar machine's gravity along the drawing's normal changes none of its columns: said, with
// the weight the frame bears along the normal.
void noteGravityZ(const Mechanism& m) {
  if (isSpatial(m) || m.gravityZ.value_or(0) == 0) return;
  double kg = 0;
  for (const Body& b : m.bodies)
    if (!b.ground && b.mass) kg += b.mass->kg;
  error("note: gravity's z (" + formatShown(*m.gravityZ) +
        " m/s^2) is along the drawing's normal: it changes no force in the drawing's plane; the "
        "frame bears the moving bodies' weight along the normal, " +
        formatShown(kg * *m.gravityZ) +
        " N, constant, which the table of a planar machine has no column for");
}

int dynamics(const Options& o) {
  if (std::optional<int> e = checkOptions(o)) return *e;
  std::optional<Mechanism> m = openDrivenModel(o.model);
  if (!m) return kBadInput;
  Kinematics k;
  if (int e = prepare(k, *m); e != kOk) return e;
  if (o.rpm > 0) k.setRpm(o.rpm);
  ForceSolver solver;
  if (Status s = solver.prepare(k); !s.ok()) {
    error(s.message);
    return kBadInput;
  }
  const bool anything = m->gravity || !m->loads.empty() ||
                        std::any_of(m->bodies.begin(), m->bodies.end(),
                                    [](const Body& b) { return !b.ground && b.mass; });
  if (!anything)
    error(
        "note: no moving body has a mass, and there is no gravity and no load: every force is "
        "zero (masses: \"mass\" on a body, see docs/dynamics.md)");
  noteGroundLoads(*m);
  const std::vector<char> undetermined = undeterminedJoints(*m, solver.result().undetermined);
  if (!solver.result().undetermined.empty()) {
    std::string names;
    for (JointId j : solver.result().undetermined)
      names += (names.empty() ? "" : ", ") + jointLabel(*m, j);
    error("note: the reactions of " + names +
          " are not determined (redundant joints share them in more than one way): their "
          "columns are left empty");
  }
  noteSpace(*m, solver.result());
  noteGravityZ(*m);
  std::string out = forceTableHeader(*m) + "\n";
  const long long rows = std::llround(o.steps * o.revs);
  Status s;
  for (long long i = 0; i <= rows; ++i) {
    const double deg = 360.0 * static_cast<double>(i) / static_cast<double>(o.steps);
    if (s = k.moveTo(deg); !s.ok()) break;
    const Forces& f = solver.compute(k);
    if (!(s = f.status).ok()) break;
    out += forceTableRow(*m, f, deg / 360 * 60 / k.rpm(), deg, undetermined) + "\n";
    if (o.out.empty() && out.size() > (1 << 16)) {
      std::fwrite(out.data(), 1, out.size(), stdout);
      out.clear();
    }
  }
  if (int e = writeOutput(o.out, out); e != kOk) return e;
  if (!s.ok()) {
    error(s.message);
    return exitFor(s);
  }
  return kOk;
}

}  // namespace

Command dynamicsCommand(Parser& parser) {
  auto o = std::make_shared<Options>();
  return {addOptions(parser, *o), [o] { return dynamics(*o); }};
}

}  // namespace linkage::cli
