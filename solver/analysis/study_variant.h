// One variant of a parameter study (linkage/study.h): the moved mechanism loaded afresh, swept
// over a turn of the crank, and measured, every measure's extremes found in one pass of a probe.
#pragma once

#include <vector>

#include "linkage/study.h"

namespace linkage {

StudyRow measureVariant(const Mechanism& moved, const StudySpec& spec, const Vec2& direction,
                        const std::vector<TransmissionJoint>& joints);

}  // namespace linkage
