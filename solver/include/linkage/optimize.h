// Dimensions found for targets (issue 29): the named dimensions of linkage/sensitivity.h varied
// within bounds so that points meet targets (a stroke, a position at a crank angle, a path through
// given points), by NLopt: a multistart over the bounds (a fixed seed), each start a local
// gradient method (SLSQP) fed by the exact sensitivities chained through the targets.
//
// Every design tried is the base design with its variables set exactly (setDimension), solved
// from the base's pose at crank angle 0 on the same assembly branches (editAtPose, as an edit in
// the editor is), and tracked through a full turn of the crank. A design that does not assemble,
// or whose crank does not turn fully, is infeasible: the optimiser sees a penalty above every
// feasible value tried, never a NaN.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "linkage/kinematics.h"
#include "linkage/model.h"
#include "linkage/status.h"

namespace linkage {

// Sets dimension `name` (as dimensions() names it) of m's drawing to `value` exactly, by
// changeDimensions (linkage/dimension_change.h): it moves what that dimension moves (a body's
// points in its own frame, its other dimensions kept; a ground point; a straight slot; a gear's
// ratio) and nothing pinned to it: the joints are closed again by the solve. BadModel, m
// unchanged, for a name m does not have, a value that is not finite, a length not positive, or
// lengths that do not make a triangle.
Status setDimension(Mechanism& m, const std::string& name, double value);
// Several at once: a body is drawn again from all its dimensions together, so that the order does
// not matter; a slot's angle and offset both read back as given.
Status setDimensions(Mechanism& m, const std::vector<std::pair<std::string, double>>& values);

struct OptVariable {
  std::string name;  // a dimension's name
  double lo = 0, hi = 0;
};

struct OptTarget {
  enum class Kind { Stroke, Position, Path, Transmission };
  Kind kind = Kind::Stroke;
  PointId point;
  double stroke = 0;       // Stroke: mm, along defaultDirection (linkage/limits.h)
  double crankDeg = 0;     // Position: at this crank angle,
  Vec2 at = Vec2::Zero();  // the point here (world mm)
  std::vector<Vec2> path;  // Path: world mm
  // Transmission: the dyad's angle (transmissionJoints(m)[joint], linkage/transmission.h) kept
  // within limitDeg to 180 - limitDeg over the turn: residuals max(0, limit - min) and
  // max(0, max - (180 - limit)), degrees. Dyads whose lines run between points only (not an
  // arc slot's radius).
  size_t joint = 0;
  double limitDeg = 0;
  double weight = 1;
};

// What a target measures, for people: Stroke {stroke}, Position {x, y}, Path {rms distance,
// largest distance} (mm), Transmission {min, max} (degrees).
using Measure = std::vector<double>;

struct OptimizeSpec {
  std::vector<OptVariable> variables;
  std::vector<OptTarget> targets;
  int starts = 16;  // the first from the design as it is (clamped into the bounds)
  std::uint64_t seed = 1;
  int steps = 360;           // samples per turn for the extremes and the path's nearest points
  int maxEvaluations = 300;  // per start
  double sameBest = 1e-9;    // mm^2: a start found the best within this (+ 1e-6 of it)
};

// One design tried. Objective: the weighted sum of squares of the targets' residuals (stroke -
// target; position - target, both coordinates; for a path, each given point's distance to the
// nearest point of the curve over the turn).
struct Evaluation {
  bool feasible = false;
  std::string why;  // when not feasible
  double objective = 0;
  std::vector<double> gradient;   // d objective / d variable
  std::vector<Measure> measures;  // by target
};

Evaluation evaluate(const Kinematics& base, const OptimizeSpec& spec, const std::vector<double>& x,
                    bool withGradient = true);

struct OptimizeResult {
  Status status;  // BadModel for a spec that cannot run (an unknown variable, empty bounds, ...)
  std::vector<double> before, after;  // the variables' values
  Evaluation atBefore, atAfter;
  int starts = 0, infeasibleStarts = 0, foundBest = 0;
  int evaluations = 0;
  Mechanism design;  // the optimised design, redrawn so that its drawing closes
};

// base: the design, loaded and at crank angle 0.
OptimizeResult optimize(const Kinematics& base, const OptimizeSpec& spec);

}  // namespace linkage
