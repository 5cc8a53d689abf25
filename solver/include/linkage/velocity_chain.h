// The velocity of a point by a chain of instant centres, step by step as a hand solution writes
// it: from the crank (its angular velocity known from the driver) through IC(crank, b) to the
// point's body b, or through bodies of the user's choosing, with the solver's exact velocity
// beside the result.
//
// One step goes from a body `from` whose motion is known to a body `to` through P = IC(from, to):
// v_P = omega_from x (P - IC(1, from)) (or from's velocity if it translates); then `to` turns
// about IC(1, to) with omega_to = (P - IC(1, to)) x v_P / |P - IC(1, to)|^2, or translates with
// v_P if IC(1, to) is at infinity. If IC(from, to) is at infinity the two bodies have the same
// angular velocity.
#pragma once

#include <vector>

#include "linkage/instant_centres.h"

namespace linkage {

// A body's motion at this instant: turning about a finite centre, translating, or at rest.
struct BodyMotion {
  enum class Kind : unsigned char { Turns, Translates, AtRest };
  Kind kind = Kind::AtRest;
  Vec2 pivot = Vec2::Zero();  // Turns: IC(1, body), mm
  double omega = 0;           // Turns: rad/s, counter-clockwise positive
  Vec2 v = Vec2::Zero();      // Translates: mm/s
  Vec2 velocityAt(const Vec2& x) const;
};

struct ChainStep {
  int from = 0, to = 0;           // textbook numbers
  bool centreAtInfinity = false;  // IC(from, to) at infinity: equal angular velocities
  Vec2 centre = Vec2::Zero();     // P = IC(from, to), or its direction at infinity
  double fromArm = 0;             // |P - IC(1, from)| when from turns, mm
  Vec2 vP = Vec2::Zero();         // velocity of P (finite P), mm/s
  double toArm = 0;               // |P - IC(1, to)| when to turns and P is finite, mm
  BodyMotion fromMotion, toMotion;
};

struct VelocityChain {
  // Ok, or why the chain cannot be followed (BadModel: a point or body that is not there, a
  // driver not pivoted to the ground; NotConverged: a step the centres do not determine, such
  // as IC(from, to) and IC(1, to) both at infinity; the message names the step).
  Status status;
  PointId point;
  int body = 0;                  // the point's body number
  int crank = 0;                 // the driven body's number
  BodyMotion crankMotion;        // omega from the driver's rpm and direction
  std::vector<ChainStep> steps;  // empty when the point is on the crank or the ground
  Vec2 position = Vec2::Zero();
  double arm = 0;  // |point - IC(1, body)| when the body turns, mm
  BodyMotion bodyMotion;
  Vec2 velocity = Vec2::Zero();        // by the chain, mm/s
  Vec2 solverVelocity = Vec2::Zero();  // Kinematics::velocity, mm/s (when velocities exist)
};

// `ics` must be the centres of k as it is (the same revision, computed at its current crank
// angle): other centres are refused with BadModel.
// `via`: textbook numbers of the bodies to go through, in order, between the crank and the
// point's body. Empty: the direct step through IC(crank, body), or else the first single body
// (in number order) through which the chain can be followed.
VelocityChain velocityChain(const Kinematics& k, const InstantCentres& ics, PointId point,
                            const std::vector<int>& via = {});

}  // namespace linkage
