#include "forces/force_table_export.h"

#include <cmath>

#include "document/document.h"
#include "linkage/dynamics.h"
#include "linkage/io/atomic_file.h"
#include "linkage/tables/force_table.h"

namespace linkage::ui {

namespace {
bool fail(QString* error, const QString& text) {
  if (error) *error = text;
  return false;
}
}  // namespace

bool exportForceTable(const Document& doc, const QString& path, long long steps, double revs,
                      QString* error) {
  if (!doc.solved())
    return fail(error, QString("The design is not solved (%1): no force table.")
                           .arg(QString::fromStdString(doc.solveStatus().message)));
  if (Status s = doc.motionStatus(); !s.ok())
    return fail(error, QString("No force table: %1.").arg(QString::fromStdString(s.message)));
  const double rowsD = static_cast<double>(steps) * revs;
  if (steps < 1 || !(revs > 0) || std::abs(rowsD - std::round(rowsD)) > 1e-9 * rowsD || rowsD > 5e7)
    return fail(error, "Steps per revolution times revolutions must be a whole number.");
  Kinematics k = doc.kinematics();  // a copy: the document's pose stays
  k.setAccelerations(true);
  ForceSolver solver;
  if (Status s = solver.prepare(k); !s.ok()) return fail(error, QString::fromStdString(s.message));
  const Mechanism& m = k.mechanism();
  const std::vector<char> undetermined = undeterminedJoints(m, solver.result().undetermined);
  std::string table = forceTableHeader(m) + "\n";
  const long long rows = std::llround(rowsD);
  for (long long i = 0; i <= rows; ++i) {
    const double deg = 360.0 * static_cast<double>(i) / static_cast<double>(steps);
    Status s = k.moveTo(deg);
    const Forces& f = solver.compute(k);
    if (s.ok()) s = f.status;
    if (!s.ok())
      return fail(error,
                  QString("%1: the table was not written.").arg(QString::fromStdString(s.message)));
    table += forceTableRow(m, f, deg / 360 * 60 / k.rpm(), deg, undetermined) + "\n";
  }
  const WriteResult w = writeFileAtomically(path.toStdString(), table);
  if (!w.ok) return fail(error, QString::fromStdString(w.error));
  return true;
}

}  // namespace linkage::ui
