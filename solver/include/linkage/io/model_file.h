// Reading and writing mechanism files (.linkage.json), as specified in
// shared/specs/model-format.md. No JSON library appears here: it is a private dependency.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "linkage/io/atomic_file.h"
#include "linkage/model.h"

namespace linkage {

// Exactly one of the two is set.
struct LoadResult {
  std::optional<Mechanism> mechanism;
  std::string
      error;  // one line naming the place, e.g. `joints[2].slot: no slot "X" on body "disk"`
};

// Validates everything the format promises (references resolve, exactly one ground, finite
// numbers, ...) and returns either a whole Mechanism or the first problem found. Syntax errors read
// `line 3, column 5: <what>`; all other errors start with the JSON path of the offending value.
// Unknown fields are kept in the entities' Extras. Independent of the global locale.
LoadResult parseMechanism(std::string_view jsonText);

// As parseMechanism; every error, also an unreadable file, is prefixed with `<path>: `.
LoadResult loadMechanismFile(const std::string& path);

// Pretty JSON (2-space indent, [x, y] pairs on one line, trailing newline) with known keys in the
// order of the spec, then the unknown fields from Extras in their original order. Numbers are
// written in the shortest form that reads back to the same double. Extras that are not a JSON
// object, and extra keys that would collide with known ones, are left out so that the file stays
// loadable.
std::string serializeMechanism(const Mechanism& m);

// serializeMechanism written with writeFileAtomically.
WriteResult saveMechanismFile(const Mechanism& m, const std::string& path);

// "" when `a` and `b` describe the same file contents, else the first difference in words. Compares
// names, exact coordinates, references by name, the driver, outputs and Extras (as JSON values);
// ignores ids and the order of the flat points/slots vectors across bodies. For round-trip checks.
std::string mechanismDifference(const Mechanism& a, const Mechanism& b);

}  // namespace linkage
