// File > Export > Motion table: the document's motion table in the CSV of
// ../shared/specs/model-format.md, the same rows `linkage-cli analyze` writes (one code path:
// linkage/io/motion_table.h), from crank angle 0 on the assembly branch the document is on.
#pragma once

#include <QString>
#include <vector>

#include "linkage/model.h"

namespace linkage::ui {

class Document;

// Writes steps * revs + 1 rows (steps * revs must be whole) of `points`, or of the design's
// outputs when `points` is empty, atomically. A design that is not solved, no points, or a
// crank that cannot reach an angle of the sweep: false, `error` says why, and no file is written
// (a table that stops early is not the format's table).
bool exportMotionTable(const Document& doc, const QString& path, long long steps, double revs,
                       QString* error, const std::vector<PointId>& points = {});

}  // namespace linkage::ui
