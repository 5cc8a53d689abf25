#include "solve/system.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "joints/driver.h"
#include "joints/pin.h"
#include "joints/pin_in_slot.h"
#include "joints/slider.h"

namespace linkage {

int System::bodyIndex(BodyId id) const {
  return id.owner == owner && id.value < bodyIndexById.size() ? bodyIndexById[id.value] : -1;
}

const PointLocation* System::point(PointId id) const {
  return id.owner == owner && id.value < hasPoint.size() && hasPoint[id.value] ? &points[id.value]
                                                                               : nullptr;
}

std::optional<System> compile(const Mechanism& m, Status& status) {
  status = Status::success();
  System sys;
  sys.owner = m.owner();
  // Entities copied in from another mechanism carry its ids, which nothing here can resolve.
  auto foreign = [&](const auto& v) {
    return std::any_of(v.begin(), v.end(), [&](const auto& e) { return e.id.owner != sys.owner; });
  };
  if (foreign(m.bodies) || foreign(m.points) || foreign(m.slots) || foreign(m.joints)) {
    status = Status::badModel(
        "an entity carries an id of another mechanism: copy entities with their names, "
        "not their ids");
    return std::nullopt;
  }
  int grounds = 0;
  for (const Body& b : m.bodies) {
    if (b.ground) {
      ++grounds;
      sys.groundId = b.id;
    } else {
      sys.bodyIds.push_back(b.id);
    }
  }
  if (grounds != 1) {
    status = Status::badModel(grounds == 0 ? "no body is the ground"
                                           : "more than one body is the ground");
    return std::nullopt;
  }
  sys.nBodies = static_cast<int>(sys.bodyIds.size());
  // Lookups by id value, so that compiling is linear in the size of the mechanism.
  std::uint32_t maxBody = 0;
  for (const Body& b : m.bodies) maxBody = std::max(maxBody, b.id.value);
  std::vector<char> isBody(maxBody + 1, 0);
  for (const Body& b : m.bodies) isBody[b.id.value] = 1;
  sys.bodyIndexById.assign(maxBody + 1, -1);
  for (int k = 0; k < sys.nBodies; ++k) sys.bodyIndexById[sys.bodyIds[k].value] = k;
  auto knownBody = [&](BodyId id) {
    return id.owner == sys.owner && id.value <= maxBody && isBody[id.value];
  };
  std::uint32_t maxSlot = 0;
  for (const Slot& sl : m.slots) maxSlot = std::max(maxSlot, sl.id.value);
  std::vector<const Slot*> slotById(maxSlot + 1, nullptr);
  for (const Slot& sl : m.slots) slotById[sl.id.value] = &sl;

  // Frames at the centroid of each body's drawn geometry (points and slot ends).
  std::vector<Vec2> sum(sys.nBodies, Vec2::Zero());
  std::vector<int> count(sys.nBodies, 0);
  Vec2 lo(INFINITY, INFINITY), hi(-INFINITY, -INFINITY);
  auto addGeometry = [&](BodyId body, const Vec2& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
    int k = sys.bodyIndex(body);
    if (k >= 0) {
      sum[k] += p;
      ++count[k];
    }
  };
  for (const Point& p : m.points) {
    if (!knownBody(p.body)) {
      status = Status::badModel("point \"" + p.name + "\" belongs to no body");
      return std::nullopt;
    }
    addGeometry(p.body, p.pos);
  }
  for (const Slot& s : m.slots) {
    if (!knownBody(s.body)) {
      status = Status::badModel("slot \"" + s.name + "\" belongs to no body");
      return std::nullopt;
    }
    if ((s.p1 - s.p0).norm() == 0) {
      status = Status::badModel("slot " + m.slotLabel(s.id) + " has zero length");
      return std::nullopt;
    }
    addGeometry(s.body, s.p0);
    addGeometry(s.body, s.p1);
  }
  // Beyond these, squares of lengths overflow or every length drowns in rounding: refuse
  // rather than return numbers that mean nothing.
  constexpr double kLargest = 1e12, kSmallest = 1e-9;  // mm
  if (lo.allFinite() && std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff()) > kLargest) {
    status =
        Status::badModel("coordinates beyond 1e12 mm: the drawing is too large to compute with");
    return std::nullopt;
  }
  sys.size = (lo.allFinite() && hi.allFinite()) ? (hi - lo).norm() : 1.0;
  if (lo.allFinite() && sys.size < kSmallest * std::max(1.0, hi.cwiseAbs().maxCoeff())) {
    status = Status::badModel(
        "the drawing's extent is below 1e-9 of its size or distance from the origin "
        "(or all its points coincide): rounding would swamp it");
    return std::nullopt;
  }
  const double L = sys.size;

  sys.frameOrigin.resize(sys.nBodies);
  for (int k = 0; k < sys.nBodies; ++k)
    sys.frameOrigin[k] = count[k] ? Vec2(sum[k] / count[k]) : Vec2::Zero();

  // Weights of the movement norm: sum over a body's geometry of |dp|^2 is
  // n |dr|^2 + dtheta^2 sum |s|^2 about the centroid; a small floor keeps it positive definite.
  sys.bodyWeightXY.assign(sys.nBodies, 0.0);
  sys.bodyWeightTheta.assign(sys.nBodies, 0.0);
  auto local = [&](BodyId body, const Vec2& p) -> PointLocation {
    int k = sys.bodyIndex(body);
    return {k, k >= 0 ? Vec2(p - sys.frameOrigin[k]) : p};
  };
  auto weigh = [&](BodyId body, const Vec2& p) {
    PointLocation loc = local(body, p);
    if (loc.body < 0) return;
    sys.bodyWeightXY[loc.body] += 1;
    sys.bodyWeightTheta[loc.body] += loc.s.squaredNorm();
  };
  std::uint32_t maxId = 0;
  for (const Point& p : m.points) maxId = std::max(maxId, p.id.value);
  sys.points.assign(maxId + 1, PointLocation{});
  sys.hasPoint.assign(maxId + 1, 0);
  for (const Point& p : m.points) {
    sys.points[p.id.value] = local(p.body, p.pos);
    sys.hasPoint[p.id.value] = 1;
    weigh(p.body, p.pos);
  }
  for (const Slot& s : m.slots) {
    weigh(s.body, s.p0);
    weigh(s.body, s.p1);
  }
  for (int k = 0; k < sys.nBodies; ++k) {
    sys.bodyWeightXY[k] = std::max(sys.bodyWeightXY[k], 1.0);
    sys.bodyWeightTheta[k] += 1e-6 * L * L;
  }

  int row = 0;
  auto push = [&](Constraint c) {
    c.row = row;
    row += c.rows();
    sys.cons.push_back(c);
  };
  for (size_t ji = 0; ji < m.joints.size(); ++ji) {
    const Joint& j = m.joints[ji];
    sys.jointIds.push_back(j.id);
    const std::string where = "joints[" + std::to_string(ji) + "]";
    const PointLocation* a = sys.point(j.a);
    if (!a) {
      status = Status::badModel(where + ".a: unknown point");
      return std::nullopt;
    }
    Constraint c;
    c.joint = static_cast<int>(ji);
    c.bi = a->body;
    c.si = a->s;
    if (j.type == JointType::Pin) {
      const PointLocation* b = sys.point(j.b);
      if (!b) {
        status = Status::badModel(where + ".b: unknown point");
        return std::nullopt;
      }
      if (b->body == a->body) {
        status = Status::badModel(where + ": both sides are on one body");
        return std::nullopt;
      }
      c.kind = RowKind::Pin;
      c.bj = b->body;
      c.sj = b->s;
      push(c);
      continue;
    }
    const Slot* s =
        j.slot.owner == sys.owner && j.slot.value <= maxSlot ? slotById[j.slot.value] : nullptr;
    if (!s) {
      status = Status::badModel(where + ".slot: unknown slot");
      return std::nullopt;
    }
    PointLocation u = local(s->body, s->p0);
    if (u.body == a->body) {
      status = Status::badModel(where + ": both sides are on one body");
      return std::nullopt;
    }
    c.kind = RowKind::Line;
    c.bj = u.body;
    c.sj = u.s;
    c.nj = perp((s->p1 - s->p0).normalized());
    push(c);
    if (j.type == JointType::Slider) {
      Constraint ang;
      ang.kind = RowKind::Angle;
      ang.joint = c.joint;
      ang.bi = c.bi;
      ang.bj = c.bj;
      ang.c = 0;  // both bodies are at angle 0 in the sketch
      push(ang);
    }
  }
  sys.nJointRows = row;

  if (m.driver) {
    int ji = m.jointIndex(m.driver->joint);
    if (ji < 0 || m.joints[ji].type != JointType::Pin) {
      status = Status::badModel("driver: its joint must be a pin");
      return std::nullopt;
    }
    const Joint& j = m.joints[ji];
    Constraint d;
    d.kind = RowKind::Driver;
    d.joint = ji;
    d.bi = sys.point(j.b)->body;  // theta_b - theta_a
    d.bj = sys.point(j.a)->body;
    sys.driverRow = row;
    push(d);
    sys.hasDriver = true;
    sys.sigma = driveSign(m.driver->direction == Direction::Cw);
    sys.rpm = m.driver->rpm;
    sys.startRad = m.driver->startDeg * M_PI / 180.0;
  }
  sys.nRows = row;
  return sys;
}

void addHold(System& sys, int col, double value) {
  Constraint h;
  h.kind = RowKind::Hold;
  h.col = col;
  h.c = value;
  h.row = sys.nRows++;
  sys.cons.push_back(h);
}

void makeViews(const System& sys, const Eigen::VectorXd& q, const Eigen::VectorXd* v,
               std::vector<BodyView>& views) {
  views.resize(sys.nBodies + 1);
  views[0] = BodyView{};
  for (int k = 0; k < sys.nBodies; ++k) {
    BodyView& b = views[k + 1];
    b.col = 3 * k;
    b.r = Vec2(q[3 * k], q[3 * k + 1]);
    b.theta = q[3 * k + 2];
    b.R = Rot{std::cos(b.theta), std::sin(b.theta)};
    if (v) {
      b.v = Vec2((*v)[3 * k], (*v)[3 * k + 1]);
      b.w = (*v)[3 * k + 2];
    }
  }
}

void setVelocities(const System& sys, const Eigen::VectorXd& v, std::vector<BodyView>& views) {
  for (int k = 0; k < sys.nBodies; ++k) {
    views[k + 1].v = Vec2(v[3 * k], v[3 * k + 1]);
    views[k + 1].w = v[3 * k + 2];
  }
}

namespace {

double holdScale(const System& sys, int col) {
  return col % 3 == 2 ? sys.size : 1.0;
}

double coordinate(const std::vector<BodyView>& views, int col) {
  const BodyView& b = views[col / 3 + 1];
  switch (col % 3) {
    case 0:
      return b.r.x();
    case 1:
      return b.r.y();
    default:
      return b.theta;
  }
}

}  // namespace

void evalResidual(const System& sys, const std::vector<BodyView>& views, double phi,
                  const std::vector<int>& rowMap, Eigen::VectorXd& out) {
  const double L = sys.size;
  for (const Constraint& c : sys.cons) {
    const int r = rowMap[c.row];
    if (r < 0 && (c.kind != RowKind::Pin || rowMap[c.row + 1] < 0)) continue;
    const BodyView& i = views[c.bi + 1];
    const BodyView& j = views[c.bj + 1];
    switch (c.kind) {
      case RowKind::Pin: {
        const Vec2 e = pin::residual(i, c.si, j, c.sj);
        if (r >= 0) out[r] = e.x();
        if (rowMap[c.row + 1] >= 0) out[rowMap[c.row + 1]] = e.y();
        break;
      }
      case RowKind::Line:
        out[r] = line::residual(i, c.si, j, c.sj, c.nj);
        break;
      case RowKind::Angle:
        out[r] = angle::residual(i.theta, j.theta, c.c, L);
        break;
      case RowKind::Driver:
        out[r] = angle::residual(i.theta, j.theta, c.c + sys.sigma * phi, L);
        break;
      case RowKind::Hold:
        out[r] = holdScale(sys, c.col) * (coordinate(views, c.col) - c.c);
        break;
    }
  }
}

namespace {

// Writes into a row-mapped view of J (dense, sparse, or a pattern recorder): rows the map skips
// are dropped.
template <class Target>
struct MappedRows {
  Target& J;
  const std::vector<int>& map;
  int base;
  double sink = 0;
  double& operator()(int row, int col) {
    const int r = map[base + row];
    return r < 0 ? sink : J.coeffRef(r, col);
  }
};

// Accumulates into entries of J that must be zero on entry.
template <class Target>
void addJacobian(const System& sys, const std::vector<BodyView>& views,
                 const std::vector<int>& rowMap, Target& J) {
  const double L = sys.size;
  for (const Constraint& c : sys.cons) {
    MappedRows<Target> rows{J, rowMap, c.row};
    const BodyView& i = views[c.bi + 1];
    const BodyView& j = views[c.bj + 1];
    switch (c.kind) {
      case RowKind::Pin:
        pin::jacobian(rows, 0, i, c.si, j, c.sj);
        break;
      case RowKind::Line:
        line::jacobian(rows, 0, i, c.si, j, c.nj);
        break;
      case RowKind::Angle:
      case RowKind::Driver:
        angle::jacobian(rows, 0, i, j, L);
        break;
      case RowKind::Hold:
        rows(0, c.col) += holdScale(sys, c.col);
        break;
    }
  }
}

// Records where addJacobian writes.
struct PatternRecorder {
  std::vector<Eigen::Triplet<double>> entries;
  double sink = 0;
  double& coeffRef(int row, int col) {
    entries.emplace_back(row, col, 0.0);
    return sink;
  }
};

// Replays the recorded writes into their slots.
struct SlotWriter {
  Eigen::SparseMatrix<double>& J;
  const int* slot;
  double& coeffRef([[maybe_unused]] int row, [[maybe_unused]] int col) {
    const int s = *slot++;
    assert(J.innerIndexPtr()[s] == row && s >= J.outerIndexPtr()[col] &&
           s < J.outerIndexPtr()[col + 1] && "the joints wrote in another order than recorded");
    return J.valuePtr()[s];
  }
};

}  // namespace

void evalJacobian(const System& sys, const std::vector<BodyView>& views,
                  const std::vector<int>& rowMap, Eigen::MatrixXd& J) {
  J.setZero();
  addJacobian(sys, views, rowMap, J);
}

SparseJacobian sparseJacobian(const System& sys, const std::vector<int>& rowMap, int rows) {
  std::vector<BodyView> views;
  makeViews(sys, sketchCoordinates(sys), nullptr, views);
  PatternRecorder rec;
  addJacobian(sys, views, rowMap, rec);
  SparseJacobian out;
  out.J.resize(rows, sys.nCoords());
  out.J.setFromTriplets(rec.entries.begin(), rec.entries.end());
  out.J.makeCompressed();
  out.slot.reserve(rec.entries.size());
  const int* start = out.J.outerIndexPtr();
  const int* inner = out.J.innerIndexPtr();
  for (const auto& e : rec.entries) {
    const int* p = std::lower_bound(inner + start[e.col()], inner + start[e.col() + 1], e.row());
    out.slot.push_back(static_cast<int>(p - inner));
  }
  return out;
}

void evalJacobian(const System& sys, const std::vector<BodyView>& views,
                  const std::vector<int>& rowMap, SparseJacobian& J) {
  J.J.coeffs().setZero();
  SlotWriter w{J.J, J.slot.data()};
  addJacobian(sys, views, rowMap, w);
  assert(w.slot == J.slot.data() + J.slot.size());
}

void evalGamma(const System& sys, const std::vector<BodyView>& views,
               const std::vector<int>& rowMap, Eigen::VectorXd& out) {
  for (const Constraint& c : sys.cons) {
    const int r = rowMap[c.row];
    const BodyView& i = views[c.bi + 1];
    const BodyView& j = views[c.bj + 1];
    switch (c.kind) {
      case RowKind::Pin: {
        const Vec2 g = pin::gamma(i, c.si, j, c.sj);
        if (r >= 0) out[r] = g.x();
        if (rowMap[c.row + 1] >= 0) out[rowMap[c.row + 1]] = g.y();
        break;
      }
      case RowKind::Line:
        if (r >= 0) out[r] = line::gamma(i, c.si, j, c.sj, c.nj);
        break;
      case RowKind::Angle:
      case RowKind::Driver:
      case RowKind::Hold:
        if (r >= 0) out[r] = 0;
        break;
    }
  }
}

Vec2 pointPosition(const System&, const Eigen::VectorXd& q, const PointLocation& p) {
  if (p.body < 0) return p.s;
  const int k = 3 * p.body;
  const Rot R{std::cos(q[k + 2]), std::sin(q[k + 2])};
  return Vec2(q[k], q[k + 1]) + R * p.s;
}

Vec2 pointVelocity(const System&, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                   const PointLocation& p) {
  if (p.body < 0) return Vec2::Zero();
  const int k = 3 * p.body;
  const Rot R{std::cos(q[k + 2]), std::sin(q[k + 2])};
  return Vec2(v[k], v[k + 1]) + v[k + 2] * perp(R * p.s);
}

Vec2 pointAcceleration(const System&, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                       const Eigen::VectorXd& a, const PointLocation& p) {
  if (p.body < 0) return Vec2::Zero();
  const int k = 3 * p.body;
  const Rot R{std::cos(q[k + 2]), std::sin(q[k + 2])};
  const Vec2 s = R * p.s;
  return Vec2(a[k], a[k + 1]) + a[k + 2] * perp(s) - v[k + 2] * v[k + 2] * s;
}

std::vector<Rot> rotations(const System& sys, const Eigen::VectorXd& q) {
  std::vector<Rot> rot(sys.nBodies);
  for (int k = 0; k < sys.nBodies; ++k)
    rot[k] = Rot{std::cos(q[3 * k + 2]), std::sin(q[3 * k + 2])};
  return rot;
}

Eigen::VectorXd sketchCoordinates(const System& sys) {
  Eigen::VectorXd q = Eigen::VectorXd::Zero(sys.nCoords());
  for (int k = 0; k < sys.nBodies; ++k) {
    q[3 * k] = sys.frameOrigin[k].x();
    q[3 * k + 1] = sys.frameOrigin[k].y();
  }
  return q;
}

}  // namespace linkage
