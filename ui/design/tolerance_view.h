// The Sensitivity dock's Tolerances tab (issue 29, "Tolerances"): a tolerance typed for any
// dimension (+-, in its unit), and the chosen point's x or y band over the cycle drawn as its
// deviation from the nominal: first order worst case and root sum of squares (filled), and, with
// samples asked for, the Monte Carlo extremes of samples each solved exactly (lines); the
// stroke's spread, the crank angles where first order is not enough, and the samples that did
// not assemble or turn, in words (linkage/tolerance.h). Computed on a thread of its own, so that
// many samples never hold the window; a result for a design, point or tolerance since changed
// is dropped. The tolerances are the dock's, kept by dimension name while the window is open
// (the file format has no place for them).
#pragma once

#include <QWidget>
#include <future>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "linkage/tolerance.h"

class QCustomPlot;
class QLabel;
class QSpinBox;
class QTableWidget;

namespace linkage::ui {

class ToleranceView : public QWidget {
  Q_OBJECT

 public:
  explicit ToleranceView(QWidget* parent = nullptr);
  ~ToleranceView() override;

  // The design, its dimensions' names, the point and component (0 x, 1 y, 2 z) to show; a new
  // computation starts when any of them or a tolerance changed.
  void update(const Mechanism& m, const std::vector<std::string>& dimensions, PointId point,
              int component);
  // Typed into the table, as a user does (tests).
  void setTolerance(const std::string& dimension, double plusMinus);
  void setSamples(int n);
  // The last result shown (none yet: its status not ok and no rows), and whether a computation
  // is under way.
  const ToleranceResult& result() const { return result_; }
  bool busy() const { return pending_ > 0; }
  QString summary() const;

 Q_SIGNALS:
  void shown();  // a result was drawn

 private:
  void fillTable(const std::vector<std::string>& dimensions);
  void start();
  void draw();

  QTableWidget* table_;
  QSpinBox *samples_, *seed_;
  QCustomPlot* plot_;
  QLabel* summary_;
  std::map<std::string, double> tol_;
  std::vector<std::string> names_;
  std::shared_ptr<const Mechanism> design_;
  PointId point_;
  int component_ = 1;
  ToleranceResult result_;
  int generation_ = 0, pending_ = 0;
  std::vector<std::future<void>> jobs_;
  bool filling_ = false;
};

}  // namespace linkage::ui
