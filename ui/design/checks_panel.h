// The design-checks dock: what a designer checks on a linkage (seed 001), for the document's
// design, from the solver's API:
// - Grashof: every four-bar loop, its links (frame, input, coupler, output, mm) and class, with
//   the margin to a change point (fourBarLoops);
// - transmission angles: each joint's minimum and maximum over a turn with their crank angles,
//   and the stretches outside the band, which is set here (remembered) and shared with the
//   canvas's arcs (sweepTransmission);
// - limit positions: every extreme of a point along a direction (default: its slot's, else +y)
//   or of a body's angle, with the crank angles and the stroke (findLimits); the same subject
//   as the canvas's extreme positions.
// Double-clicking a value turns the crank to where it occurs. Values follow edits: recomputed
// at once when the design, the band or the subject changes, only while the panel is seen
// (docks/dock_panel.h); unseen, an edit only marks it stale. Each number's exact value is in
// its cell's Qt::UserRole, the crank angle it occurs at in CrankRole.
#pragma once

#include <QPointer>

#include "docks/dock_panel.h"

class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QHBoxLayout;
class QLabel;
class QLineEdit;
class QTableWidget;

namespace linkage::ui {

class DesignChoices;
class Document;

class ChecksPanel : public DockPanel {
  Q_OBJECT

 public:
  static constexpr int CrankRole = Qt::UserRole + 1;

  explicit ChecksPanel(DesignChoices* choices, QWidget* parent = nullptr);
  void setDocument(Document* doc);
  QTableWidget* grashofTable() const { return grashof_; }
  QTableWidget* transmissionTable() const { return transmission_; }
  QTableWidget* limitsTable() const { return limits_; }
  QComboBox* subjectBox() const { return subject_; }
  QLineEdit* directionEdit() const { return direction_; }
  QDoubleSpinBox* bandLo() const { return lo_; }
  QDoubleSpinBox* bandHi() const { return hi_; }
  QString transmissionStatus() const;
  QString limitsStatus() const;
  // Times the checks were computed (tests: none while hidden).
  int computations() const { return computations_; }

 private:
  // The tables and notes of the results, the transmission band's row, the form choosing the
  // limits' subject, and all of them in three sections in a scroll area.
  void buildWidgets();
  void createResults();
  QHBoxLayout* bandRow();
  QFormLayout* subjectForm();
  void layOut(QHBoxLayout* band, QFormLayout* form);
  void offerSubjects();
  void subjectEdited();
  void compute() override;
  // Empties a section's table and note; false, with the note saying why, without motion.
  bool clearSection(QTableWidget* table, QLabel* note) const;
  void fillGrashof();
  void fillTransmission();
  void fillLimits();
  void turnTo(double crankDeg);

  QPointer<Document> doc_;
  DesignChoices* choices_;
  int computations_ = 0;
  QTableWidget *grashof_, *transmission_, *limits_;
  QComboBox* subject_;
  QLineEdit* direction_;
  QDoubleSpinBox *lo_, *hi_;
  QLabel *transmissionNote_, *limitsNote_;
  QObject* docContext_ = nullptr;
};

}  // namespace linkage::ui
