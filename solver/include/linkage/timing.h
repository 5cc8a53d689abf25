// The cycle (timing) diagram of a machine: outputs followed over one machine cycle (crank angle
// 0 to 360 of the driver, the main shaft), their events, and windows (the crank angles where a
// condition on an output holds) with the conflicts between windows that must not overlap.
//
// Every event is found by root finding on the exact motion (analysis/crank_roots.h: brackets
// on samples of the exact value and derivative, safeguarded Newton to 1e-9 degree of crank):
// extremes (dead centres) are roots of the output's velocity; crossings of a level are roots of
// value - level (Newton on the velocity); a dwell is where the output's speed stays below a
// threshold for at least a given angle, its ends roots of velocity -+ threshold (Newton on the
// acceleration).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "linkage/limits.h"

namespace linkage {

// An output: a point's position along a direction (mm) or a body's angle (degrees from the
// drawing, counter-clockwise, whole turns counted): linkage/limits.h's LimitMeasure, named as a
// user wrote it ("needlebar.N:y", "feeddog.T:1,0", "hook:angle").
struct CycleOutput {
  std::string name;
  LimitMeasure measure;
};

// A window: where the output is below (or above) a level.
struct CycleWindow {
  std::string name;
  CycleOutput output;
  bool below = true;  // value < level; else value > level
  double level = 0;
};

// Crank angles from `fromDeg` in [0, 360) to `toDeg` > fromDeg, past 360 when it wraps.
struct AngleInterval {
  double fromDeg = 0, toDeg = 0;
};

struct Crossing {
  double crankDeg = 0;
  double level = 0;
  bool rising = false;
};

// One row of the diagram.
struct CycleRow {
  CycleOutput output;
  std::vector<double> crankDeg, value;  // the samples
  std::vector<double> normalised;       // (value - min) / (max - min); 0 when it does not move
  double min = 0, max = 0;              // over the cycle, exact
  std::vector<LocalExtreme> extremes;   // dead centres, crank order
  std::vector<AngleInterval> dwells;    // crank order of their start
  std::vector<Crossing> crossings;      // of its windows' levels, crank order
  bool periodic = true;                 // the output repeats after one turn
};

struct WindowIntervals {
  std::string name;
  std::vector<AngleInterval> intervals;  // in order of their start
};

struct Conflict {
  std::string first, second;
  std::vector<AngleInterval> overlaps;  // in order of their start; empty: no conflict
};

struct CycleDiagram {
  // BadModel (an output the mechanism does not have, a conflict naming an unknown window),
  // Underconstrained, or the solver's status where the crank cannot turn fully.
  Status status;
  std::vector<CycleRow> rows;            // one per distinct output, first use first
  std::vector<WindowIntervals> windows;  // in the order given
  std::vector<Conflict> conflicts;       // in the order given
  bool anyConflict() const;
};

struct CycleOptions {
  int steps = 360;  // sampling intervals over the cycle that bracket the events (at least 4)
  // A dwell: speed below dwellSpeed (the output's unit per degree of crank; 0: a ten-thousandth
  // of its range over the samples per degree, about 1 % of a slider-crank's peak speed) for at
  // least dwellMinDeg degrees of crank.
  double dwellSpeed = 0;
  double dwellMinDeg = 10;
};

// Over crank angles 0 to 360 on a copy of k (k does not move). `outputs` are rows of their own
// (the windows' outputs are rows too); `conflicts` are pairs of window names.
CycleDiagram cycleDiagram(const Kinematics& k, const std::vector<CycleOutput>& outputs,
                          const std::vector<CycleWindow>& windows,
                          const std::vector<std::pair<std::string, std::string>>& conflicts,
                          const CycleOptions& opt = {});

// The diagram of the timing a document keeps (linkage/model.h's Timing: its outputs, windows
// and conflicts; each output named as linkage/timing_text.h writes it). Its clearances are
// linkage/clearance.h's.
CycleDiagram cycleDiagram(const Kinematics& k, const Timing& t, const CycleOptions& opt = {});

// "body.point:y", "body.point:x", "body.point:DX,DY", "body:angle"; nullopt with `why` (which
// part is wrong and why) otherwise.
std::optional<CycleOutput> parseOutput(const Mechanism& m, const std::string& text,
                                       std::string* why);
// "NAME=OUTPUT<VALUE" or "NAME=OUTPUT>VALUE"; NAME without '=', ',', '+' or spaces.
std::optional<CycleWindow> parseWindow(const Mechanism& m, const std::string& text,
                                       std::string* why);

// The overlaps of two sets of intervals on the cycle (each in order of its start, wrapping
// past 360 allowed); `periodic` joins an overlap that ends at 360 to one that starts at 0.
std::vector<AngleInterval> overlapOf(const std::vector<AngleInterval>& a,
                                     const std::vector<AngleInterval>& b, bool periodic);

}  // namespace linkage
