// The Python module's model (app/python/module.cpp binds it): one mechanism file, its design and
// its solver, with the command line's answers as numbers rather than text. No Python here: the
// binding turns the errors below into Python exceptions and the vectors into numpy arrays.
//
// Every query starts from the design loaded afresh at crank angle 0 and tracks from there, as a
// `linkage-cli` command does on the saved file: an answer does not depend on the queries before
// it, and a motion table is the command line's to the last bit.
#pragma once

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "linkage/dynamics.h"
#include "linkage/instant_centres.h"
#include "linkage/kinematics.h"
#include "linkage/model.h"
#include "linkage/optimize.h"

namespace linkage::py {

// Bad input: a file, a name, an option, a mechanism the driver cannot move (the command line's
// exit 2). Python: ValueError.
struct BadInput : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};
// A crank angle the mechanism cannot reach, or a singular position (the command line's exit 3).
// Python: linkage.MotionError (a RuntimeError).
struct MotionFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Throws the exception that fits a failed status (nothing when it is Ok).
void raise(const Status& s);

// The examples' names, found as Model::open finds them.
std::vector<std::string> examples(const std::string& modulePath);

// A table of doubles, row by row, with its column names.
struct Table {
  std::vector<std::string> columns;
  std::vector<double> values;  // rows * columns.size()
  size_t rows() const { return columns.empty() ? 0 : values.size() / columns.size(); }
};

class Model {
 public:
  // A path or an example's name, resolved as the command line resolves it; BadInput with the
  // reader's message (naming the place) otherwise. `modulePath` finds installed examples.
  static Model open(const std::string& nameOrPath, const std::string& modulePath);

  const Mechanism& design() const { return design_; }
  std::string source() const { return source_; }
  std::vector<std::string> points() const;  // "body.point", file order
  std::vector<std::string> bodies() const;

  // `linkage-cli analyze MODEL --steps N --revs R [--rpm RPM] --point P...` as numbers. A crank
  // angle it cannot reach: MotionFailure naming it (the rows before it are not returned).
  Table analyze(long long steps, double revs, double rpm,
                const std::vector<std::string>& points) const;
  // The motion table's column names for these points (none: the file's outputs).
  std::vector<std::string> columns(const std::vector<std::string>& points) const;
  // P, V, A of one point at many crank angles (deg), in the order given, tracked from one to
  // the next: n rows of sweepColumns() values, analyze's columns of that point (x, y, vx, vy,
  // ax, ay; in space x, y, z, vx, vy, vz, ax, ay, az in the world). What a fast loop in Python
  // calls once.
  int sweepColumns() const;
  void sweep(const std::string& point, const double* angles, size_t n, double rpm,
             double* out) const;
  InstantCentres instantCentres(double crankDeg) const;
  Forces forces(double crankDeg, double rpm) const;
  // d(position of the point)/d(dimension) at the crank angle, by dimension (linkage/
  // sensitivity.h's names, file order); `quantity` 0 position, 1 velocity, 2 acceleration (at
  // rpm, 0 the file's). In the world: (x, y, z), a planar machine's z 0.
  std::vector<std::pair<std::string, Vec3>> sensitivity(const std::string& point, double crankDeg,
                                                        int quantity, double rpm) const;
  // d(stroke)/d(dimension) (linkage/stroke_sensitivity.h): along the point's default direction.
  // Along the point's default direction, or `direction` (x, y, z or DX,DY[,DZ]).
  std::vector<std::pair<std::string, double>> strokeSensitivity(
      const std::string& point, const std::string& direction = "") const;
  // d(shaking force)/d(dimension) at the crank angle and rpm (linkage/shaking_sensitivity.h):
  // (dfx, dfy), on a machine in space the world's (dfx, dfy, dfz).
  std::vector<std::pair<std::string, std::vector<double>>> shakingSensitivity(double crankDeg,
                                                                              double rpm) const;
  // d(a joint's reaction)/d(dimension) (linkage/force_sensitivity.h), the joint named as
  // linkage-cli dynamics names it (pin:crank.A): a value a column of its kind there.
  std::vector<std::pair<std::string, std::vector<double>>> forceSensitivity(
      const std::string& joint, double crankDeg, double rpm) const;
  // Every dimension's name and value as drawn (mm, degrees or a ratio).
  std::vector<std::pair<std::string, double>> dimensions() const;

  // Edits, as the editor types them (linkage/edits.h): the design redrawn so that it closes;
  // refused (BadInput with the reason, nothing changed) where it cannot be solved.
  void setSideLengths(const std::string& body, const std::vector<double>& lengths);
  std::vector<double> sideLengths(const std::string& body) const;
  void setPoint(const std::string& point, double x, double y);
  void setDimension(const std::string& name, double value);
  // The editor's writer, atomically.
  void save(const std::string& path) const;

  // linkage-cli optimize's search (linkage/optimize.h): variables with their bounds, targets in
  // its --target syntax; with `apply`, the design becomes the one found. BadInput naming the
  // variable or target, or why no start could run.
  struct Optimized {
    OptimizeResult result;
    std::vector<std::string> targetNames;
  };
  struct Bounds {
    std::string name;
    double lo = 0, hi = 0;
  };
  Optimized optimize(const std::vector<Bounds>& vary, const std::vector<std::string>& targets,
                     int starts, std::uint64_t seed, int steps, bool apply);

  const Kinematics& loaded() const { return base_; }

 private:
  Kinematics at(double crankDeg, double rpm = 0) const;  // a fresh copy moved there
  PointId pointNamed(const std::string& label) const;
  std::vector<PointId> outputPoints(const std::vector<std::string>& names) const;
  BodyId bodyNamed(const std::string& name) const;
  void commit(Mechanism next);

  std::string source_;
  Mechanism design_;
  Kinematics base_;  // design_ loaded, at crank angle 0
};

}  // namespace linkage::py
