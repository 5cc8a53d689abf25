#include "kinematics/closed_form.h"

#include <cmath>

#include "elements/cam_row.h"

namespace linkage {

namespace {

Rot compose(const Rot& a, const Rot& b) {
  return Rot{a.c * b.c - a.s * b.s, a.s * b.c + a.c * b.s};
}

// The rotation taking a body's local direction (given as the rotation `local`) to the unit
// vector u: the pose follows without a sin and cos of the body's angle. (u is C - P over the
// link's length: a unit vector to rounding, as the intersection put C at that distance.)
Rot turning(const Rot& local, const Vec2& u) {
  return compose(Rot{u.x(), u.y()}, Rot{local.c, -local.s});
}

PointState pointOf(int body, const BodyState& b, const Vec2& s) {
  if (body < 0) return {s, Vec2::Zero(), Vec2::Zero()};
  const Vec2 g = b.R * s, t = perp(g);
  return {b.r + g, b.v + b.w * t, b.a + b.al * t - b.w * b.w * g};
}

// The 2 x 2 system [a b] x = rhs of a group's velocities, then of its accelerations (the same
// matrix). Singular when the columns are (nearly) parallel: a dead point, left to the general
// solver to explain.
struct Solve2 {
  Vec2 a, b;
  double det;
  Solve2(const Vec2& a_, const Vec2& b_) : a(a_), b(b_), det(cross(a_, b_)) {}
  bool regular() const { return det * det > 1e-20 * a.squaredNorm() * b.squaredNorm(); }
  void solve(const Vec2& rhs, double& x, double& y) const {
    x = cross(rhs, b) / det;
    y = cross(a, rhs) / det;
  }
};

// The RS group's equation a cos t + b sin t = c (closed_form.h) at the known bodies' motion:
// the pin P1 in b1's class F1, the rod's far end p2 in its class F2.
struct RockerTerms {
  Vec3 Q, V2, A2;  // world: Q, and the far end's velocity and acceleration
  Vec3 E1, E2;
  double a, b, c;
};

RockerTerms rockerTerms(const Plane& F1, const Plane& F2, const Vec2& u, double z1, double z2,
                        double l, const Vec2& P1, const PointState& p2) {
  RockerTerms t;
  const Vec3 X = F1.xAxis, Y = F1.yAxis;
  t.Q = F1.world(P1, z1) - F2.world(p2.p, z2);
  t.V2 = p2.v.x() * F2.xAxis + p2.v.y() * F2.yAxis;
  t.A2 = p2.a.x() * F2.xAxis + p2.a.y() * F2.yAxis;
  t.E1 = u.x() * X + u.y() * Y;
  t.E2 = -u.y() * X + u.x() * Y;
  t.a = 2 * t.Q.dot(t.E1);
  t.b = 2 * t.Q.dot(t.E2);
  t.c = l * l - t.Q.squaredNorm() - u.squaredNorm();
  return t;
}

Vec3 lift(const Plane& F, const Vec2& v) {
  return v.x() * F.xAxis + v.y() * F.yAxis;
}

}  // namespace

bool ClosedFormPlan::solve(const System& sys, const Motion& prev, double phi, Motion& next,
                           bool accelerations) const {
  next.phi = phi;
  next.accelerations = accelerations;
  next.body.resize(sys.nBodies);
  const Rot crank{std::cos(phi), std::sin(phi)};
  for (const Group& g : groups_)
    if (!solveGroup(g, sys, prev, phi - prev.phi, crank, next)) return false;
  return true;
}

void ClosedFormPlan::bodiesOf(const Group& g, std::vector<int>& unknown,
                              std::vector<int>& known) const {
  unknown.clear();
  known.clear();
  if (g.kind == Kind::Core) {
    const CoreGroup& core = cores_[g.core];
    unknown.push_back(core.core);
    for (const CoreLink& l : core.links) {
      if (l.block >= 0) unknown.push_back(l.block);
      known.push_back(l.known);
    }
    return;
  }
  for (int b : {g.b1, g.b2})
    if (b >= 0) unknown.push_back(b);
  known.push_back(g.k1);
  if (g.kind != Kind::Crank) known.push_back(g.k2);
  if (g.kind == Kind::Geared) known.push_back(g.k3);
}

bool ClosedFormPlan::sameGeometry(const Group& a, const Group& b, const ClosedFormPlan& pa,
                                  const ClosedFormPlan& pb) {
  if (a.kind == Kind::Core) {
    const std::vector<CoreLink>&la = pa.cores_[a.core].links, &lb = pb.cores_[b.core].links;
    if (la.size() != lb.size()) return false;
    for (size_t i = 0; i < la.size(); ++i)
      if (la[i].s != lb[i].s || la[i].ks != lb[i].ks || la[i].n != lb[i].n ||
          la[i].blockPin != lb[i].blockPin)
        return false;
    return true;
  }
  return a.p1k == b.p1k && a.p1 == b.p1 && a.c1 == b.c1 && a.c2 == b.c2 && a.p2 == b.p2 &&
         a.p2k == b.p2k && a.u == b.u && a.n == b.n && a.q2 == b.q2 &&
         (a.kind != Kind::RC || a.d2 == b.d2) && (a.kind != Kind::Cam || *a.cam == *b.cam) &&
         (a.kind != Kind::RS ||
          (a.d2 == b.d2 && a.f1 == b.f1 && a.f2 == b.f2 && a.z1 == b.z1 && a.z2 == b.z2));
}

std::vector<int> ClosedFormPlan::bodiesOf(int g) const {
  std::vector<int> unknown, known;
  bodiesOf(groups_[g], unknown, known);
  return unknown;
}

int ClosedFormPlan::resolveFrom(size_t first, const System& sys, const Motion& prev, Motion& next,
                                std::vector<char>& moved, bool jump, const ClosedFormPlan* before,
                                const std::vector<char>* reframed) const {
  const Rot crank{std::cos(prev.phi), std::sin(prev.phi)};
  std::vector<int> unknown, known;
  int solved = 0;
  for (size_t i = first; i < groups_.size(); ++i) {
    const Group& g = groups_[i];
    bodiesOf(g, unknown, known);
    bool touched = before ? !sameGeometry(before->groups_[i], g, *before, *this) : i == first;
    for (int b : known) touched = touched || (b >= 0 && moved[b]);
    // A body whose frame moved (its drawing changed, if only rigidly: a redraw) is where its
    // old displacement puts it, not where its joints hold it: solved again too.
    for (int b : unknown) touched = touched || (reframed && b >= 0 && (*reframed)[b]);
    if (!touched) continue;  // its bodies keep the motion already in next
    if (!solveGroup(g, sys, prev, 0.0, crank, next, jump)) return -1;
    for (int b : unknown) moved[b] = 1;
    ++solved;
  }
  return solved;
}

int ClosedFormPlan::resolveEdited(const System& sys, const ClosedFormPlan& before,
                                  const Motion& prev, Motion& next,
                                  const std::vector<char>& reframed) {
  if (before.groups_.size() != groups_.size() || before.cores_.size() != cores_.size()) return -1;
  std::vector<int> unknown, known, knownBefore;
  for (size_t i = 0; i < groups_.size(); ++i) {
    const Group &a = before.groups_[i], &b = groups_[i];
    bodiesOf(a, unknown, knownBefore);
    bodiesOf(b, unknown, known);
    if (a.kind != b.kind || a.b1 != b.b1 || a.b2 != b.b2 || known != knownBefore) return -1;
  }
  // The same assembly branches as before the edit.
  for (size_t i = 0; i < groups_.size(); ++i) groups_[i].sign = before.groups_[i].sign;
  for (size_t i = 0; i < cores_.size(); ++i) cores_[i].detSign = before.cores_[i].detSign;

  next.phi = prev.phi;
  next.body = prev.body;
  next.accelerations = prev.accelerations;
  std::vector<char> moved(sys.nBodies, 0);
  return resolveFrom(0, sys, prev, next, moved, false, &before, &reframed);
}

bool ClosedFormPlan::flip(int g, const System& sys, const Motion& prev, Motion& next) {
  if (!hasMirror(g)) return false;
  ClosedFormPlan trial = *this;
  Group& G = trial.groups_[g];
  if (G.kind == Kind::Core)
    trial.cores_[G.core].detSign = -trial.cores_[G.core].detSign;
  else
    G.sign = -G.sign;
  next.phi = prev.phi;
  next.body = prev.body;
  next.accelerations = prev.accelerations;
  std::vector<char> moved(sys.nBodies, 0);
  if (trial.resolveFrom(static_cast<size_t>(g), sys, prev, next, moved, true) < 0) return false;
  *this = std::move(trial);
  return true;
}

void ClosedFormPlan::coupledAngle(const Group& g, const System& sys, const Motion& next,
                                  double& theta, double& w, double& al) {
  // sum c_k theta_k = value over the row's bodies: theta_B from the others (known, in next).
  const Row& row = sys.cons[g.angles];
  double cb = 0, sum = row.value, wsum = 0, asum = 0;
  for (int k = 0; k < 3; ++k) {
    if (row.c[k] == 0) continue;
    if (row.body[k] == g.b1) {
      cb += row.c[k];
      continue;
    }
    const BodyState& o = next.of(row.body[k]);
    sum -= row.c[k] * (row.body[k] < 0 ? 0.0 : o.angle());
    wsum -= row.c[k] * o.w;
    asum -= row.c[k] * o.al;
  }
  theta = sum / cb;
  w = wsum / cb;
  al = asum / cb;
}

namespace {

// Sets body b, continuing its count of whole turns from the previous position (a jump: the
// nearest to it).
[[gnu::always_inline]] inline void setBody(Motion& next, const Motion& prev, bool jump, int b,
                                           const Rot& R, double w, double al, const Vec2& s,
                                           const Vec2& P, const Vec2& vP, const Vec2& aP) {
  const BodyState& before = prev.body[b];
  const double turns =
      jump ? nearestTurns(before.angle(), R) : turnsAfter(before.R, before.turns, R);
  place(next.body[b], R, turns, w, al, s, P, vP, aP);
}

}  // namespace

inline bool ClosedFormPlan::circles(const Group& g, const Motion& prev, const Vec2& Cpred,
                                    const PointState& p1, Motion& next, bool jump,
                                    Dyad& out) const {
  const PointState p2 = pointOf(g.k2, next.of(g.k2), g.p2k);
  const Vec2 &P1 = p1.p, &P2 = p2.p;
  const double d1 = g.d1, d2 = g.d2;
  const Vec2 e = P2 - P1;
  const double L = e.norm();
  if (!(L > 0)) return false;
  const Vec2 eh = e / L;
  const double a = (d1 * d1 - d2 * d2 + L * L) / (2 * L);
  const double h2 = d1 * d1 - a * a;
  if (!(h2 >= 0)) return false;
  if (!jump && g.sign * cross(eh, Cpred - P1) < 0) return false;
  const Vec2 C = P1 + a * eh + g.sign * std::sqrt(h2) * perp(eh);
  out.u1 = C - P1;
  const Vec2 u2 = C - P2;
  const Solve2 m(perp(out.u1), -perp(u2));
  if (!m.regular()) return false;
  double w2, al2;
  m.solve(p2.v - p1.v, out.w1, w2);
  if (next.accelerations)
    m.solve(p2.a - p1.a - w2 * w2 * u2 + out.w1 * out.w1 * out.u1, out.al1, al2);
  else
    out.al1 = al2 = NAN;
  // RC: the second link is the arc's radius, no body's.
  if (g.kind == Kind::RRR)
    setBody(next, prev, jump, g.b2, turning(g.rot2, u2 / d2), w2, al2, g.p2, P2, p2.v, p2.a);
  return true;
}

inline bool ClosedFormPlan::line(const Group& g, const Vec2& Cpred, const PointState& p1,
                                 Motion& next, bool jump, Dyad& out) const {
  // The line C must keep to: the slot (through U, normal n), shifted by the block's offset.
  const Vec2 &P1 = p1.p, &vP1 = p1.v, &aP1 = p1.a;
  const bool acc = next.accelerations;
  const double d1 = g.d1;
  const BodyState& k2 = next.of(g.k2);
  const Vec2 n = k2.R * g.n, dir = k2.R * g.d, U = k2.pos(g.u);
  const Vec2 w = g.kind == Kind::RRP ? Vec2(k2.R * (g.q2 - g.c2)) : Vec2::Zero();
  const double delta = n.dot(U - w - P1);
  const double lam2 = d1 * d1 - delta * delta;
  if (!(lam2 >= 0)) return false;
  const Vec2 foot = P1 + delta * n;
  if (!jump && g.sign * dir.dot(Cpred - foot) < 0) return false;
  const Vec2 C = foot + g.sign * std::sqrt(lam2) * dir;
  const Vec2 u1 = C - P1;
  out.u1 = u1;
  // C = U + s dir - w, with the block turning with k2 (w' = w_k2 perp(w)).
  const double s = dir.dot(C + w - U);
  const Solve2 m(perp(u1), -dir);
  if (!m.regular()) return false;
  double &w1 = out.w1, &al1 = out.al1, sd, sdd;
  Vec2 V0 = Vec2::Zero(), A0 = Vec2::Zero();  // a slot in the ground does not move
  if (g.k2 < 0) {
    m.solve(-vP1, w1, sd);
    if (acc) m.solve(w1 * w1 * u1 - aP1, al1, sdd);
  } else {
    const PointState uk = pointOf(g.k2, k2, g.u);
    V0 = uk.v + s * k2.w * perp(dir) - k2.w * perp(w);
    m.solve(V0 - vP1, w1, sd);
    if (acc)
      A0 = uk.a + 2 * sd * k2.w * perp(dir) + s * (k2.al * perp(dir) - k2.w * k2.w * dir) -
           (k2.al * perp(w) - k2.w * k2.w * w);
    if (acc) m.solve(A0 - aP1 + w1 * w1 * u1, al1, sdd);
  }
  if (!acc) al1 = sdd = NAN;
  if (g.kind == Kind::RRP) {
    // The block keeps its slot body's angle (the slider holds the drawn relative angle, zero),
    // whole turns included.
    place(next.body[g.b2], k2.R, k2.turns, k2.w, k2.al, g.c2, C, V0 + sd * dir, A0 + sdd * dir);
  }
  return true;
}

bool ClosedFormPlan::solveGroup(const Group& g, const System& sys, const Motion& prev, double h,
                                const Rot& crank, Motion& next, bool jump) const {
  if (g.kind == Kind::Core) {
    const CoreGroup& core = cores_[g.core];
    if (!jump) return solveCore(core, sys, prev, next);
    BodyState start;
    return corePose(core, next, start) && solveCore(core, sys, prev, next, &start);
  }
  if (g.kind == Kind::Cam) return follower(g, prev, next, jump);
  const BodyState& k1 = next.of(g.k1);
  const PointState p1 = pointOf(g.k1, k1, g.p1k);
  if (g.kind == Kind::Crank) {
    setBody(next, prev, jump, g.b1, compose(k1.R, g.sign > 0 ? crank : Rot{crank.c, -crank.s}),
            k1.w + g.sign, k1.al, g.p1, p1.p, p1.v, p1.a);
    return true;
  }
  if (g.kind == Kind::PR) return slotted(g, prev, h, p1, next, jump);
  if (g.kind == Kind::RS) return rocker(g, sys, prev, h, p1, next, jump);
  if (g.kind == Kind::Geared) {
    double theta, w, al;
    coupledAngle(g, sys, next, theta, w, al);
    const Rot R = Rot::of(theta);
    place(next.body[g.b1], R, nearestTurns(theta, R), w, next.accelerations ? al : NAN, g.p1, p1.p,
          p1.v, p1.a);
    return true;
  }
  // The joint C as the smooth motion would carry it: if that lands on the other side of the
  // branch line than the drawn branch, the motion crosses a singular position (a change
  // point, or a dead point ahead), where the intersection formula would reflect onto the
  // other branch. The general solve takes over there and reports it.
  const Vec2 Cpred = prev.body[g.b1].predicted(g.c1, h, prev.accelerations);
  Dyad d;
  const bool ok = g.kind == Kind::RRR || g.kind == Kind::RC
                      ? circles(g, prev, Cpred, p1, next, jump, d)
                      : line(g, Cpred, p1, next, jump, d);
  if (!ok) return false;
  setBody(next, prev, jump, g.b1, turning(g.rot1, d.u1 / g.d1), d.w1, d.al1, g.p1, p1.p, p1.v,
          p1.a);
  return true;
}

bool ClosedFormPlan::slotted(const Group& g, const Motion& prev, double h, const PointState& p1,
                             Motion& next, bool jump) const {
  const PointState c = pointOf(g.k2, next.of(g.k2), g.p2k);
  const Vec2 D = c.p - p1.p, Dv = c.v - p1.v, Da = c.a - p1.a;
  const double L2 = D.squaredNorm(), k = g.n.dot(g.u - g.p1), h2 = L2 - k * k;
  if (!(L2 > 0) || !(h2 >= 0)) return false;
  // The slot's normal as the motion carries it: on the other side of D than drawn, the motion
  // crosses a singular position (|D| = |k|); the general solve takes over and explains it.
  if (!jump) {
    const BodyState& b = prev.body[g.b1];
    const Vec2 Np =
        b.predicted(g.p1 + g.n, h, prev.accelerations) - b.predicted(g.p1, h, prev.accelerations);
    if (g.sign * cross(D, Np) < 0) return false;
  }
  const Vec2 N = (k * D + g.sign * std::sqrt(h2) * perp(D)) / L2;
  const double den = perp(N).dot(D);
  if (!(den * den > 1e-20 * L2)) return false;
  const double w = -N.dot(Dv) / den;
  const double al =
      next.accelerations ? (w * w * k - 2 * w * perp(N).dot(Dv) - N.dot(Da)) / den : NAN;
  setBody(next, prev, jump, g.b1, turning(g.rot1, N), w, al, g.p1, p1.p, p1.v, p1.a);
  return true;
}

double ClosedFormPlan::rockerSide(const Group& g, const System& sys, const Motion& m,
                                  const Rot& R) const {
  const PointState p1 = pointOf(g.k1, m.of(g.k1), g.p1k);
  const PointState p2 = pointOf(g.k2, m.of(g.k2), g.p2k);
  const RockerTerms t =
      rockerTerms(sys.frames[g.f1], sys.frames[g.f2], g.c1 - g.p1, g.z1, g.z2, g.d2, p1.p, p2);
  // sin(t - atan2(b, a)), scaled: which root of a cos t + b sin t = c the rotation is.
  const double side = t.a * R.s - t.b * R.c;
  return side > 0 ? 1 : side < 0 ? -1 : 0;
}

bool ClosedFormPlan::rocker(const Group& g, const System& sys, const Motion& prev, double h,
                            const PointState& p1, Motion& next, bool jump) const {
  const Plane &F1 = sys.frames[g.f1], &F2 = sys.frames[g.f2];
  const Vec2 u = g.c1 - g.p1;
  const PointState p2 = pointOf(g.k2, next.of(g.k2), g.p2k);
  const RockerTerms t = rockerTerms(F1, F2, u, g.z1, g.z2, g.d2, p1.p, p2);
  const double rho2 = t.a * t.a + t.b * t.b;
  if (!(rho2 > 0)) return false;
  const double rho = std::sqrt(rho2), ch = t.c / rho;
  if (!(std::abs(ch) <= 1)) return false;  // the rod cannot reach: a dead point passed
  const double sh = g.sign * std::sqrt(1 - ch * ch);
  const double c0 = t.a / rho, s0 = t.b / rho;
  const Rot R{c0 * ch - s0 * sh, s0 * ch + c0 * sh};
  if (!jump) {
    // Where the motion carries C: on the other side of the branch line, a dead point lies
    // between (the general solve takes over and explains it).
    const Vec2 v = prev.body[g.b1].predicted(g.c1, h, prev.accelerations) - p1.p;
    const Rot Rp{v.dot(u), cross(u, v)};  // rotation by the predicted angle, scaled
    if (g.sign * (t.a * Rp.s - t.b * Rp.c) < 0) return false;
  }
  const Vec2 Ru = R * u, pRu = perp(Ru);
  const Vec3 D = t.Q + lift(F1, Ru);
  const Vec2 gD(D.dot(F1.xAxis), D.dot(F1.yAxis));
  const double den = gD.dot(pRu);
  if (!(den * den > 1e-20 * gD.squaredNorm() * u.squaredNorm())) return false;
  const double w = D.dot(t.V2 - lift(F1, p1.v)) / den;
  double al = NAN;
  if (next.accelerations) {
    const Vec3 dD = lift(F1, p1.v + w * pRu) - t.V2;
    al = (D.dot(t.A2 - lift(F1, p1.a) + w * w * lift(F1, Ru)) - dD.squaredNorm()) / den;
  }
  setBody(next, prev, jump, g.b1, R, w, al, g.p1, p1.p, p1.v, p1.a);
  return true;
}

}  // namespace linkage
