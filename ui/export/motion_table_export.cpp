#include "export/motion_table_export.h"

#include "document/document.h"
#include "linkage/io/atomic_file.h"
#include "linkage/tables/motion_table.h"

namespace linkage::ui {

namespace {
bool fail(QString* error, const QString& text) {
  if (error) *error = text;
  return false;
}
}  // namespace

bool exportMotionTable(const Document& doc, const QString& path, long long steps, double revs,
                       QString* error, const std::vector<PointId>& points) {
  if (!doc.solved())
    return fail(error, QString("The design is not solved (%1): no motion table.")
                           .arg(QString::fromStdString(doc.solveStatus().message)));
  MotionTableSpec spec;
  spec.points = points.empty() ? doc.design().outputs : points;
  spec.steps = steps;
  spec.revs = revs;
  if (spec.points.empty())
    return fail(error, "The mechanism has no output points: mark the points to export.");
  if (motionTableRows(spec) < 0)
    return fail(error, "Steps per revolution times revolutions must be a whole number.");
  Kinematics k = doc.kinematics();  // a copy: the document's pose stays
  k.setAccelerations(true);         // the document has them off while no view shows them
  if (Status s = k.checkDetermined(spec.points); !s.ok())
    return fail(error, QString::fromStdString(s.message));
  std::string table;
  const Status s = sweepMotionTable(k, spec, [&table](const std::string& row) {
    table += row;
    table += '\n';
  });
  if (!s.ok())
    return fail(error,
                QString("%1: the table was not written.").arg(QString::fromStdString(s.message)));
  const WriteResult w = writeFileAtomically(path.toStdString(), table);
  if (!w.ok) return fail(error, QString::fromStdString(w.error));
  return true;
}

}  // namespace linkage::ui
