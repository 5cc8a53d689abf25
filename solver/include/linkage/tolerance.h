// Tolerances carried through the motion (issue 29): the band of a point's x and y (and z, on a
// machine in space) over the cycle, and the spread of its stroke, when the named dimensions
// (linkage/sensitivity.h) vary within symmetric tolerances +-T_k and pins have a radial play c.
//
// A machine in space (linkage/space.h) is carried in the world: its dimensions include depths,
// the ground's z, rods' lengths and planes' origins, its derivatives are Sensitivity's
// Space::World, each sample's design is drawn exactly (linkage/dimension_change.h), and the
// band is of the point's world x, y and z. Its stroke is still of y, the world's (the stroke's
// direction is not an option here). A play opens its pin in the pin's plane, its free point
// moved in its body's plane; one whose free point is on the ground (whose x and y are the
// world's, not the pin's plane's) is refused by name.
//
// First order, from the exact derivatives at each crank angle: worst case sum |d out/d p_k| T_k
// (a play counts c |d out/d offset|, the derivative's largest over the direction the pin's
// point may sit: c times the norm of the two columns, the point moved by x and by y); root sum
// of squares sqrt(sum (d out/d p_k T_k)^2) with a play's term c |d out/d offset|. The stroke's
// first order from the envelope theorem: the change of the largest y less that of the least, each
// at its own crank angle.
//
// Monte Carlo: each sample draws every dimension's change uniformly in [-T_k, T_k] and each
// play's offset uniformly over the disc of radius c (in the pin's body, held over the cycle),
// from its own seed (the run's seed and the sample's index), so that the results do not depend
// on the number of threads. The changed design (linkage/dimension_change.h) is solved exactly at
// each crank angle from the nominal's branches (Kinematics::edit); its stroke from its limit
// positions: each of the nominal's local extremes of y narrowed by Newton on the exact velocity
// and acceleration. A sample that does not assemble, cannot turn the crank fully or does not come
// back to where it started after a turn (it changed branch) is counted, not used.
//
// First order is not enough where the derivatives are unbounded (a singular position), and where
// the Monte Carlo band leaves the first-order worst case (which bounds every sample to first
// order) by more than 10 % of it, or the samples' mean or spread (standard deviation) differs
// from the first-order one (mean: the nominal; variance: sum (d out/d p_k T_k)^2 / 3 for uniform
// changes, c^2 |d out/d offset|^2 / 4 for a play) by more than 10 % of the first-order standard
// deviation and five standard errors: `nonlinearDeg` lists those crank angles. Samples that
// fail (a box of tolerances not all of which assemble or turn) are reported apart: the
// survivors are then a truncated sample, and first order is not to be trusted anywhere.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "linkage/kinematics.h"
#include "linkage/model.h"
#include "linkage/status.h"

namespace linkage {

struct ToleranceSpec {
  PointId point;
  struct Tol {
    std::string dimension;  // a name of dimensions(), or a pin "body.P-body.Q" for a play
    double plusMinus = 0;   // T (in the dimension's unit), or the play's radial clearance c (mm)
    bool play = false;
  };
  std::vector<Tol> tolerances;
  int steps = 360;  // crank angles 360 i / steps
  int samples = 0;  // Monte Carlo samples (0: first order only)
  std::uint64_t seed = 1;
  int threads = 0;     // 0: std::thread::hardware_concurrency()
  bool band = true;    // Monte Carlo at every crank angle (else the stroke alone)
  bool stroke = true;  // the stroke (extremes of y over the cycle)
  // The largest crank step of a sample's turn (KinematicsOptions::maxStepDeg): a sample is
  // solved exactly at every angle whatever it is; it only sets how often the tracker checks
  // that the turn stays on its branch (the nominal's 2 degrees: half the speed, the same
  // strokes to 1e-13 mm on the Wanzer needle and the same failures across a toggle in the tests).
  double sampleStepDeg = 5.0;
};

// x, y and z: a planar machine's x and y in the drawing, z 0 throughout; a machine in space's
// in the world.
struct ToleranceRow {
  double crankDeg = 0;
  Vec3 nominal = Vec3::Zero();
  bool firstOrder = false;  // the derivatives exist here (not a singular position)
  Vec3 worst = Vec3::Zero(), rss = Vec3::Zero();  // half-widths, mm
  Vec3 sigma = Vec3::Zero();                      // first order's standard deviation, mm
  // Monte Carlo over the samples that completed: extremes, mean, standard deviation.
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero(), mean = Vec3::Zero(), sd = Vec3::Zero();
  bool nonlinear = false;  // first order is not enough here
};

struct StrokeSpread {
  double nominal = 0, minDeg = 0, maxDeg = 0;  // the nominal stroke and its limit angles
  bool firstOrder = false;
  double worst = 0, rss = 0, sigma = 0;     // first order
  double lo = 0, hi = 0, mean = 0, sd = 0;  // Monte Carlo
  bool nonlinear = false;
};

struct ToleranceResult {
  // BadModel naming an unknown dimension or pin, a negative tolerance, a play in space on a
  // ground point; the nominal's failure.
  Status status;
  bool space = false;  // a machine in space (linkage/space.h): the rows' z is the world's
  std::vector<ToleranceRow> rows;
  StrokeSpread stroke;
  int samples = 0;           // drawn
  int used = 0;              // completed the cycle on the nominal's branch
  int failed = 0;            // samples - used
  std::string firstFailure;  // the first failed sample's index and reason
  // The crank angles between which failed samples stopped, the crank unable to turn on (NaN
  // when none did: they did not assemble, or none failed): where the toggle is. Survivors of a
  // box whose samples fail are a truncated sample: first order is not to be trusted anywhere.
  double stopLoDeg = NAN, stopHiDeg = NAN;
  std::vector<double> nonlinearDeg;  // the rows' crank angles where first order is not enough
};

ToleranceResult tolerances(const Mechanism& m, const ToleranceSpec& spec);

// The design of Monte Carlo sample `index` as tolerances() draws it for this spec and seed: to
// look at one sample again (and for tests to solve it independently).
Status toleranceSample(const Mechanism& m, const ToleranceSpec& spec, long long index,
                       Mechanism& out);

}  // namespace linkage
