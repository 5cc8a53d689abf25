// Find Dimensions' targets (issue 29, "Dimensions found for targets"): a table whose rows are
// the optimiser's targets of every kind (linkage/optimize.h OptTarget), each with what it is of
// (a point; a dyad as `linkage-cli transmission` names it; fx, fy or the force; the file's
// watched clearances by their parts as the file names them; its timing windows' ends), its value, a
// crank angle where one is needed, and its weight; read with a message naming the row and the
// fault; and each target's measures in words with their units, for the result table.
#pragma once

#include <QStringList>
#include <QTableWidget>
#include <vector>

#include "linkage/optimize.h"

namespace linkage::ui {

class Document;

class OptimizeTargets : public QTableWidget {
  Q_OBJECT

 public:
  enum Column { Kind, Of, Value, Crank, Weight };
  explicit OptimizeTargets(Document* doc, QWidget* parent = nullptr);

  // A row of this kind for `of` (as its list names it: "needlebar.B", "mu:link.E", "fx",
  // "hook.K – needlebar.N", "needle.start"); false where the list has no such entry. value: mm,
  // "x, y", a CSV file, degrees or N, as the kind reads it.
  bool addRow(OptTarget::Kind kind, const QString& of, const QString& value, double crankDeg = 0,
              double weight = 1);
  // The row's kind changed: its list of what it can be of, and a value to type over.
  void setKind(int row, OptTarget::Kind kind);
  // The design changed: every row's list again, keeping what was chosen by its name.
  void refreshChoices();
  // The targets; false with `why` naming the row and its fault. A path's CSV is read here (the
  // command line's format, linkage/optimize_text.h).
  bool read(std::vector<OptTarget>& out, QString* why) const;
  QStringList probeLines() const;

 private:
  OptTarget::Kind kindOf(int row) const;
  QString defaultValue(OptTarget::Kind kind, const QString& of) const;
  bool readRow(int row, OptTarget& t, QString* why) const;

  Document* doc_;
};

// One row of the result table: a measure in words with its unit, before and after, and what
// it is asked to be.
struct MeasureRow {
  QString what;
  double before = 0, after = 0;
  QString target;
};
std::vector<MeasureRow> measureRows(const Mechanism& m, const OptTarget& t, const Measure& before,
                                    const Measure& after);

}  // namespace linkage::ui
