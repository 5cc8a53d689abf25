// Loading and editing a mechanism (KinematicsState): compile, analyse, assemble, start; and the
// four ways an edit is re-solved from the current pose, cheapest first.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "kinematics/block_solve.h"
#include "kinematics/kinematics_state.h"
#include "linkage/elements.h"

namespace linkage {

namespace {

constexpr double kDeg = M_PI / 180.0;

// q of `next` (a compiled edit) that puts every body `old` also has where it is now: the rigid
// displacement from the drawing (rotation, translation) carried over to its new frame.
Eigen::VectorXd carriedPose(const System& old, const Eigen::VectorXd& oldQ, const System& next) {
  Eigen::VectorXd warm = sketchCoordinates(next);
  for (int k = 0; k < next.nBodies; ++k) {
    const int o = old.bodyIndex(next.bodyIds[k]);
    if (o < 0) continue;
    const double th = oldQ[3 * o + 2];
    const Rot R = Rot::of(th);
    const Vec2 t = Vec2(oldQ[3 * o], oldQ[3 * o + 1]) - R * old.frameOrigin[o];
    const Vec2 r = R * next.frameOrigin[k] + t;
    warm.segment<3>(3 * k) << r.x(), r.y(), th;
  }
  return warm;
}

// Which rows of `next` (an edit with the same joints) differ from `old`'s in their numbers
// (positions, directions, radii, constants); none when some row joins other bodies or is of
// another kind, which no dimensions-only edit does.
std::optional<std::vector<char>> changedRows(const System& old, const System& next) {
  std::vector<char> changed(next.cons.size(), 0);
  for (size_t r = 0; r < next.cons.size(); ++r) {
    const Row &a = old.cons[r], &b = next.cons[r];
    if (a.kind != b.kind || a.row != b.row || a.joint != b.joint || a.body[0] != b.body[0] ||
        a.body[1] != b.body[1] || a.body[2] != b.body[2])
      return std::nullopt;
    changed[r] = !a.sameNumbers(b);
  }
  return changed;
}

// The units an edit is solved by: the decomposition's groups in solving order, then the bodies
// no group reached split into the parts their rows connect (two class-IV linkages of different
// mechanisms are two units), each with the rows that fix it.
struct Unit {
  std::vector<int> bodies, rows;
};

std::vector<Unit> editUnits(const System& sys, const Decomposition& d) {
  std::vector<Unit> units;
  for (const Group& g : d.groups) units.push_back({g.bodies, g.rows});
  std::vector<int> part(sys.nBodies, -1);  // union-find over the unresolved bodies
  for (int k : d.unresolved) part[k] = k;
  auto root = [&](int k) {
    while (part[k] != k) k = part[k] = part[part[k]];
    return k;
  };
  std::vector<int> rowPart(sys.cons.size(), -1);
  for (size_t r = 0; r < rowPart.size(); ++r) {
    const Row& c = sys.cons[r];
    if (c.kind == Primitive::Hold) continue;
    for (int i = 0; i < c.bodies(); ++i) {
      const int k = c.body[i];
      if (k < 0 || part[k] < 0) continue;
      if (rowPart[r] >= 0) part[root(k)] = root(rowPart[r]);
      rowPart[r] = root(k);
    }
  }
  std::vector<int> unitOf(sys.nBodies, -1);
  for (int k : d.unresolved) {
    if (unitOf[root(k)] < 0) {
      unitOf[root(k)] = static_cast<int>(units.size());
      units.emplace_back();
    }
    units[unitOf[root(k)]].bodies.push_back(k);
  }
  for (size_t r = 0; r < rowPart.size(); ++r)
    if (rowPart[r] >= 0) units[unitOf[root(rowPart[r])]].rows.push_back(static_cast<int>(r));
  return units;
}

// The bodies an edit must solve again, as ClosedFormPlan::resolveFrom finds them: a unit is
// solved again when one of its rows changed, one of its bodies' frames moved (reshaped), or a
// body its rows read is solved again; `units` counts them. None when a changed row is in no
// unit (the decomposition would not account for it).
std::optional<std::vector<int>> bodiesToSolve(const System& old, const System& next,
                                              const Decomposition& d, int& units) {
  const std::optional<std::vector<char>> changed = changedRows(old, next);
  if (!changed) return std::nullopt;
  std::vector<char> solved(next.nBodies, 0), covered(changed->size(), 0);
  std::vector<int> bodies;
  units = 0;
  for (const Unit& u : editUnits(next, d)) {
    bool touched = false;
    for (int k : u.bodies) touched = touched || next.frameOrigin[k] != old.frameOrigin[k];
    for (int r : u.rows) {
      covered[r] = 1;
      const Row& c = next.cons[r];
      touched = touched || (*changed)[r];
      for (int i = 0; i < c.bodies(); ++i)
        touched = touched || (c.body[i] >= 0 && solved[c.body[i]]);
    }
    if (!touched) continue;
    for (int k : u.bodies) solved[k] = 1;
    bodies.insert(bodies.end(), u.bodies.begin(), u.bodies.end());
    ++units;
  }
  for (size_t r = 0; r < changed->size(); ++r)
    if ((*changed)[r] && !covered[r]) return std::nullopt;
  return bodies;
}

}  // namespace

Status KinematicsState::load(const Mechanism& m) {
  return prepare(m, nullptr, 0.0);
}

Status KinematicsState::analyse(const Mechanism& m, const Eigen::VectorXd& q) {
  structure = analyzeStructure(sys, q, opt.sparseFrom);
  decomposition = decompose(sys);
  if (sys.hasDriver && !structure.driverMoves) {
    const JointId dj = m.driver->joint;
    Status s = Status::failure(StatusCode::Locked, "");
    s.joints.push_back(dj);
    s.message = "the driver at " + jointName(m, dj) + " cannot turn: " +
                (structure.mobility == 0
                     ? "the mechanism has no degree of freedom (it is a structure)"
                     : "either the other joints hold the two bodies it joins rigidly together, "
                       "or the mechanism is drawn at a dead point (a limit position of the crank, "
                       "where links line up): draw it a little away from there");
    return s;
  }
  if (!structure.redundantJoints.empty()) {
    Note n{Note::Kind::RedundantJoints, "redundant joint(s): ", {}, {}};
    for (int j : structure.redundantJoints) {
      n.joints.push_back(m.joints[j].id);
      n.text += (n.joints.size() > 1 ? ", " : "") + jointName(m, m.joints[j].id);
    }
    n.text += " repeat constraints of the others; checked, not needed by the solve";
    notes.push_back(std::move(n));
  }
  if (structure.freeAfterDriver > 0) {
    Note n{Note::Kind::FreedomsHeld, "", {}, {}};
    n.text = std::to_string(structure.freeAfterDriver) +
             (sys.hasDriver ? " degree(s) of freedom the driver does not determine"
                            : " degree(s) of freedom and no driver") +
             " (bodies " + bodyList(structure.freeBodies) + "): held where they are drawn";
    for (int k : structure.freeBodies) n.bodies.push_back(sys.bodyIds[k]);
    notes.push_back(std::move(n));
  }
  return Status::success();
}

void KinematicsState::resetSolver(const Eigen::VectorXd& q) {
  std::vector<int> active = structure.activeRows;
  for (int col : structure.holdCoordinates) {
    addHold(sys, col, q[col]);
    active.push_back(sys.nRows - 1);
  }
  newton.reset(sys, active, opt.sparseFrom);
}

Status KinematicsState::start(const Eigen::VectorXd& q, double phi) {
  Snapshot snap;
  snap.q = q;
  if (!newton.derivatives(sys, q, snap.dq, snap.ddq)) {
    Status s = Status::failure(
        StatusCode::Singular,
        "the mechanism is drawn in a singular position (links in line: a dead point or a "
        "change point): velocities are not determined there; draw it a little away from it");
    s.crankDeg = (phi - sys.startRad) / kDeg;
    return s;
  }
  snap.fromCoordinates(phi, snap.q, snap.dq, snap.ddq);
  snap.coordinates = true;
  snap.regular = true;
  reg = snap;
  atSingular = false;
  regSign = newton.detSign();
  valid = true;
  plan.reset();
  if (opt.closedForm) {
    plan = ClosedFormPlan::build(decomposition, sys, static_cast<int>(mech.joints.size()), reg);
    // The plan must reproduce the configuration just solved, or it is not used.
    next.coordinates = false;  // whatever next held before is not what the plan writes
    if (plan && !(plan->solve(sys, reg, phi, next) &&
                  (coordinates(next).q - reg.q).cwiseAbs().maxCoeff() <= 1e-9 * sys.size &&
                  (next.dq - reg.dq).cwiseAbs().maxCoeff() <= 1e-7 * (1 + reg.dq.norm())))
      plan.reset();
  }
  return Status::success();
}

bool KinematicsState::assembleOffLine(const Eigen::VectorXd& drawn, Eigen::VectorXd& q, double phi,
                                      Status& s) {
  // Links drawn in line (a four-bar with every pivot on one line) make rows dependent there that
  // are not dependent anywhere else: a joint they leave open is then a loop that is too short or
  // too long at that pose, or one that closes off the line, not a redundant joint in conflict.
  // Turning the bodies a little (alternate ways, so that no two stay in line) tells the two
  // apart: if fewer rows are dependent there, assemble again from there with those rows. Which
  // side of the line the mechanism closes on is then the turn's, as a hand pushing a drawing off
  // a dead point would choose; the note says how far it moved.
  Eigen::VectorXd off = q;
  for (int k = 0; k < sys.nBodies; ++k) off[3 * k + 2] += 1e-3 * (k % 2 ? -1 : 1) * (1 + k % 3);
  if (analyzeStructure(sys, off, opt.sparseFrom).dependentRows.size() >=
      structure.dependentRows.size())
    return false;
  notes.clear();
  assembly = {};
  Status again = analyse(mech, off);
  if (again.ok()) {
    resetSolver(off);
    again = assemble(mech, sys, structure, newton, off, phi, assembly);
  }
  if (again.ok()) again = checkRedundant(mech, sys, structure, off, phi);
  if (!again.ok()) {
    // A loop that cannot close off the line either: that is the cause. Anything else (the
    // driver locked: a structure whose redundancy is real, as a parallelogram's fifth link
    // that is drawn too long) leaves the conflict as the first analysis found it.
    if (again.code == StatusCode::AssemblyFailed) s = again;
    return false;
  }
  q = off;
  assembly.maxMove = largestMove(mech, sys, drawn, q, &assembly.body);
  assembly.moved = assembly.maxMove > 1e-9 * sys.size;
  return true;
}

Status KinematicsState::prepare(const Mechanism& m, const Eigen::VectorXd* warm, double warmPhi) {
  valid = false;
  notes.clear();
  assembly = {};
  plan.reset();
  Status s;
  std::optional<System> compiled = compile(m, s);
  if (!compiled) return s;
  mech = m;
  sys = std::move(*compiled);

  Eigen::VectorXd q = warm ? *warm : sketchCoordinates(sys);
  const Eigen::VectorXd drawn = q;
  const double phi = warm ? warmPhi : 0.0;
  if (s = analyse(mech, q); !s.ok()) return s;
  resetSolver(q);
  if (s = assemble(mech, sys, structure, newton, q, phi, assembly); !s.ok()) return s;
  if (s = checkRedundant(mech, sys, structure, q, phi);
      !s.ok() && !assembleOffLine(drawn, q, phi, s))
    return s;
  if (!warm && assembly.moved) {
    const Body* b = mech.body(assembly.body);
    char buf[160];
    std::snprintf(buf, sizeof buf,
                  "the drawing does not close exactly: assembled by moving body '%s' by up to "
                  "%.6g mm (bodies keep their shape)",
                  b ? b->name.c_str() : "?", assembly.maxMove);
    notes.push_back(Note{Note::Kind::AssemblyMoved, buf, {}, {assembly.body}});
  }
  if (s = start(q, phi); !s.ok()) return s;
  if (!warm && sys.hasDriver && sys.startRad != 0) {
    s = moveToPhi(sys.startRad);
    if (!s.ok()) {
      valid = false;
      s.message = "cannot turn the crank to its start angle (start_deg): " + s.message;
      return s;
    }
  }
  return Status::success();
}

bool KinematicsState::editInPlace(const Mechanism& m, const std::vector<BodyId>& reshaped) {
  if (!plan || atSingular) return false;
  Status s;
  std::optional<System> edited = compile(m, s);
  if (!edited || edited->nRows != sys.nRows || edited->nBodies != sys.nBodies) return false;
  // The current pose in the new body frames: a reshaped body keeps its rigid displacement from
  // the drawing (its frame origin, the centroid of its points, moved with the points).
  Motion warm = reg;
  std::vector<char> reframed(edited->nBodies, 0);
  for (BodyId id : reshaped) {
    const int k = edited->bodyIndex(id);
    if (k < 0) continue;  // ground: no frame to move
    reframed[k] = edited->frameOrigin[k] != sys.frameOrigin[k];
    BodyState& b = warm.body[k];
    const Vec2 shift = b.R * (edited->frameOrigin[k] - sys.frameOrigin[k]);
    b.r += shift;
    b.v += b.w * perp(shift);
    b.a += b.al * perp(shift) - b.w * b.w * shift;
  }
  // The same topology: the same decomposition.
  std::optional<ClosedFormPlan> editedPlan =
      ClosedFormPlan::build(decomposition, *edited, static_cast<int>(m.joints.size()), warm);
  if (!editedPlan) return false;
  Motion solved;
  const int groups = editedPlan->resolveEdited(*edited, *plan, warm, solved, reframed);
  if (groups < 0) return false;
  mech = m;
  sys = std::move(*edited);
  plan = std::move(editedPlan);
  static_cast<Motion&>(reg) = std::move(solved);
  reg.regular = true;
  reg.coordinates = false;
  // The same rows, so the structure and the Newton solver's row map stay as they are.
  assembly = {};
  noteEdit(groups, EditPath::InPlace);
  return true;
}

// An edit that kept the analysis: the old assembly's notes no longer describe the pose.
void KinematicsState::noteEdit(int groups, EditPath path) {
  notes.erase(std::remove_if(notes.begin(), notes.end(),
                             [](const Note& n) { return n.kind == Note::Kind::AssemblyMoved; }),
              notes.end());
  lastEditGroups = groups;
  lastEdit = path;
}

bool KinematicsState::editBlocks(const Mechanism& m) {
  // Off the closed-form path, an edit is solved by the units (groups) it touches and those
  // downstream of them, the way editInPlace solves the plan's groups: Newton on their bodies'
  // coordinates alone (block_solve.h), every other body keeping its motion to the bit. The same
  // rows and the same analysis; the branch must stay (det J's sign is det J_SS's). Anything
  // else is left to editKeepingAnalysis.
  if (plan || atSingular) return false;
  Status s;
  std::optional<System> edited = compile(m, s);
  const int holds = static_cast<int>(structure.holdCoordinates.size());
  if (!edited || edited->nRows != sys.nRows - holds || edited->nBodies != sys.nBodies) return false;
  int units = 0;
  const std::optional<std::vector<int>> bodies = bodiesToSolve(sys, *edited, decomposition, units);
  if (!bodies) return false;
  const Snapshot& now = coordinates(cur());
  Eigen::VectorXd q = now.q, dq = now.dq, ddq = now.ddq;
  if (!bodies->empty()) {
    // Only the bodies solved again start from the carried pose: it is not exact to the bit.
    const Eigen::VectorXd carried = carriedPose(sys, now.q, *edited);
    for (int k : *bodies) q.segment<3>(3 * k) = carried.segment<3>(3 * k);
  }
  for (int col : structure.holdCoordinates) addHold(*edited, col, q[col]);
  if (!bodies->empty() && !solveBlock(m, *edited, *bodies, now.phi, q, dq, ddq)) return false;
  Snapshot solved = reg;
  solved.q = q;
  solved.dq = dq;
  solved.ddq = ddq;
  for (int k : *bodies) solved.bodyFromCoordinates(k, q, dq, ddq);
  solved.coordinates = true;
  solved.regular = true;
  mech = m;
  sys = std::move(*edited);
  reg = std::move(solved);
  // The same rows: the structure, the row map and J's pattern stay; the factors do not.
  newton.forgetFactors();
  assembly = {};
  noteEdit(units, EditPath::Blocks);
  return true;
}

bool KinematicsState::solveBlock(const Mechanism& m, const System& edited,
                                 const std::vector<int>& bodies, double phi, Eigen::VectorXd& q,
                                 Eigen::VectorXd& dq, Eigen::VectorXd& ddq) const {
  // The holds sit at the same rows as before, so the solver's row map serves the edited rows.
  const std::optional<Block> block = makeBlock(edited, newton.rowMap(), bodies);
  // Dense only: a block as large as the sparse solve's is left to it.
  if (!block || block->rows >= opt.sparseFrom) return false;
  BlockSolver solver;
  const int sign = solver.signAt(sys, *block, coordinates(cur()).q);
  return sign != 0 && solver.solve(edited, *block, q, phi, opt.newton).converged &&
         solver.derivatives(edited, *block, q, dq, ddq) && solver.detSign() == sign &&
         checkRedundant(m, edited, structure, q, phi).ok();
}

bool KinematicsState::editKeepingAnalysis(const Mechanism& m) {
  // The same joints and bodies: the structure analysis (which rows are independent, which
  // coordinates are held) is kept, and so is the Newton solver (its row map and the sparse
  // LU's analysis of J's pattern, which the joints fix); the edited drawing is re-assembled
  // from the current pose at the current crank angle by Newton, or the damped assembly where
  // the edit moved too much for it. It must land on the same branch, regular: the same sign of
  // det J. Anything else (a rank that the edit changed shows as a singular J, or as redundant
  // rows that no longer hold) is left to the whole analysis.
  if (atSingular) return false;
  Status s;
  std::optional<System> edited = compile(m, s);
  const int holds = static_cast<int>(structure.holdCoordinates.size());
  if (!edited || edited->nRows != sys.nRows - holds) return false;
  const Snapshot& now = coordinates(cur());
  Eigen::VectorXd q = carriedPose(sys, now.q, *edited);
  for (int col : structure.holdCoordinates) addHold(*edited, col, q[col]);
  KinematicsState trial(opt);
  trial.mech = m;
  trial.sys = std::move(*edited);
  trial.structure = structure;
  trial.decomposition = decomposition;
  trial.newton = std::move(newton);
  const bool ok = trial.reassemble(q, now.phi) && trial.regSign == regSign;
  if (!ok) {
    newton = std::move(trial.newton);
    return false;
  }
  trial.notes = notes;
  trial.revision = revision;
  trial.noteEdit(-1, EditPath::KeptAnalysis);
  *this = std::move(trial);
  return true;
}

bool KinematicsState::reassemble(Eigen::VectorXd& q, double phi) {
  const Eigen::VectorXd from = q;
  if (!newton.solve(sys, q, phi, opt.newton).converged) {
    q = from;
    AssemblyReport moved;
    if (!assemble(mech, sys, structure, newton, q, phi, moved).ok()) return false;
  }
  return checkRedundant(mech, sys, structure, q, phi).ok() && start(q, phi).ok();
}

Status KinematicsState::editFrom(const KinematicsState& old, const Mechanism& m) {
  lastEditGroups = -1;
  lastEdit = EditPath::Whole;
  const Snapshot& now = old.coordinates(old.cur());
  const double phi = now.phi;
  Status s;
  std::optional<System> next = compile(m, s);
  if (!next) return s;
  const Eigen::VectorXd warm = carriedPose(old.sys, now.q, *next);
  if (s = prepare(m, &warm, phi); s.ok()) return s;
  // The edit moved things too far for a warm start: assemble the drawing and turn the crank.
  if (s = load(m); !s.ok()) return s;
  if (s = moveToPhi(phi); !s.ok()) {
    notes.push_back(
        Note{Note::Kind::CrankMoved,
             "the edited mechanism cannot be turned to the crank angle it was at: " + s.message,
             s.joints, s.bodies});
  }
  return Status::success();
}

}  // namespace linkage
