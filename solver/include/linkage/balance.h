// Counterweights that balance the shaking force exactly: the shaking force is linear in the
// counterweights' static moments s_k = m_k u_k (kg mm, u_k fixed in body k from the point where
// it is pinned to the ground), so minimising its peak over the cycle is a linear programme (a
// Chebyshev approximation), solved by COIN-OR CLP on sampled angles, then refined to the
// continuous optimum by exchange: the true peak of the solution is found between the samples by
// Brent's method on the exact motion, its angle (and, for |F|, its direction) added to the
// programme, until the peak and the programme's optimum (a lower bound: no counterweights
// within the bound do better on the angles used) agree. Their difference is the certified gap.
// A counterweight's own weight is left out (it does not shake the frame at constant speed).
#pragma once

#include <optional>
#include <vector>

#include "linkage/kinematics.h"

namespace linkage {

enum class BalanceMeasure { Fx, Fy, Force };  // |shaking fx|, |shaking fy|, |shaking force|

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
  double kgMm() const { return staticMoment.norm(); }
  double angleDeg() const;  // of u in the body's sketch frame
};

struct BalanceResult {
  Status status;  // BadModel naming the body or the option; the tracker's where it cannot turn
  std::vector<Counterweight> counterweights;
  double peakBefore = 0, peakBeforeDeg = 0;  // N, crank degrees
  double peakAfter = 0, peakAfterDeg = 0;
  double lowerBound = 0;  // the programme's optimum: the peak cannot go lower
  double gap() const { return peakAfter - lowerBound; }
  int exchanges = 0;  // rounds of the exchange
  int angles = 0;     // angles the last programme used
};

// k is not moved (copies of it are).
BalanceResult balanceShaking(const Kinematics& k, const BalanceOptions& opt);

// The counterweights as masses of their bodies: a point mass at the radius of the body's
// farthest drawn point from its pivot (20 mm when it has none), combined with the body's own.
void addCounterweights(Mechanism& m, const std::vector<Counterweight>& c);

// Under gravity a counterweight also weighs, which the balance leaves out (a static moment
// m u fixes its mass only with a radius): the exact peak of the measure over the cycle of k's
// mechanism with r's counterweights added as addCounterweights makes them (what `balance --out`
// writes shakes with this). r.peakAfter without gravity; nullopt with `why` when it cannot be
// found (the tracker's failure).
std::optional<double> peakWithWeight(const Kinematics& k, const BalanceOptions& opt,
                                     const BalanceResult& r, Status* why = nullptr);

}  // namespace linkage
