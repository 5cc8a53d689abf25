// Find Dimensions (issue 29, "Dimensions found for targets"): the dimensions to vary, each
// between bounds, or counterweights on the bodies pinned to the ground (never both: the solver
// refuses the mix, said); the targets of every kind (design/optimize_targets.h); the search
// (linkage/optimize.h: a multistart of a gradient method fed by the exact sensitivities, on a
// thread of its own so that the window answers meanwhile); the result shown before and after
// (each variable, each target's measures with their units, each counterweight's mass, the
// objective, how many starts found the best) and
// applied to the design as one undo step. A design that does not assemble is never applied:
// the search counts it infeasible.
#pragma once

#include <QDialog>
#include <QStringList>
#include <future>
#include <memory>
#include <optional>
#include <vector>

#include "linkage/optimize.h"

class QLabel;
class QLayout;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace linkage::ui {

class Document;
class OptimizeTargets;
struct MeasureRow;

class OptimizeDialog : public QDialog {
  Q_OBJECT

 public:
  explicit OptimizeDialog(Document* doc, QWidget* parent = nullptr);
  ~OptimizeDialog() override;

  // The design's dimensions and outputs read again (a new design, an edit).
  void refresh();
  // What a user does in the tables and buttons (and the tests): vary a dimension between lo and
  // hi; a stroke target or a position target for a point (by its label "body.point"); search;
  // apply. find() returns at once; finished() tells when the result is shown.
  bool vary(const std::string& dimension, double lo, double hi);
  bool addStrokeTarget(const std::string& point, double strokeMm);
  bool addPositionTarget(const std::string& point, double crankDeg, Vec2 at);
  // Any kind: `of` as the target table's list names it, `value` as its Value cell reads it.
  bool addTarget(OptTarget::Kind kind, const QString& of, const QString& value, double crankDeg = 0,
                 double weight = 1);
  void find();
  bool busy() const { return busy_; }
  const std::optional<OptimizeResult>& result() const { return result_; }
  bool apply();
  QString summary() const;  // what the line under the result says
  // For the real-X tests (ui/window/probe.h): the summary, the buttons, the rows and where.
  QStringList probeLines() const;

 Q_SIGNALS:
  void finished();

 private:
  void buildVariables();
  QLayout* buildTargetButtons();
  void addVariableRow(int row, const QString& name, const QString& value, double lo, double hi);
  bool readSpec(OptimizeSpec& spec, QString* why) const;
  void showResult();
  void showRows(const std::vector<MeasureRow>& rows);
  QString resultSummary() const;

  Document* doc_;
  QTableWidget *variables_, *result_table_;
  OptimizeTargets* targets_;
  QSpinBox *starts_, *seed_;
  QPushButton *find_, *apply_;
  QLabel* summary_;
  std::optional<OptimizeResult> result_;
  OptimizeSpec spec_;  // what result_ answers
  std::vector<std::future<void>> jobs_;
  bool busy_ = false;
  int generation_ = 0;
};

}  // namespace linkage::ui
