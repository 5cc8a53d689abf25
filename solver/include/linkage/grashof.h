// Grashof's classification of every four-bar loop of a mechanism: four bodies joined in a ring
// by four pins, each body's link being the distance between its two pins as drawn.
//
// A loop is read as a four-bar with a frame, an input, a coupler and an output: the frame is
// the loop's body that the mechanism's structure solves first (the ground when it is in the
// loop), the input is the frame's neighbour solved first (the crank, in a loop that holds it),
// the output its other neighbour. With s and l the shortest and longest links and p, q the
// others, s + l < p + q is Grashof: the shortest link turns fully relative to the others,
// which names the class (input shortest: crank-rocker; frame: double-crank; coupler: Grashof
// double-rocker; output: rocker-crank, the output turns fully while the input rocks);
// s + l > p + q: no link turns fully (non-Grashof double-rocker, or triple rocker); equal: a
// change point, where all four pins can come into line and the loop can change branch.
#pragma once

#include <array>
#include <vector>

#include "linkage/model.h"

namespace linkage {

enum class GrashofClass {
  CrankRocker,
  DoubleCrank,
  GrashofDoubleRocker,
  RockerCrank,
  NonGrashofDoubleRocker,
  ChangePoint,
};
// "crank-rocker", "double-crank", "double-rocker (Grashof)", "rocker-crank",
// "double-rocker (non-Grashof)", "change point".
const char* toString(GrashofClass c);

// |(s + l) - (p + q)| at most this times l is a change point: the drawing's coordinates carry
// rounding, and a loop that close to one behaves as one.
constexpr double kChangePointTolerance = 1e-9;

// Lengths in the order frame, input, coupler, output.
GrashofClass grashofClass(double frame, double input, double coupler, double output);

struct FourBarLoop {
  std::array<BodyId, 4> bodies;     // frame, input, coupler, output
  std::array<JointId, 4> joints;    // frame-input, input-coupler, coupler-output, output-frame
  std::array<double, 4> lengths{};  // frame, input, coupler, output (mm, between pins as drawn)
  GrashofClass kind = GrashofClass::ChangePoint;
  double margin = 0;  // (p + q) - (s + l), mm: positive Grashof, negative not
};

// Every four-bar loop, ordered by the frame and then the input as the structure solves them,
// then file order. Rings with a link of zero length (two of a body's pins at one place) are
// not four-bars and are left out.
std::vector<FourBarLoop> fourBarLoops(const Mechanism& m);

}  // namespace linkage
