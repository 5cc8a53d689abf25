// The forces dock's widget: over one turn at the driver's speed (linkage/force_samples.h), the
// driver's torque, the shaking force's fx and fy, its polar diagram (fy against fx on equal
// scales, the pose marked) and a chosen joint's reaction; a cursor at the document's crank
// angle, and clicking or dragging on a crank-angle plot asks for that angle, as the motion
// plots do (the same signal). A machine in space: what `linkage-cli dynamics` writes, in the
// world's axes (forces/force_figure.h).
//
// Only determined numbers are shown: a design not solved, a motion the driver does not
// determine, or a design with no masses and no loads gets a sentence in place of the curves;
// a joint whose reaction is not determined (a redundant joint) gets one in place of its curves.
// Work only while seen (docks/dock_panel.h): hidden, an edit marks the curves stale; a pose
// change moves the cursor.
//
// Wiring in a main window:
//   auto* forces = new ForcesPanel(doc, dock);
//   connect(forces, &ForcesPanel::crankAngleRequested, [doc](double d) { doc->setCrankDeg(d); });
//   exportForcesFigure->triggered: forces->saveFigureAs(); exportForcesTable: saveTableAs().
#pragma once

#include <QPointer>
#include <memory>

#include "docks/dock_panel.h"
#include "forces/force_figure.h"
#include "linkage/force_samples.h"

class QComboBox;
class QCustomPlot;
class QLabel;
class QMouseEvent;
class QScrollArea;
class QStackedWidget;

namespace linkage::ui {

class Document;

class ForcesPanel : public DockPanel {
  Q_OBJECT

 public:
  explicit ForcesPanel(Document* doc, QWidget* parent = nullptr);
  ~ForcesPanel() override;
  Document* document() const { return doc_; }

  // The joint whose reaction is plotted: its index in the design's joints (-1: none). Kept by
  // its name ("pin:rod.B") across edits of the design.
  void setJoint(int index);
  int joint() const;

  // The figure as shown (without the cursor) to .png, .pdf or .svg at `size` pixels; computes
  // the curves first if the panel is hidden. False, `error` saying why, when there are none.
  bool exportFigure(const QString& path, QSize size, QString* error);
  // The force table (docs/dynamics.md), the rows `linkage-cli dynamics` writes.
  bool exportTable(const QString& path, long long steps, double revs, QString* error);

  // For tests and tools.
  QCustomPlot* plotWidget() const { return plot_; }
  const ForceFigure& figure() const { return *figure_; }
  // The samples drawn, or null when a sentence is shown instead.
  const ForceSamples* samples() const;
  QString message() const;     // the sentence shown in place of the curves, "" for none
  QString cursorText() const;  // the values at the pose, as shown
  double cursorDeg() const { return figure_->cursor(); }
  int computations() const { return computations_; }

 public Q_SLOTS:
  // Asks for a file (SVG, PDF, PNG) and writes the figure; a failure in a message box.
  void saveFigureAs();
  // Asks for the steps and revolutions, then a file, and writes the force table.
  void saveTableAs();

 Q_SIGNALS:
  // A click or drag on a crank-angle plot at this crank angle, in the turn the document's crank
  // is in (so that following it moves the mechanism the short way).
  void crankAngleRequested(double deg);

 protected:
  void resizeEvent(QResizeEvent* e) override;

 private:
  void buildWidgets();
  void offerJoints();
  void compute() override;
  void cameIntoView() override;
  void rebuildFigure();
  QString whyNoForces() const;
  // The sentence for forces too large for the plots' axes, "" when they can be drawn.
  QString beyondThePlots() const;
  // The room the figure has: the scroll area's viewport without scroll bars.
  QSize room() const;
  void updateCursor();
  QString valuesInSpace(double deg, const Kinematics& k, const Forces& f) const;
  void mouseOnPlot(QMouseEvent* e, bool press);

  QPointer<Document> doc_;
  ForceSamples samples_;
  double forceScale_ = 0, torqueScale_ = 0;  // the peaks: what is rounding next to them
  QString why_;                              // the sentence in place of the curves
  QString jointName_;                        // the chosen joint, by the force table's name
  int computations_ = 0;

  QComboBox* joints_;
  QLabel *values_, *sentence_;
  QStackedWidget* stack_;
  QScrollArea* scroll_;  // the plot, scrolled in a dock too low for it
  QCustomPlot* plot_;
  QSize exportSize_;  // while a figure is exported: the size it is laid out for
  std::unique_ptr<ForceFigure> figure_;
};

}  // namespace linkage::ui
