// The forces panel's Export Table: the document's force table in the CSV of `linkage-cli
// dynamics` (docs/dynamics.md), the rows written by the same functions
// (linkage/tables/force_table.h) from the same solve, so that the two files are byte-equal.
#pragma once

#include <QString>

namespace linkage::ui {

class Document;

// steps * revs + 1 rows (crank 0 to 360 revs) at the driver's speed, from crank 0 on the
// assembly branch the document is on, written atomically. A design not solved, a motion not
// determined, or a crank angle the mechanism cannot reach: false, `error` says why and no file
// is written (a table that stops early is not the whole table). Reactions the joints do not
// determine are left empty, as the command line leaves them.
bool exportForceTable(const Document& doc, const QString& path, long long steps, double revs,
                      QString* error);

}  // namespace linkage::ui
