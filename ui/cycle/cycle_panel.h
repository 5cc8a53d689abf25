// The Cycle dock's widget (issue 18): the machine's cycle (timing) diagram over one turn of the
// main shaft (ui/cycle/cycle_figure.h) and the entries it is made of (rows, windows, conflicts,
// clearances: ui/cycle/cycle_entries.h), typed in a line or edited in the list, each with its
// result (the windows' crank angles, the overlaps, the closest approach) found exactly by the
// solver. Every change of an entry is an undo step of the document, kept in its file.
//
// A cursor follows the document's crank angle; a click or drag on the diagram asks for that
// angle (the same signal as the plots'). Only determined numbers are shown: a design not
// solved, a motion the driver does not determine or a crank that cannot turn a whole cycle get
// a sentence in place of the diagram; an entry that cannot be measured says why in its row.
// Work only while seen: hidden, an edit marks the diagram stale.
#pragma once

#include <QPointer>
#include <QWidget>
#include <memory>

#include "canvas/clearance_marks.h"
#include "cycle/cycle_entries.h"
#include "cycle/cycle_figure.h"
#include "plots/redraw_throttle.h"

class QComboBox;
class QCustomPlot;
class QLabel;
class QLineEdit;
class QMouseEvent;
class QScrollArea;
class QStackedWidget;
class QTreeWidget;
class QTreeWidgetItem;

namespace linkage::ui {

class Document;
class Selection;

class CyclePanel : public QWidget {
  Q_OBJECT

 public:
  explicit CyclePanel(Document* doc, QWidget* parent = nullptr);
  ~CyclePanel() override;

  // Adds an entry as typed; false with why (the entry is not added). One undo step.
  bool addEntry(EntryKind kind, const QString& text, QString* why = nullptr);
  // Replaces or removes entry `index` of its kind. One undo step each.
  bool editEntry(EntryKind kind, int index, const QString& text, QString* why = nullptr);
  void removeEntry(EntryKind kind, int index);
  // A clearance between the selection's two things: two points, or a point and a slot of
  // another body. False with why when the selection is not that.
  bool watchSelection(const Selection& s, QString* why);

  bool exportFigure(const QString& path, QSize size, QString* error);
  // The timing table (docs/timing.md), what `linkage-cli timing` writes for the file.
  bool exportTable(const QString& path, QString* error);

  // For tests and tools.
  QCustomPlot* plotWidget() const { return plot_; }
  const CycleFigure& figure() const { return *figure_; }
  QTreeWidget* entryList() const { return list_; }
  QLineEdit* entryLine() const { return line_; }
  QComboBox* kindBox() const { return kind_; }
  const CycleDiagram* diagram() const;  // null when a sentence is shown
  const std::vector<CycleClearanceRow>& clearances() const { return clearances_; }
  QString message() const { return why_; }
  QString entryError() const;
  QString cursorText() const;
  QString resultText(EntryKind kind, int index) const;
  int computations() const { return computations_; }
  // What a script driving the editor reads (window/probe.h): the sentence or the rows, each
  // entry with its result, where the kind box, the line and the diagram's angles are.
  QStringList probeLines() const;
  bool redrawPending() const { return throttle_.pending(); }

 public Q_SLOTS:
  void saveFigureAs();
  void saveTableAs();

 Q_SIGNALS:
  void crankAngleRequested(double deg);
  // Where the clearances' closest approaches are, for the canvas (none while hidden).
  void marksChanged(const std::vector<linkage::ui::ClearanceMark>& marks);

 protected:
  void showEvent(QShowEvent* e) override;
  void hideEvent(QHideEvent* e) override;
  bool eventFilter(QObject* watched, QEvent* e) override;

 private:
  void buildWidgets();
  QWidget* buildAddRow();
  void buildList();  // the entries and their results
  void fillList();
  void markStale();
  void schedule();
  void recompute();
  void computeClearances(const Kinematics& k);
  void rebuildFigure();
  void showResults();
  QString whyNoDiagram() const;
  void updateCursor();
  void mouseOnPlot(QMouseEvent* e, bool press);
  void ensureComputed();
  void itemEdited(QTreeWidgetItem* item);
  void fitEntryColumn();
  void emitMarks();
  bool change(const QString& title, const std::function<bool(Mechanism&, QString*)>& edit,
              QString* why);

  QPointer<Document> doc_;
  CycleDiagram diagram_;
  std::vector<CycleWindow> windows_;
  std::vector<CycleClearanceRow> clearances_;
  std::vector<QString> clearanceWhy_;  // per clearance entry: why it is not measured, or ""
  QString why_;
  bool stale_ = true, dragging_ = false, filling_ = false;
  int computations_ = 0;

  QComboBox* kind_;
  QLineEdit* line_;
  QLabel *error_, *values_, *sentence_;
  QTreeWidget* list_;
  QStackedWidget* stack_;
  QScrollArea* scroll_;  // the diagram, scrolled in a dock too low for its rows
  QCustomPlot* plot_;
  std::unique_ptr<CycleFigure> figure_;
  RedrawThrottle throttle_{this, [this] { recompute(); }};
};

}  // namespace linkage::ui
