// The plots dock's widget: position, velocity, acceleration (and jerk on request) of a point,
// or a body's rotation, against the crank angle over R revolutions, stacked on a shared axis;
// another open document's curves overlaid or side by side (the homework's 3 x 2 figure); the
// harmonics as bar charts; extremes marked and listed; a cursor on every plot at the current
// crank angle, and clicking or dragging on a plot asks for that crank angle.
//
// Work is done only for what is seen (docks/dock_panel.h): hidden or behind another tab, the
// panel computes nothing (an edit marks the curves stale; they are sampled when it is seen
// again, or when a figure is exported); a pose change only moves the cursor (its own layer is
// repainted, the curves are not recomputed); an edit of one document resamples that document's
// curves only, and only the orders shown.
//
// Wiring in a main window:
//   auto* plots = new PlotsPanel(dock);
//   plots->setDocument(doc);
//   connect(plots, &PlotsPanel::crankAngleRequested, [doc](double d) { doc->setCrankDeg(d); });
#pragma once

#include <QList>
#include <QPointer>
#include <memory>
#include <vector>

#include "docks/dock_panel.h"
#include "figures/units.h"
#include "plots/curve_set.h"

class QCustomPlot;
class QLabel;
class QMouseEvent;
class QStackedWidget;
class QTreeWidget;

namespace linkage::ui {

class Document;
class HarmonicsFigure;
class MotionFigure;
class PlotControls;

class PlotsPanel : public DockPanel {
  Q_OBJECT

 public:
  enum class Compare { Off, Overlay, SideBySide };

  explicit PlotsPanel(QWidget* parent = nullptr);
  ~PlotsPanel() override;

  // The document whose curves are plotted and whose crank angle the cursor follows; nullptr
  // for none. The plotted point is its first output (or the one asked before, if it has it).
  void setDocument(Document* doc);
  Document* document() const { return doc_; }
  // Other open documents to compare with (the same point, found by its "body.point" name).
  // Shown when the compare mode is not Off; a document deleted elsewhere drops out.
  void setComparisonDocuments(const QList<Document*>& docs);
  void setCompare(Compare c);
  // The point of the other documents to compare with ("body.point"); "" for the point of the
  // same name (or, where there is none, their first output).
  void setComparisonTarget(const QString& target);
  QString comparisonTarget() const { return against_; }
  Compare compare() const { return compare_; }

  // What is plotted; the controls follow.
  void setRequest(const CurveRequest& r);
  const CurveRequest& request() const { return request_; }
  // Remembered in QSettings ("plots/velocityUnit", "plots/accelerationUnit").
  void setUnits(const PlotUnits& u);
  const PlotUnits& units() const { return units_; }
  void setHarmonicsShown(bool on);

  // Writes the figure shown (curves, or harmonics when they are shown) to .png, .pdf or .svg at
  // `size` pixels, without the cursor; computes the curves first if the panel is hidden.
  bool exportFigure(const QString& path, QSize size, QString* error);

  // For tests and tools.
  QCustomPlot* plotWidget() const { return plot_; }
  const MotionFigure& figure() const { return *figure_; }
  double cursorDeg() const;      // where the cursor is drawn, in the plotted range
  QString cursorText() const;    // the values at the cursor, as shown
  QString extremesText() const;  // the extremes list, one line per row
  QString statusText() const;    // the line over the plots: why there is nothing to plot
  int computations() const { return computations_; }  // curve sets sampled so far
  const CurveSet* curves(int i) const;  // 0: the document's; then the comparisons shown

 Q_SIGNALS:
  // A click or drag on a plot at this crank angle: in the R-revolution window the document's
  // crank is in, so that following it moves the mechanism the short way.
  void crankAngleRequested(double deg);

 private:
  void compute() override;
  void cameIntoView() override;
  void buildWidgets();
  void offerTargets();
  void writeControls();
  // Document d's curves sampled again (an edit of it).
  void resample(Document* d);
  void rebuildFigure();
  void updateCursor();
  void updateExtremes();
  void mouseOnPlot(QMouseEvent* e, bool press);
  std::vector<Document*> shownDocuments() const;
  // What is plotted of document d: the request, with another document's point chosen.
  CurveRequest requestFor(const Document* d) const;
  void offerComparisonTargets();
  std::vector<const CurveSet*> shownSets() const;

  QPointer<Document> doc_;
  QList<QPointer<Document>> others_;
  Compare compare_ = Compare::Off;
  QString against_;
  CurveRequest request_;
  PlotUnits units_;
  bool harmonics_ = false;

  // One curve set per shown document (same order as shownDocuments()), null when stale.
  std::vector<std::pair<QPointer<Document>, std::unique_ptr<CurveSet>>> sets_;
  bool figureStale_ = true;
  // Receivers of the documents' signals: replaced (and so disconnected) with the documents.
  QObject *docContext_ = nullptr, *othersContext_ = nullptr;
  int computations_ = 0;

  PlotControls* controls_;
  QStackedWidget* stack_;
  QCustomPlot *plot_, *harmonicsPlot_;
  std::unique_ptr<MotionFigure> figure_;
  std::unique_ptr<HarmonicsFigure> harmonicsFigure_;
  QLabel *status_, *values_;
  QTreeWidget* extremes_;
};

}  // namespace linkage::ui
