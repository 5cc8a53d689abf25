// Parameter studies: one dimension of a mechanism varied over a range, the design measured at
// every value (the paper of seed 001 moves the fixed pivot F on an arc, alpha from 0 to 35
// degrees, and watches the needle's stroke, its lowest position and the transmission angles).
//
// What varies is a point of a body, moved along a line or on an arc about a centre, scaled by
// a parameter t. A point is a design point: moving it moves every point pinned to it where they
// are drawn together (the ground's pivot F and the rocker's point F pinned there move as one),
// so the joint stays closed and the drawing stays assembled; the bodies' other points stay, so
// the links that end there change length. Points held in slots are not carried (a slot holds a
// point on a line, not at a place).
//
// Every variant is a fresh load of the moved mechanism, so a row is what a separate run on the
// moved model file gives; variants run in parallel, one solver per thread (the one pool of
// threads for studies: an editor runs runStudy on a thread of its own and watches it through
// StudyControl).
#pragma once

#include <atomic>
#include <functional>
#include <optional>
#include <vector>

#include "linkage/kinematics.h"
#include "linkage/limits.h"
#include "linkage/transmission.h"

namespace linkage {

struct PointMove {
  PointId point;
  enum class Kind { Line, Arc } kind = Kind::Line;
  Vec2 by = Vec2::Zero();      // Line: moved by t * by (mm)
  Vec2 centre = Vec2::Zero();  // Arc: turned about centre by t * angleDeg (counter-clockwise)
  double angleDeg = 0;
};

// The points a move of p carries: p and every point pinned to it, directly or through others,
// drawn at the same place (within 1e-9 of the drawing's size), in the mechanism's order.
std::vector<PointId> movedTogether(const Mechanism& m, PointId p);

// m with the move applied at t (to every point movedTogether carries). BadModel, and m
// unchanged, when the point is not m's or a number is not finite.
Status movePoint(Mechanism& m, const PointMove& move, double t);

struct StudySpec {
  PointMove move;
  double from = 0, to = 1;
  int values = 11;                // t = from + (to - from) i / (values - 1), i = 0 .. values - 1
  PointId point;                  // whose stroke, extremes, peak speed and acceleration
  std::optional<Vec2> direction;  // of the stroke; default: defaultDirection (limits.h)
  std::vector<BodyId> bodies;     // whose swings
  int steps = 360;                // samples per turn of the crank (at least 4)
  int threads = 0;                // 0: one per core
  // Keep each variant's path of the point (what an editor overlays to compare the designs).
  bool keepPaths = false;
};

struct StudyRow {
  double t = 0;
  // Ok, or why this variant has no measures: it does not load (the drawing cannot be
  // assembled, ...) or the crank does not turn fully (Unreachable or Singular, with where).
  Status status;
  bool turns = false;             // the crank turns fully
  std::optional<double> lockDeg;  // where the crank stops, from the drawing forwards
  Limits point;                   // the point along the direction
  double peakSpeed = 0;           // largest |v| of the point at the samples, mm/s
  double peakAccel = 0;           // largest |a|, mm/s^2
  std::vector<Limits> bodies;     // swings, in the order of StudySpec::bodies
  std::vector<TransmissionSummary> transmission;  // extremes, min and max (no stretches)
  // With keepPaths: the point's position at crank angles 360 i / steps, as far as the crank
  // turned.
  std::vector<Vec2> path;
};

struct Study {
  Status status;  // BadModel for a spec that cannot run (the rows are then empty)
  std::vector<TransmissionJoint> joints;  // of the mechanism (the same in every variant)
  std::vector<StudyRow> rows;             // in t order: every value's, or those computed
  bool cancelled = false;                 // stopped before every value had its row
  int threads = 1;                        // the threads that ran
};

// How a caller off the run's threads follows and stops it: `progress` after each variant (on
// the thread that computed it, any of the pool's), `cancel` read before each variant is taken:
// the variants under way finish, no other starts, and the rows computed are kept.
struct StudyControl {
  std::function<void(int done, int total)> progress;
  const std::atomic<bool>* cancel = nullptr;
};

Study runStudy(const Mechanism& m, const StudySpec& spec, const StudyControl& control = {});

}  // namespace linkage
