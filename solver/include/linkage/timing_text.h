// The parts of a machine's cycle diagram (linkage/model.h's Timing) as a user types them on the
// command line or in the editor, and as a file holds them:
//   an output   "body.point:y", "body.point:x", "body.point:DX,DY" (along that direction),
//               "body:angle"
//   a window    "NAME=OUTPUT<VALUE" or "NAME=OUTPUT>VALUE"
//   a clearance's part   "body.point", "body.P-Q" (the segment between two points of a body: a
//               needle, a blade), or "body.slot" (a point first when a body has both)
// Parsing is strict and locale-independent; a failure says which part is wrong and why.
// Writing gives the shortest text that reads back to the same numbers.
#pragma once

#include <optional>
#include <string>

#include "linkage/model.h"

namespace linkage {

std::optional<LimitMeasure> parseMeasure(const Mechanism& m, const std::string& text,
                                         std::string* why);
std::string measureText(const Mechanism& m, const LimitMeasure& x);

std::optional<TimingWindow> parseTimingWindow(const Mechanism& m, const std::string& text,
                                              std::string* why);
std::string windowText(const Mechanism& m, const TimingWindow& w);
// A window's name: not empty, none of ',', '+', ':', '<', '>', '=', '"', a space or a control
// character (they separate the parts of a window, a conflict, the command line's
// conflict:N1+N2 rows and the rows of a CSV table).
bool validWindowName(const std::string& name);

// One part of a clearance; nullopt with `why` when the text names none.
std::optional<ClearancePart> parseClearancePart(const Mechanism& m, const std::string& text,
                                                std::string* why);
// What is wrong with a clearance from `point` to `other` ("" when nothing is): ids m does not
// hold, a segment whose ends are on two bodies or in one place, a point to itself, or to a
// segment or slot of its own body.
std::string clearancePartProblem(const Mechanism& m, PointId point, const ClearancePart& other);

// What is wrong with the timing on m, with the place ("timing.windows[2]: ..."), or "" when
// nothing is: ids m does not hold, a window name given twice or not valid, a conflict naming a
// window that is not there or one window twice, a clearance clearancePartProblem refuses, a
// negative or non-finite minimum.
std::string timingProblem(const Mechanism& m, const Timing& t);

// The shortest decimal text of v that reads back as v ("0.1", "-150", "1e-07").
std::string shortestText(double v);

}  // namespace linkage
