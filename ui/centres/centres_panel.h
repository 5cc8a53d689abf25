// The instant-centres panel: every centre at the current crank angle (i, j, bodies, where, at
// infinity, how it was found), following the animation; and for a chosen point, its velocity by
// a chain of centres written out step by step as the homework writes it, beside the solver's
// exact velocity and their difference. Work is done only while the panel is seen
// (docks/dock_panel.h), once per turn of the event loop.
#pragma once

#include <QElapsedTimer>
#include <QPointer>
#include <QStringList>
#include <QTimer>
#include <optional>

#include "docks/dock_panel.h"
#include "linkage/velocity_chain.h"

class QComboBox;
class QLineEdit;
class QTableWidget;
class QTextBrowser;

namespace linkage::ui {

class Document;

class CentresPanel : public DockPanel {
  Q_OBJECT

 public:
  explicit CentresPanel(QWidget* parent = nullptr);
  void setDocument(Document* doc);
  // Asks for what is shown to be recomputed (while seen), once per turn of the event loop
  // however often it is asked (an edit changes the design and the pose at once); the window
  // calls it on every pose change.
  void refresh();
  const std::optional<VelocityChain>& chain() const { return chain_; }
  QTableWidget* table() const { return table_; }
  QString chainText() const;
  // What the panel's text says now (the chain written out, or why there is none), plain.
  QString stepsText() const;

 Q_SIGNALS:
  // A row was chosen: (0, 0) when none.
  void centreChosen(int i, int j);
  // The chain changed (or is gone): the canvas draws its distances.
  void chainChanged();

 private:
  void compute() override;
  void leftView() override;
  void dropChain();
  void rebuildPoints();
  void fillTable(const InstantCentres& ics);
  std::pair<int, int> shownRows() const;  // [first, last) with a margin
  void fillRows(const InstantCentres& ics, int from, int to);
  void fillScrolledTo();
  static QString coordinate(const InstantCentre& c, double v);
  QString planeText(const InstantCentres& ics, const InstantCentre& c) const;
  QString statusText(const InstantCentre& c, bool held) const;
  void fillChain(const InstantCentres& ics);
  // chainText()'s parts: the crank's turning, each step from body to body (how v_P is found,
  // then what it makes of the next body's motion), the point's velocity, the check against
  // the solver.
  QString crankText(const VelocityChain& ch, const InstantCentres& ics) const;
  QString stepText(const ChainStep& st) const;
  QString stepMotionText(const ChainStep& st) const;
  QString pointText(const VelocityChain& ch, const QString& label) const;
  QString comparisonText(const VelocityChain& ch) const;

  QPointer<Document> doc_;
  QTableWidget* table_;
  std::vector<bool> fresh_;          // the rows written at this pose
  std::uint64_t tableRevision_ = 0;  // the revision the columns were sized for
  QComboBox* point_;
  QLineEdit* via_;
  QTextBrowser* steps_;
  std::optional<VelocityChain> chain_;
  QStringList pointLabels_;  // the choices of point_
  bool choseNone_ = false;   // the user asked for no chain
  // The written-out chain is laid out as rich text, which costs more than a frame: while the
  // mechanism moves it is rewritten at most ten times a second, and once more when it stops.
  QElapsedTimer lastText_;
  QTimer textTimer_;
};

}  // namespace linkage::ui
