// Reading the optional "mechanisms" field (../shared/specs/model-format.md): how the file names,
// colours and hides the machine's mechanisms, each known by its bodies.
#pragma once

#include "io/forces_read.h"

namespace linkage::json_read {

void readMechanismEntries(const Json& v, const std::string& path, Mechanism& m,
                          const BodyRef& body);

}  // namespace linkage::json_read
