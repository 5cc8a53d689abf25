// The Cycle dock's widget (issue 18): the machine's cycle (timing) diagram over one turn of the
// main shaft (ui/cycle/cycle_figure.h) and the entries it is made of (rows, windows, conflicts,
// clearances: ui/cycle/cycle_entries.h), typed in a line or edited in the list, each with its
// result (the windows' crank angles, the overlaps, the closest approach) found exactly by the
// solver. Every change of an entry is an undo step of the document, kept in its file.
//
// A window is also made by choosing (issue 26): the form under the line (cycle/window_form.h)
// takes its point from a list or from the canvas (Pick), its axis, below or above, and the
// threshold typed; each window's threshold is a line in its row of the diagram
// (cycle/level_lines.h) that a drag moves, the window's ends and overlaps following live,
// the release one undo step. The form edits the window chosen in the list, or adds a new one.
//
// A cursor follows the document's crank angle; a click or drag on the diagram asks for that
// angle (the same signal as the plots'). Only determined numbers are shown: a design not
// solved, a motion the driver does not determine or a crank that cannot turn a whole cycle get
// a sentence in place of the diagram; an entry that cannot be measured says why in its row.
// Work only while seen (docks/dock_panel.h): hidden, an edit marks the diagram stale.
#pragma once

#include <QPointer>
#include <memory>
#include <optional>
#include <utility>

#include "canvas/clearance_marks.h"
#include "cycle/cycle_entries.h"
#include "cycle/cycle_figure.h"
#include "cycle/level_lines.h"
#include "docks/dock_panel.h"

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
class WindowForm;

class CyclePanel : public DockPanel {
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

  // The window form, and what the canvas answers to its Pick: the point clicked (the form
  // takes it as if chosen from its list), or that none will come (Esc, another tool).
  WindowForm* windowForm() const { return form_; }
  void pointPicked(PointId p);
  void pickEnded();
  // Where window i's threshold line is on the screen's plot, at a crank angle (nullopt: it
  // is not drawn); for tests and the probe.
  std::optional<QPointF> levelPixel(int window, double crankDeg) const;

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

 public Q_SLOTS:
  void saveFigureAs();
  void saveTableAs();

 Q_SIGNALS:
  void crankAngleRequested(double deg);
  // The form's Pick: on, the canvas should give the next point clicked (pointPicked) or say
  // that none will come (pickEnded); off, give up picking.
  void pickPointRequested(bool on);
  // Where the clearances' closest approaches are, for the canvas (none while hidden).
  void marksChanged(const std::vector<linkage::ui::ClearanceMark>& marks);

 protected:
  bool eventFilter(QObject* watched, QEvent* e) override;

 private:
  void buildWidgets();
  QWidget* buildAddRow();
  void buildList();  // the entries and their results
  void fillList();
  void compute() override;
  void cameIntoView() override;
  void leftView() override;
  void computeClearances(const Kinematics& k);
  // Clearance entry i's result (null when it is not measured).
  const CycleClearanceRow* clearanceRow(int i) const;
  void rebuildFigure();
  void showResults();
  QString whyNoDiagram() const;
  void updateCursor();
  void mouseOnPlot(QMouseEvent* e, bool press);
  void itemEdited(QTreeWidgetItem* item);
  void setError(const QString& why);  // "" hides the line
  void fitEntryColumn();
  void emitMarks();
  bool change(const QString& title, const std::function<bool(Mechanism&, QString*)>& edit,
              QString* why);
  // The window form (cycle/window_form.h): cycle_panel_windows.cpp.
  void connectForm();
  void formFollowsDesign();
  void selectWindowItem(int window);
  void formEdited(bool outputChanged);
  void addFromForm();
  // -1: a new window; `reveal` shows the form (Window in the kind box).
  void setFormTarget(int window, bool reveal = true);
  void showDraftResult(const TimingWindow& w);
  std::optional<std::pair<double, double>> strokeOf(const LimitMeasure& x) const;
  // A threshold dragged on the diagram: shown live (preview_), made one undo step on release.
  void beginLevelDrag(int window);
  void dragLevel(double pixelY);
  void endLevelDrag();

  QPointer<Document> doc_;
  CycleDiagram diagram_;
  std::vector<CycleWindow> windows_;
  std::vector<CycleClearanceRow> clearances_;
  std::vector<QString> clearanceWhy_;  // per clearance entry: why it is not measured, or ""
  QString why_;
  bool filling_ = false;
  std::optional<Timing> preview_;  // the timing shown while a threshold is dragged
  int levelDrag_ = -1;             // the window whose threshold is dragged
  std::uint32_t formOwner_ = 0;    // the mechanism the form's fields are of (Mechanism::owner)
  int computations_ = 0;

  QComboBox* kind_;
  QLineEdit* line_;
  WindowForm* form_;
  QLabel *error_, *values_, *sentence_;
  QTreeWidget* list_;
  QStackedWidget* stack_;
  QScrollArea* scroll_;  // the diagram, scrolled in a dock too low for its rows
  QCustomPlot* plot_;
  std::unique_ptr<CycleFigure> figure_;
  std::unique_ptr<LevelLines> levels_;
};

}  // namespace linkage::ui
