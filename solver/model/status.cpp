#include "linkage/status.h"

namespace linkage {

const char* toString(StatusCode c) {
  switch (c) {
    case StatusCode::Ok:
      return "ok";
    case StatusCode::BadModel:
      return "bad model";
    case StatusCode::Underconstrained:
      return "under-constrained";
    case StatusCode::Locked:
      return "locked";
    case StatusCode::Conflicting:
      return "conflicting joints";
    case StatusCode::AssemblyFailed:
      return "cannot assemble";
    case StatusCode::Unreachable:
      return "unreachable crank angle";
    case StatusCode::Singular:
      return "singular position";
    case StatusCode::NotConverged:
      return "not converged";
  }
  return "?";
}

}  // namespace linkage
