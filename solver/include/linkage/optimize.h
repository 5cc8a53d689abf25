// Dimensions found for targets (issue 29): the named dimensions of linkage/sensitivity.h varied
// within bounds so that points meet targets (a stroke, a position at a crank angle, a path through
// given points, a transmission angle, the shaking force's peak), by NLopt: a multistart over the
// bounds (a fixed seed), each start a local gradient method (SLSQP) fed by the exact
// sensitivities chained through the targets. Or counterweights varied (their static moments) for
// the shaking force: a peak over the turn is a minimax, met as one (below, Evaluation::peaks).
//
// Every design tried is the base design with its variables set exactly (setDimension), solved
// from the base's pose at crank angle 0 on the same assembly branches (editAtPose, as an edit in
// the editor is), and tracked through a full turn of the crank. A design that does not assemble,
// or whose crank does not turn fully, is infeasible: the optimiser sees a penalty above every
// feasible value tried, never a NaN.
//
// On a machine in space (planes, docs/spatial.md) every dimension may vary (depths, ground z,
// ball rods' lengths, planes' origins too: changeDimensions sets them exactly), the gradient is
// the world's (Sensitivity::Space::World), and the targets are a stroke (along the world's +y,
// strokeDirection in linkage/stroke_sensitivity.h, or a direction given), a position and a path
// (world x, y and, if given, z), a window's end, a clearance, a reaction, a transmission angle
// (in its plane) and the shaking force or moment over dimensions or counterweights (each turning
// in its plane).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "linkage/balance.h"
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

// A variable is a dimension (by its name) or a counterweight added to a body pinned to the
// ground: `BODY.counterweight.x` and `BODY.counterweight.y`, its static moment (kg mm) in the
// body's drawing from its pivot (linkage/balance.h), 0 as drawn; its mass the least that gives
// it, at the body's reach R (|s| / R: its weight counts where gravity is on). Varied with
// dimensions, each design is drawn again at crank angle 0 and the moment, fixed in its body's
// drawing, turns with the body's turn there (its gradient counts it); a reaction over both is
// refused (a counterweight's share is not differentiated by a dimension yet).
struct OptVariable {
  std::string name;  // a dimension's or a counterweight's
  double lo = 0, hi = 0;
};

struct OptTarget {
  enum class Kind { Stroke, Position, Path, Transmission, Shaking, Clearance, Window, Force };
  Kind kind = Kind::Stroke;
  PointId point;
  double stroke = 0;        // Stroke: mm, along strokeDirection (linkage/stroke_sensitivity.h)
  double crankDeg = 0;      // Position: at this crank angle,
  Vec2 at = Vec2::Zero();   // the point here (world mm)
  std::optional<double> z;  // and, on a machine in space, at this world z (none: x, y only)
  std::vector<Vec2> path;   // Path: world mm
  // Transmission: the angle (transmissionJoints(m)[joint], linkage/transmission.h; a dyad's, a
  // rod's on a slider or in a slot) kept within limitDeg to 180 - limitDeg over the turn:
  // residuals max(0, limit - min) and max(0, max - (180 - limit)), degrees (a rod's is at most
  // 90: only its lower limit binds).
  size_t joint = 0;
  double limitDeg = 0;
  // Shaking: the peak over the turn of |fx|, |fy| or |f| of the shaking force (linkage/
  // dynamics.h shaking(), with the counterweights varied) at most limitN: residual
  // max(0, peak - limitN), N; limitN 0 minimises the peak. A planar machine's.
  // With `moment`, the shaking moment's |M| about the drawing's origin (N m, linkage/dynamics.h
  // shaking()) instead, with the counterweights' moments: a planar machine's.
  BalanceMeasure measure = BalanceMeasure::Force;
  bool moment = false;
  double limitN = 0;
  // Force: the peak over the turn of joint m.joints[index]'s reaction |f| (linkage/dynamics.h,
  // on the body of its first point) at most limitN, as Shaking's (measure Force). Over
  // dimensions or counterweights (their shares: linkage/force_sensitivity.h). On a machine in
  // space a body's bearing's load out of its plane instead (`reaction`): |fn| (N) or the tilts'
  // |(mx, my)| (limitN in N m), as well over dimensions or counterweights.
  enum class Reaction { InPlane, Normal, Tilt };
  Reaction reaction = Reaction::InPlane;
  // Clearance: the file's watched clearance `index` (its timing's, counted from 0) at least
  // gapMm at its closest approach over the turn: residual max(0, gapMm - least), mm.
  size_t index = 0;
  double gapMm = 0;
  // Window: the file's timing window `window` (a point's, a body's angle, a distance), its first
  // interval's start (its end with windowEnd) at crankDeg: residual the angle from crankDeg to it,
  // degrees
  // (-180 to 180). A design where it never opens is infeasible.
  std::string window;
  bool windowEnd = false;
  double weight = 1;
  // Stroke: along this direction in the world instead (any length; a planar machine's z 0):
  // `@x`, `@z`, `@DX,DY,DZ` in the target's text (linkage/optimize_text.h).
  std::optional<Vec3> direction;
  // Path: on a machine in space, each given point's world z (a file of x,y,z lines); empty: the
  // distances are in the world's x, y only (as a position without z).
  std::vector<double> pathZ;
};

// What a target measures, for people: Stroke {stroke}, Position {x, y} ({x, y, z} with a z), Path
// {rms distance, largest distance} (mm), Transmission {min, max} (degrees), Shaking {peak (N), its
// crank angle}, Clearance {least (mm), its crank angle}, Window {the end's crank angle}, Force
// {peak (N), its crank angle}.
using Measure = std::vector<double>;

struct OptimizeSpec {
  std::vector<OptVariable> variables;
  std::vector<OptTarget> targets;
  int starts = 16;  // the first from the design as it is (clamped into the bounds)
  std::uint64_t seed = 1;
  int steps = 360;           // samples per turn for the extremes and the path's nearest points
  int maxEvaluations = 300;  // per start
  int threads = 0;           // the starts run on this many (0: every core); the same answer
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
  // A peak target's part: the turn cut into intervals, each interval's largest value less the
  // limit (a row) and its exact gradient (at the angle where it is reached: the envelope
  // theorem). The objective holds weight * max(0, largest row)^2 (peakObjective), the gradient
  // that term's where one row is the largest (peakGradient); the search takes the rows instead:
  // minimise weight * t^2 with every row <= t, smooth where the peak's is not.
  struct PeakRows {
    size_t target = 0;
    std::vector<double> value;
    std::vector<std::vector<double>> gradient;  // by row, by variable
  };
  std::vector<PeakRows> peaks;
  double peakObjective = 0;
  std::vector<double> peakGradient;
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
  std::vector<Counterweight> counterweights;  // those varied, as added to `design`
};

// base: the design, loaded and at crank angle 0.
OptimizeResult optimize(const Kinematics& base, const OptimizeSpec& spec);

}  // namespace linkage
