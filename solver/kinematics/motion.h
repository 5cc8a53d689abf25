// The mechanism at one driver angle, body by body: each body's frame origin and rotation with
// their first and second derivatives in the driver angle phi.
//
// Why body by body and not the coordinate vector q: the closed-form groups produce a body's
// rotation directly (as the direction of a link, a unit vector), and everything asked of a
// pose (points, their velocities and accelerations, instant centres) needs the rotation, not
// the angle. Keeping (cos, sin) avoids a sine and cosine per body per query, and the angle,
// an atan2, is evaluated only when asked for. The angle is continuous (it counts whole turns):
// `turns` is kept by noticing each crossing of the -x axis from one position to the next,
// which needs only signs, as long as a body turns less than half a turn per step (the
// trackers' step limits guarantee far less).
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "elements/body_view.h"

namespace linkage {

struct BodyState {
  Vec2 r = Vec2::Zero(), v = Vec2::Zero(), a = Vec2::Zero();  // frame origin, d/dphi, d2/dphi2
  Rot R;                                                      // rotation
  double w = 0, al = 0;                                       // d theta/dphi, d2 theta/dphi2
  double turns = 0;  // theta = atan2(R) + 2 pi turns: a whole number (a double cannot overflow)

  double angle() const { return std::atan2(R.s, R.c) + 2 * M_PI * turns; }
  Vec2 pos(const Vec2& s) const { return r + R * s; }
  Vec2 vel(const Vec2& s) const { return v + w * perp(R * s); }
  Vec2 acc(const Vec2& s) const {
    const Vec2 g = R * s;
    return a + al * perp(g) - w * w * g;
  }
  // Where the local point s would be after h more radians of driver on the smooth path: Taylor
  // to second order, or to first where accelerations were not computed.
  Vec2 predicted(const Vec2& s, double h, bool accelerations) const {
    const Vec2 first = pos(s) + h * vel(s);
    return accelerations ? Vec2(first + (0.5 * h * h) * acc(s)) : first;
  }
};

// Whole turns of a body whose rotation moved from `before` (with `turns`) to `after` by less
// than half a turn: atan2 jumps by 2 pi where the path crosses the -x axis, which shows as a
// change of sign of sin with cos negative on the way.
inline double turnsAfter(const Rot& before, double turns, const Rot& after) {
  if (std::signbit(before.s) == std::signbit(after.s) || before.c + after.c >= 0) return turns;
  return std::signbit(after.s) ? turns + 1 : turns - 1;
}

// Whole turns that put a body of rotation R nearest to the angle `near`: for a jump (another
// assembly at the same crank angle), where no path between the two positions is followed.
inline double nearestTurns(double near, const Rot& R) {
  return std::round((near - std::atan2(R.s, R.c)) / (2 * M_PI));
}

// A point's position, velocity and acceleration (per radian of driver and its square).
struct PointState {
  Vec2 p, v, a;
};

struct Motion {
  double phi = 0;
  std::vector<BodyState> body;
  // False when only positions and velocities were asked for: a and al are then NaN.
  bool accelerations = true;

  // Body b, or ground (at rest at the origin) for b < 0.
  const BodyState& of(int b) const {
    static const BodyState ground;
    return b < 0 ? ground : body[b];
  }

  // Between this form and the coordinate vectors of the general solve (x, y, theta per body).
  void fromCoordinates(double phiAt, const Eigen::VectorXd& q, const Eigen::VectorXd& dq,
                       const Eigen::VectorXd& ddq);
  void toCoordinates(Eigen::VectorXd& q, Eigen::VectorXd& dq, Eigen::VectorXd& ddq) const;
  // Body k alone from the coordinate vectors (an edit that solved some bodies again).
  void bodyFromCoordinates(int k, const Eigen::VectorXd& q, const Eigen::VectorXd& dq,
                           const Eigen::VectorXd& ddq);
};

// Sets a body from its rotation, angular rate and acceleration and the motion (P, vP, aP) of
// its local point s.
// (Always inlined: the closed-form groups call it once per body per step.)
[[gnu::always_inline]] inline void place(BodyState& b, const Rot& R, double turns, double w,
                                         double al, const Vec2& s, const Vec2& P, const Vec2& vP,
                                         const Vec2& aP) {
  const Vec2 g = R * s;
  b.R = R;
  b.turns = turns;
  b.w = w;
  b.al = al;
  b.r = P - g;
  b.v = vP - w * perp(g);
  b.a = aP - al * perp(g) + w * w * g;
}

}  // namespace linkage
