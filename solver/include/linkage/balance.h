// Counterweights that balance the shaking force exactly, their own weight included. A
// counterweight on body k is a point mass m_k at u_k from the point where the body is pinned to
// the ground (u_k fixed in the body); what it adds to the shaking force is linear in its static
// moment s_k = m_k u_k (kg mm: the inertia force of a point turning with the body) and in its
// mass (its weight m_k g, a constant force on the frame). It may sit at most R_k from the pivot
// (the farthest point or slot end drawn on the body), so |s_k| <= R_k m_k: a cone, convex.
// Minimising the peak of the shaking force over the cycle is then a convex programme in (s, m):
// linear rows at sampled angles (a Chebyshev approximation) and the cone by tangent rows that
// contain it, solved by COIN-OR CLP, then refined to the continuous optimum by exchange: the true
// peak of the solution is found between the samples by Brent's method on the exact motion, its
// angle (and, for |F|, its direction) added to the programme, and the cone's tangent where the
// solution leaves it, until the peak and the programme's optimum (a lower bound: no counterweights
// within the bounds do better on the angles used) agree. Their difference is the certified gap.
// No counterweight at all is one of the choices: the peak after is never above the peak before.
//
// A machine in space (linkage/space.h): the shaking force is the world's, in 3D; a counterweight
// turns in its body's plane, so it adds only to the components in that plane (its static moment
// a 2D vector in the plane), and |F| <= t is held by tangent rows on the sphere. What lies along
// the normal of every counterweight's plane, when they are all parallel, is beyond them: said
// with its peak (BalanceResult::unreached; docs/balancing.md, "Machines in space").
#pragma once

#include <optional>
#include <vector>

#include "linkage/kinematics.h"

namespace linkage {

// |shaking fx|, |shaking fy|, |shaking force|; |shaking fz| (a machine in space). In the world's
// axes; a planar machine's |force| is in its plane.
enum class BalanceMeasure { Fx, Fy, Force, Fz };

struct BalanceOptions {
  std::vector<BodyId> bodies;  // a counterweight on each (pinned to the ground)
  BalanceMeasure measure = BalanceMeasure::Force;
  std::optional<double> maxKgMm;  // |s| at most this on each body
  int steps = 360;                // samples per turn for the first programme
  double tolerance = 1e-9;        // the gap, relative to the peak before
};

struct Counterweight {
  BodyId body;
  PointId pivot;                     // the body's point pinned to the ground
  Vec2 staticMoment = Vec2::Zero();  // kg mm, in the body's sketch frame
  double kg = 0;                     // its mass (its weight is part of the peak after)
  double maxRadiusMm =
      0;  // R: the farthest point or slot end drawn on the body from the pivot (20 mm when none)
  double kgMm() const { return staticMoment.norm(); }
  // From the pivot: at most maxRadiusMm; less where a heavier mass nearer the pivot does better
  // under gravity (0: a mass on the pivot itself).
  double radiusMm() const { return kg > 0 ? staticMoment.norm() / kg : 0; }
  double angleDeg() const;  // of u in the body's sketch frame
  bool none() const { return kg == 0 && kgMm() == 0; }
};

struct BalanceResult {
  Status status;  // BadModel naming the body or the option; the tracker's where it cannot turn
  std::vector<Counterweight> counterweights;
  double peakBefore = 0, peakBeforeDeg = 0;  // N, crank degrees
  double peakAfter = 0, peakAfterDeg = 0;    // with the counterweights as they are applied
  double lowerBound = 0;                     // the programme's optimum: the peak cannot go lower
  double gap() const { return peakAfter - lowerBound; }
  // What no counterweight reaches: where every counterweight's plane is parallel (a planar
  // machine's: the drawing's), the shaking force along their normal `unreached` (world, unit),
  // which their turning cannot change (their weight adds to it, one way); its peak |F . n| with
  // the counterweights applied and before (N, crank degrees). None where the planes span space.
  std::optional<Vec3> unreached;
  double unreachedPeak = 0, unreachedPeakDeg = 0, unreachedPeakBefore = 0;
  int exchanges = 0;  // rounds of the exchange
  int angles = 0;     // angles the last programme used
};

// A counterweight on body b, none yet: its pivot (b's point pinned to the ground) and its reach
// R. BadModel naming the body where it is the ground or not pinned to it.
Status counterweightOn(const Mechanism& m, BodyId b, Counterweight& c);

// k is not moved (copies of it are).
BalanceResult balanceShaking(const Kinematics& k, const BalanceOptions& opt);

// Where a counterweight's body turns in the world: its plane class frame's axes E (3 x 2) and
// its plane's turn P into that frame (a planar machine's: the drawing's x, y and I).
struct CounterweightPlacing {
  Eigen::Matrix<double, 3, 2> E = Eigen::Matrix<double, 3, 2>::Zero();
  Eigen::Matrix2d P = Eigen::Matrix2d::Identity();
  bool turned = false;  // P is not the identity
  Vec3 normal = Vec3::UnitZ();
};
CounterweightPlacing placeCounterweight(const Mechanism& m, BodyId b);

// What a counterweight on body b adds to the shaking force in the world per kg mm of its static
// moment, at k's pose (N per kg mm): 1e-3 E (omega^2 I - alpha perp) R(theta) P, a point mass
// turning about its fixed pivot with its body (its weight m g is apart).
Eigen::Matrix<double, 3, 2> counterweightForcePerMoment(const Kinematics& k, BodyId b,
                                                        const CounterweightPlacing& p);
// Its change where the body's angle, angular velocity and acceleration change by dTheta, dOmega,
// dAlpha (rad, rad/s, rad/s^2; a dimension's, at the same pose).
Eigen::Matrix<double, 3, 2> counterweightForcePerMomentChange(const Kinematics& k, BodyId b,
                                                              const CounterweightPlacing& p,
                                                              double dTheta, double dOmega,
                                                              double dAlpha);

// The counterweights as masses of their bodies: a point mass kg at pivot + staticMoment / kg,
// combined with the body's own (and listed in Mass::counterweights).
void addCounterweights(Mechanism& m, const std::vector<Counterweight>& c);

}  // namespace linkage
