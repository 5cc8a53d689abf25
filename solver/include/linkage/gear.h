// The gear's number, for the code that shows or sets it (the editor's ratio field, tests): a
// gear keeps its ratio as its first number (its field "ratio": elements/gear.cpp).
#pragma once

#include "linkage/model.h"

namespace linkage {

inline double gearRatio(const Joint& j) {
  return j.number(0);
}
inline void setGearRatio(Joint& j, double ratio) {
  j.numbers.assign(1, ratio);
}

}  // namespace linkage
