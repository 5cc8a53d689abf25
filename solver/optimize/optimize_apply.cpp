// Dimensions set to values (linkage/optimize.h): the tolerances' exact finite changes
// (changeDimensions, linkage/dimension_change.h) by the differences from the design's values.
#include <algorithm>
#include <cmath>

#include "linkage/dimension_change.h"
#include "linkage/optimize.h"
#include "linkage/sensitivity.h"

namespace linkage {

namespace {

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// A side (P0-P1, P1-Pk, P0-Pk), whose value is a length and must stay positive: a change past 0
// would draw the body mirrored rather than fail.
bool isSide(const Dimension& d) {
  // A cam's rise is signed (a fall is a negative rise); its base and roller are lengths.
  if (d.camOf && endsWith(d.name, ".rise")) return false;
  return d.unit == Dimension::Unit::Mm && d.slots.empty() && !endsWith(d.name, ".x") &&
         !endsWith(d.name, ".y") && !endsWith(d.name, ".along") && !endsWith(d.name, ".across");
}

Status checked(const Dimension& d, double value) {
  if (!std::isfinite(value))
    return Status::badModel("'" + d.name + "': the value is not a finite number");
  if (isSide(d) && !(value > 0)) return Status::badModel("'" + d.name + "' must be positive");
  if (d.ratioOf && !(value != 0)) return Status::badModel("'" + d.name + "' cannot be 0");
  return Status::success();
}

}  // namespace

Status setDimensions(Mechanism& m, const std::vector<std::pair<std::string, double>>& values) {
  const std::vector<Dimension> dims = dimensions(m);
  std::vector<double> delta(dims.size(), 0.0);
  for (const auto& [named, value] : values) {
    const std::string& name = named;  // (a structured binding: clang cannot capture it)
    auto it =
        std::find_if(dims.begin(), dims.end(), [&](const Dimension& d) { return d.name == name; });
    if (it == dims.end()) return Status::badModel("no dimension '" + name + "' in the mechanism");
    if (Status s = checked(*it, value); !s.ok()) return s;
    delta[it - dims.begin()] = value - it->value;
  }
  Mechanism next = m;
  if (Status s = changeDimensions(next, dims, delta); !s.ok()) return s;
  // A slot turned about its first end has a new offset (measured from elsewhere): a second pass,
  // with no turn, gives each offset asked for its value exactly.
  const std::vector<Dimension> turned = dimensions(next);
  std::vector<double> again(turned.size(), 0.0);
  bool more = false;
  for (const auto& [name, value] : values)
    for (size_t k = 0; k < turned.size(); ++k)
      if (turned[k].name == name && endsWith(name, ".offset") && turned[k].value != value) {
        again[k] = value - turned[k].value;
        more = true;
      }
  if (more)
    if (Status s = changeDimensions(next, turned, again); !s.ok()) return s;
  m = std::move(next);
  return Status::success();
}

Status setDimension(Mechanism& m, const std::string& name, double value) {
  return setDimensions(m, {{name, value}});
}

}  // namespace linkage
