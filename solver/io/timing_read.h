// Reading the optional "timing" field: what the machine's cycle diagram shows (its rows,
// windows, conflicts and clearances), in the text a user types (linkage/timing_text.h). Refused
// with the place named when a part does not parse or names what the mechanism does not have.
#pragma once

#include "io/json_read.h"

namespace linkage::json_read {

// Into m.timing; m's bodies, points and slots are read already.
void readTiming(const Json& v, const std::string& path, Mechanism& m);

}  // namespace linkage::json_read
