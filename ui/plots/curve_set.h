// The curves of one mechanism that the plots show: what a user asked for (by names, so that
// the same point can be found in another open document), sampled by the solver, with extremes,
// and a private copy of the solver that gives exact values at a cursor between samples.
#pragma once

#include <QString>
#include <array>
#include <memory>

#include "figures/units.h"
#include "linkage/extremes.h"
#include "linkage/motion_samples.h"
#include "linkage/spectrum.h"

namespace linkage::ui {

struct CurveRequest {
  QString target;  // "body.point", or a body's name for its rotation
  bool body = false;
  Quantity::Component component = Quantity::Component::Y;
  double directionDeg = 0;  // Along: counter-clockwise from +x
  double elevationDeg = 0;  // Along: above the x-y plane (a machine in space)
  QString other;            // Distance: the second point, "body.point"

  std::array<bool, kOrders> orders{true, true, true, false};
  int revs = 1;
  int steps = 360;  // per revolution
  bool operator==(const CurveRequest&) const = default;
  // How the labels name the component.
  ComponentName name() const { return {component, directionDeg, elevationDeg, other}; }
};

class CurveSet {
 public:
  // Resolves the request in k's mechanism and samples it (nothing when k is not solved or the
  // target is not there: status() says why). `solve` is what the last solve of the document's
  // design said: when it failed, k is the last design that could be solved, another one, and
  // there are no curves, its reason the status.
  CurveSet(const Kinematics& k, const CurveRequest& r, const QString& title,
           const Status& solve = Status::success());

  const QString& title() const { return title_; }
  // The frame a point's x and y are in, for the axis labels: "" in a planar machine; "world"
  // in a machine in space (x, y, z in the world, Kinematics::motionInSpace).
  const QString& frame() const { return frame_; }
  const CurveRequest& request() const { return request_; }
  // Ok; or why the curves stop early or are missing (the sweep's status, an unknown target).
  const Status& status() const { return status_; }
  bool empty() const { return samples_ == nullptr || samples_->size() == 0; }
  bool periodic() const { return samples_ && samples_->periodic; }
  // "disk angle [deg], clockwise" (crankAxisLabel, figures/units.h).
  const QString& crankLabel() const { return crankLabel_; }
  const Quantity& quantity() const { return quantity_; }

  // The order's curve (solver units); values are empty for an order not asked for or that
  // cannot be had (its status says why).
  const Curve& curve(Order o) const { return curves_[static_cast<int>(o)]; }
  const Extremes& extremes(Order o) const { return extremes_[static_cast<int>(o)]; }
  // The crank angles sampled: [0, last].
  double lastDeg() const;

  // Exact values at a crank angle within the sampled range (NaN outside it or for orders not
  // asked): the solver copy moves there. Jerk is the trigonometric interpolant of its samples.
  std::array<double, kOrders> valuesAt(double crankDeg);

  Spectrum harmonics(Order o, int maxK, Status* why) const;

 private:
  QString title_, crankLabel_, frame_;
  CurveRequest request_;
  Quantity quantity_;
  Status status_;
  std::shared_ptr<MotionSamples> samples_;
  std::array<Curve, kOrders> curves_;
  std::array<Extremes, kOrders> extremes_;
  std::array<double, kOrders> scales_{};  // of each order: next to it, a value is rounding
  std::unique_ptr<Kinematics> probe_;
  PeriodicInterpolant jerk_;
};

}  // namespace linkage::ui
