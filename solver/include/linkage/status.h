// What a solver call returns: a code plus what a person needs to act on it (which joint, which
// body, which crank angle, why). Solver calls never throw for a mechanism's problems.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "linkage/model.h"

namespace linkage {

enum class StatusCode {
  Ok,
  BadModel,          // a reference or value the solver cannot use (e.g. no driver)
  Underconstrained,  // the driver does not determine the motion of some body
  Locked,            // the driver cannot turn: the mechanism is a structure
  Conflicting,       // joints that cannot all hold
  AssemblyFailed,    // the sketch cannot be closed
  Unreachable,       // a crank angle the mechanism cannot reach (limit position)
  Singular,          // a singular position: velocities not determined there
  NotConverged,      // the position solve failed for another reason
};

const char* toString(StatusCode c);

// How far a joint is from holding, in mm (a slider's angle as the arc it makes over the size of
// the mechanism); the joint id is none for the driver.
struct JointGap {
  JointId joint;
  double gap = 0;
};

struct Status {
  StatusCode code = StatusCode::Ok;
  std::string message;                   // one sentence, names the place and the cause
  std::optional<double> crankDeg;        // where it happened, when it is about a crank angle
  std::optional<double> lastReachedDeg;  // Unreachable: the last crank angle that was solved
  std::vector<JointId> joints;           // the joints involved
  std::vector<BodyId> bodies;            // the bodies involved
  std::vector<JointGap> gaps;            // AssemblyFailed, Conflicting: the joints left open

  bool ok() const { return code == StatusCode::Ok; }
  static Status success() { return {}; }
  static Status failure(StatusCode c, std::string msg) {
    Status s;
    s.code = c;
    s.message = std::move(msg);
    return s;
  }
  static Status badModel(std::string msg) { return failure(StatusCode::BadModel, std::move(msg)); }
};

}  // namespace linkage
