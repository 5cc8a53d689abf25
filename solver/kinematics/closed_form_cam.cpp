// The cam group of the closed-form plan (closed_form.h, "cam"): a follower placed from its guide
// and its cam in one pass, no iteration. The equations are the cam row's and the follower's own
// joint's (elements/cam_row.h, on_line.h) with the known bodies' motion put in, as the general
// solve's rows would give it: the tests compare the two paths to rounding.
#include <cmath>

#include "elements/cam_row.h"
#include "kinematics/closed_form.h"

namespace linkage {

namespace {

// A line turning with the guide (and the translating follower, which keeps the guide's angle)
// that the follower's point must keep at a signed distance t from the guide's point:
//   N . (r_F + A - Q) = t,  N = R n,  A = R a (a on the follower),  Q on the guide.
// Its terms once the follower's origin (then its velocity) is known.
struct Held {
  Vec2 N, A, Q, vQ, aQ;
  double t, dt, ddt;  // t and its first and second derivatives by the driver angle
  // N . r_F = rhs
  double position() const { return t - N.dot(A - Q); }
  // N . v_F = rhs, with the guide's rate w and the origin r
  double velocity(double w, const Vec2& r) const {
    return dt - w * perp(N).dot(r + A - Q) - N.dot(w * perp(A) - vQ);
  }
  // N . a_F = rhs, with the guide's rate w and acceleration al and the origin's r and v
  double acceleration(double w, double al, const Vec2& r, const Vec2& v) const {
    const Vec2 D = r + A - Q, dD = v + w * perp(A) - vQ;
    return ddt - (al * perp(N) - w * w * N).dot(D) - 2 * w * perp(N).dot(dD) -
           N.dot(al * perp(A) - w * w * A - aQ);
  }
};

Held held(const Rot& R, const BodyState& guide, const Vec2& n, const Vec2& a, const Vec2& q) {
  Held h;
  h.N = R * n;
  h.A = R * a;
  h.Q = guide.pos(q);
  h.vQ = guide.vel(q);
  h.aQ = guide.acc(q);
  h.t = h.dt = h.ddt = 0;
  return h;
}

// x with rows N1^T x = b1, N2^T x = b2.
Vec2 solveRows(const Vec2& N1, const Vec2& N2, double det, double b1, double b2) {
  return Vec2(b1 * N2.y() - b2 * N1.y(), N1.x() * b2 - N2.x() * b1) / det;
}

}  // namespace

bool ClosedFormPlan::follower(const Group& g, const Motion& prev, Motion& next, bool jump) const {
  const CamRow& k = *g.cam;
  const BodyState &guide = next.of(g.k1), &cam = next.of(g.k2);
  const bool acc = next.accelerations;
  // The cam's turn relative to the guide and the follower's displacement by the driver angle.
  const double w = cam.w - guide.w, al = acc ? cam.al - guide.al : 0.0;
  const cam::Displacement s = k.program.at(camAngle(cam.R, guide.R));
  const double ds = s.v * w, dds = acc ? s.a * w * w + s.v * al : NAN;
  BodyState& f = next.body[g.b1];
  const BodyState& before = prev.body[g.b1];
  if (k.kind.oscillating) {
    const double sg = k.kind.sign, turn = sg * s.s;
    const Rot T = Rot::of(turn), &G = guide.R;
    const Rot R{G.c * T.c - G.s * T.s, G.s * T.c + G.c * T.s};
    const double turns =
        jump ? nearestTurns(before.angle(), R) : turnsAfter(before.R, before.turns, R);
    place(f, R, turns, guide.w + sg * ds, acc ? guide.al + sg * dds : NAN, g.p1, guide.pos(g.p1k),
          guide.vel(g.p1k), guide.acc(g.p1k));
    return true;
  }
  // Translating: the cam's line (along the slot, at s from the drawn b) and the slot's.
  const Rot& R = guide.R;
  Held cut = held(R, guide, k.along, g.c2, g.p2), slot = held(R, guide, g.n, g.c1, g.p2k);
  cut.t = s.s;
  cut.dt = ds;
  cut.ddt = dds;
  const double det = cross(cut.N, slot.N);
  if (!(std::abs(det) > 1e-9)) return false;  // the slot along the cam's line: no such cam
  f.R = R;
  f.turns = guide.turns;
  f.w = guide.w;
  f.al = acc ? guide.al : NAN;
  f.r = solveRows(cut.N, slot.N, det, cut.position(), slot.position());
  f.v = solveRows(cut.N, slot.N, det, cut.velocity(f.w, f.r), slot.velocity(f.w, f.r));
  if (acc)
    f.a = solveRows(cut.N, slot.N, det, cut.acceleration(f.w, f.al, f.r, f.v),
                    slot.acceleration(f.w, f.al, f.r, f.v));
  else
    f.a = Vec2::Constant(NAN);
  return true;
}

}  // namespace linkage
