// The table of a parameter study (linkage/study.h), as `linkage-cli study` writes it and the
// editor's study dialog shows and exports it: one column per measure, named as in
// docs/design-checks.md (t, turns, lock_deg, <point>.min_mm, ..., <body>.swing_deg,
// mu:<a>.min_deg, mu:<a>.max_deg), one row per value of t. A measure a row does not have (the
// crank does not turn fully, the variant does not load) is empty.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "linkage/study.h"

namespace linkage {

// The columns' names, for a study of `spec` on m that answered s.
std::vector<std::string> studyColumns(const Mechanism& m, const StudySpec& spec, const Study& s);

// A row's values in the order of studyColumns (turns as 1 or 0).
std::vector<std::optional<double>> studyValues(const StudySpec& spec, const Study& s,
                                               const StudyRow& r);

// The CSV text: the header line, then one line per row (17 significant digits).
std::string studyTableCsv(const Mechanism& m, const StudySpec& spec, const Study& s);

}  // namespace linkage
