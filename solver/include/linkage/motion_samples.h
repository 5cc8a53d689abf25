// The motion of chosen points and bodies sampled over whole revolutions of the crank: what plots,
// spectra and extremes are made of.
//
// Positions, velocities and accelerations are the solver's own at every sample (the exact
// linear solves with the constraint Jacobian; never differences of positions). The solver does
// not compute jerk: it is the spectral derivative of the sampled accelerations over one
// revolution (spectrum.h), which needs the motion to repeat after one turn of the crank and is
// as exact as the acceleration's spectrum has decayed by N / 4 harmonics; Curve::errorEstimate
// says how far that is.
//
// A crank that cannot turn the whole way ends the sweep at the last sample before the angle it
// cannot pass: the status says why and where, the samples before it are kept, and nothing after
// it is made up (no NaN rows, no samples from another assembly branch: the tracker refuses
// those steps).
#pragma once

#include <vector>

#include "linkage/kinematics.h"
#include "linkage/spectrum.h"

namespace linkage {

// Which time derivative: position, velocity, acceleration, jerk.
enum class Order { Position = 0, Velocity = 1, Acceleration = 2, Jerk = 3 };
constexpr int kOrders = 4;

// What one curve shows: a component of a point's motion, or a body's rotation (angle, angular
// velocity, angular acceleration, angular jerk).
struct Quantity {
  // X, Y, Z and Along are components of the position vector and its derivatives; Magnitude is
  // the length of each vector (|r|, the speed |v|, |a|, |j|), as Working Model reports them.
  // Distance: the distance from the point to `other` and its rates (d' = D . D' / d,
  // d'' = (D' . D' + D . D'' - d'^2) / d with D the vector between them: exact), the gap a
  // clearance watches, in space on a machine in space.
  enum class Component { X, Y, Magnitude, Along, Z, Distance };
  PointId point;  // set for a point ...
  BodyId body;    // ... or this for a body's rotation
  Component component = Component::Y;
  // Along: the direction (normalised; must not be zero); one out of the x-y plane is the
  // world's.
  Vec3 direction{1, 0, 0};
  PointId other;  // Distance: the second point
  // A point's motion in the world (Kinematics::motionInSpace: a machine in space's x, y, z;
  // z is 0 in a planar one), not in its plane class's frame. Z is always of the world, and so
  // is an Along whose direction leaves the x-y plane.
  bool world = false;
  bool inWorld() const {
    return world || component == Component::Z ||
           (component == Component::Along && direction.z() != 0);
  }

  static Quantity ofPoint(PointId p, Component c, Vec2 along = Vec2(1, 0)) {
    return ofPoint(p, c, Vec3(along.x(), along.y(), 0));
  }
  static Quantity ofPoint(PointId p, Component c, Vec3 along) {
    Quantity q;
    q.point = p;
    q.component = c;
    q.direction = along;
    return q;
  }
  static Quantity distance(PointId p, PointId other) {
    Quantity q;
    q.point = p;
    q.other = other;
    q.component = Component::Distance;
    return q;
  }
  static Quantity ofBody(BodyId b) {
    Quantity q;
    q.body = b;
    return q;
  }
  bool isBody() const { return static_cast<bool>(body); }
};

struct SampleSpec {
  std::vector<PointId> points;
  std::vector<BodyId> bodies;
  long long steps = 360;      // samples per revolution
  double revs = 1;            // steps * revs must be a whole number
  bool accelerations = true;  // needed for accelerations and jerk
  double rpm = 0;             // 0: the mechanism's own
  bool world = false;         // the points' motion in the world too (Quantity::world)
};

struct PointSamples {
  PointId id;
  std::vector<Vec2> p, v, a;  // mm, mm/s, mm/s^2; a is empty without accelerations
  // In the world (SampleSpec::world; empty otherwise): exact, from motionInSpace.
  std::vector<Vec3> p3, v3, a3;
};

struct BodySamples {
  BodyId id;
  std::vector<double> angle, omega, alpha;  // rad (whole turns counted), rad/s, rad/s^2
};

struct MotionSamples {
  // Ok, or why the sweep ended early: an Unreachable or Singular status of the solver, with the
  // crank angle it could not pass; BadModel for an unknown id or a bad spec (no samples then).
  Status status;
  long long steps = 0;
  double revs = 0;
  double rpm = 0, omega = 0;  // omega in rad/s, > 0
  bool accelerations = false;
  bool world = false;            // the points' world motion was sampled
  std::vector<double> crankDeg;  // i * 360 / steps for i = 0, 1, ... as far as the crank went
  std::vector<PointSamples> points;
  std::vector<BodySamples> bodies;
  // The first revolution was sampled and the whole mechanism (every body's pose and angular
  // velocity, every sampled point's position and velocity) is back where it started, to 1e-9
  // of the mechanism's size: the curves repeat with period 360 degrees.
  bool periodic = false;
  // The solver after the sweep, for evaluating between samples (extremes.h).
  Kinematics kinematics;

  long long size() const { return static_cast<long long>(crankDeg.size()); }
  bool complete() const { return status.ok(); }
  const PointSamples* point(PointId id) const;
  const BodySamples* body(BodyId id) const;
};

// Samples the motion of a copy of `k` from crank angle 0 to 360 * revs (both ends included), the
// angles of the motion table (motion_table.h); `k` itself does not move. The copy starts from
// k's pose, so the samples are on k's assembly branch.
MotionSamples sampleMotion(const Kinematics& k, const SampleSpec& spec);

// One curve: the quantity's values at the sampled angles, in mm, mm/s, mm/s^2, mm/s^3 for a
// point and rad, rad/s, rad/s^2, rad/s^3 for a body.
struct Curve {
  Status status;  // BadModel when the samples cannot give this curve (why)
  std::vector<double> crankDeg;
  std::vector<double> values;
  // Jerk only: a bound on the error of the spectral derivative (same unit as values).
  double errorEstimate = 0;
};
Curve curveOf(const MotionSamples& s, const Quantity& q, Order order);

// The quantity, order by order, at the solver's current pose (exact; jerk is not known there
// and comes back as NaN). What a cursor between samples shows.
double valueAt(const Kinematics& k, const Quantity& q, Order order);

// The harmonics of a curve over the first revolution (samples 0 ... steps - 1): needs periodic
// samples (and accelerations for acceleration and jerk); otherwise the terms are empty and
// `why` says so. A body's angle is taken less its steady turning (the whole turns it makes per
// revolution, spread evenly over it): the periodic part, whose harmonics mean something.
Spectrum harmonicsOf(const MotionSamples& s, const Quantity& q, Order order, int maxK,
                     Status* why = nullptr);

}  // namespace linkage
