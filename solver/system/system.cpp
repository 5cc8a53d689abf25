#include "system/system.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "elements/cam_row.h"
#include "elements/coincident.h"
#include "elements/distance3.h"
#include "elements/on_circle.h"
#include "elements/on_line.h"

namespace linkage {

int System::bodyIndex(BodyId id) const {
  return id.owner == owner && id.value < bodyIndexById.size() ? bodyIndexById[id.value] : -1;
}

const PointLocation* System::point(PointId id) const {
  return id.owner == owner && id.value < hasPoint.size() && hasPoint[id.value] ? &points[id.value]
                                                                               : nullptr;
}

void addHold(System& sys, int col, double value) {
  Row h;
  h.kind = Primitive::Hold;
  h.col = col;
  h.value = value;
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

// End k of a Distance3 row at the views.
static distance3::End end(const System& sys, const BodyView& b, const Row& c, int k) {
  return {b, c.s[k], sys.frames[c.frame[k]], c.depth[k]};
}

// The angle combination of an Angles row at the views' angles.
static double angleSum(const Row& c, const std::vector<BodyView>& views) {
  double sum = 0;
  for (int k = 0; k < 3; ++k)
    if (c.c[k] != 0) sum += c.c[k] * views[c.body[k] + 1].theta;
  return sum;
}

void evalResidual(const System& sys, const std::vector<BodyView>& views, double phi,
                  const std::vector<int>& rowMap, Eigen::VectorXd& out) {
  const double L = sys.size;
  for (const Row& c : sys.cons) {
    const int r = rowMap[c.row];
    if (r < 0 && (c.kind != Primitive::Coincident || rowMap[c.row + 1] < 0)) continue;
    const BodyView& i = views[c.body[0] + 1];
    const BodyView& j = views[c.body[1] + 1];
    switch (c.kind) {
      case Primitive::Coincident: {
        const Vec2 e = coincident::residual(i, c.s[0], j, c.s[1]);
        if (r >= 0) out[r] = e.x();
        if (rowMap[c.row + 1] >= 0) out[rowMap[c.row + 1]] = e.y();
        break;
      }
      case Primitive::OnLine:
        out[r] = on_line::residual(i, c.s[0], j, c.s[1], c.n);
        break;
      case Primitive::OnCircle:
        out[r] = on_circle::residual(i, c.s[0], j, c.s[1], c.c[0]);
        break;
      case Primitive::Distance3:
        out[r] = distance3::residual(end(sys, i, c, 0), end(sys, j, c, 1), c.c[0]);
        break;
      case Primitive::Angles:
        out[r] = L * (angleSum(c, views) - c.value - c.driven * phi);
        break;
      case Primitive::Hold:
        out[r] = holdScale(sys, c.col) * (coordinate(views, c.col) - c.value);
        break;
      case Primitive::Cam:
        out[r] = cam_row::residual(c, i, j, views[c.body[2] + 1], L);
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
  for (const Row& c : sys.cons) {
    MappedRows<Target> rows{J, rowMap, c.row};
    const BodyView& i = views[c.body[0] + 1];
    const BodyView& j = views[c.body[1] + 1];
    switch (c.kind) {
      case Primitive::Coincident:
        coincident::jacobian(rows, 0, i, c.s[0], j, c.s[1]);
        break;
      case Primitive::OnLine:
        on_line::jacobian(rows, 0, i, c.s[0], j, c.n);
        break;
      case Primitive::OnCircle:
        on_circle::jacobian(rows, 0, i, c.s[0], j, c.s[1], c.c[0]);
        break;
      case Primitive::Distance3:
        distance3::jacobian(rows, 0, end(sys, i, c, 0), end(sys, j, c, 1), c.c[0]);
        break;
      case Primitive::Angles:
        for (int k = 0; k < 3; ++k)
          if (c.c[k] != 0 && c.body[k] >= 0) rows(0, 3 * c.body[k] + 2) += L * c.c[k];
        break;
      case Primitive::Hold:
        rows(0, c.col) += holdScale(sys, c.col);
        break;
      case Primitive::Cam:
        cam_row::jacobian(rows, 0, c, i, j, views[c.body[2] + 1], L);
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

Eigen::Matrix<double, 2, 9> rowJacobian(const System& sys, const std::vector<BodyView>& views,
                                        const Row& r) {
  Eigen::Matrix<double, 2, 9> J = Eigen::Matrix<double, 2, 9>::Zero();
  // Only what the rows' Jacobians read (the pose) and where their columns go here.
  BodyView v[3];
  for (int k = 0; k < 3; ++k) {
    if (r.body[k] < 0) continue;
    v[k].r = views[r.body[k] + 1].r;
    v[k].R = views[r.body[k] + 1].R;
    v[k].col = 3 * k;
  }
  switch (r.kind) {
    case Primitive::Coincident:
      coincident::jacobian(J, 0, v[0], r.s[0], v[1], r.s[1]);
      break;
    case Primitive::OnLine:
      on_line::jacobian(J, 0, v[0], r.s[0], v[1], r.n);
      break;
    case Primitive::OnCircle:
      on_circle::jacobian(J, 0, v[0], r.s[0], v[1], r.s[1], r.c[0]);
      break;
    case Primitive::Distance3:
      distance3::jacobian(J, 0, end(sys, v[0], r, 0), end(sys, v[1], r, 1), r.c[0]);
      break;
    case Primitive::Angles:
      for (int k = 0; k < 3; ++k)
        if (r.body[k] >= 0) J(0, 3 * k + 2) = sys.size * r.c[k];
      break;
    case Primitive::Hold:
      J(0, r.col % 3) = holdScale(sys, r.col);
      break;
    case Primitive::Cam:  // its reaction's row: the contact's (cam_row.h)
      cam_row::contactJacobian(J, r, v[0], v[1], v[2]);
      break;
  }
  return J;
}

void rowForce(const System& sys, const std::vector<BodyView>& views, const Row& r, RowForce& f) {
  f.isCouple = r.kind == Primitive::Angles;
  if (f.isCouple) {
    for (int k = 0; k < 3; ++k) f.couple[k] = r.body[k] >= 0 ? sys.size * r.c[k] : 0.0;
    return;
  }
  const BodyView& i = views[r.body[0] + 1];
  const BodyView& j = views[r.body[1] + 1];
  if (r.kind == Primitive::Cam) {  // the contact's force, along its normal (cam_row.h)
    const cam::Contact k = cam_row::contact(r, i, j, views[r.body[2] + 1]);
    f.P = k.point;
    f.u[0] = k.normal;
    return;
  }
  f.twoEnds = r.kind == Primitive::Distance3;
  if (f.twoEnds) {
    Vec2 at[2];
    distance3::force(end(sys, i, r, 0), end(sys, j, r, 1), r.c[0], at, f.u);
    f.P = at[0];
    f.P1 = at[1];
    return;
  }
  f.P = i.r + i.R * r.s[0];
  if (r.kind == Primitive::Coincident) {
    f.u[0] = Vec2(1, 0);
    f.u[1] = Vec2(0, 1);
  } else if (r.kind == Primitive::OnLine) {
    f.u[0] = j.R * r.n;
  } else {  // OnCircle: along the radius, through the centre s[1] on body[1]
    f.u[0] = (f.P - j.r - j.R * r.s[1]) / r.c[0];
  }
}

void evalGamma(const System& sys, const std::vector<BodyView>& views,
               const std::vector<int>& rowMap, Eigen::VectorXd& out) {
  for (const Row& c : sys.cons) {
    const int r = rowMap[c.row];
    const BodyView& i = views[c.body[0] + 1];
    const BodyView& j = views[c.body[1] + 1];
    switch (c.kind) {
      case Primitive::Coincident: {
        const Vec2 g = coincident::gamma(i, c.s[0], j, c.s[1]);
        if (r >= 0) out[r] = g.x();
        if (rowMap[c.row + 1] >= 0) out[rowMap[c.row + 1]] = g.y();
        break;
      }
      case Primitive::OnLine:
        if (r >= 0) out[r] = on_line::gamma(i, c.s[0], j, c.s[1], c.n);
        break;
      case Primitive::OnCircle:
        if (r >= 0) out[r] = on_circle::gamma(i, c.s[0], j, c.s[1], c.c[0]);
        break;
      case Primitive::Distance3:
        if (r >= 0) out[r] = distance3::gamma(end(sys, i, c, 0), end(sys, j, c, 1), c.c[0]);
        break;
      case Primitive::Angles:
      case Primitive::Hold:
        if (r >= 0) out[r] = 0;
        break;
      case Primitive::Cam:
        if (r >= 0) out[r] = cam_row::gamma(c, i, j, views[c.body[2] + 1], sys.size);
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
