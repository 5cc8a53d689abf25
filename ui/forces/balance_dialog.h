// Forces > Balance: counterweights that minimise the peak of the shaking force over the cycle
// (linkage/balance.h: exact, with a certified gap). The user picks the bodies pinned to the
// ground that take one, the measure (fx, fy, fz in space, or |F|), an optional bound on each
// |s| (kg mm) and the samples of the first programme; Compute runs balanceShaking (tens of
// milliseconds) and
// shows the counterweights (static moment, mass, radius, angle), the peak before and after with
// their crank angles, the gap, and the shaking force before and after (curves and polar
// diagrams), after as Apply leaves it: under gravity with the counterweights' weight, which the
// balance minimises with the rest. Apply adds the counterweights to the bodies' masses
// (addCounterweights) as one undoable edit; it is offered only when the peak goes down. A
// machine in space: the world's force, and what the counterweights cannot reach said with its
// peak.
#pragma once

#include <QDialog>
#include <QPointer>
#include <optional>

#include "linkage/balance.h"

class QCheckBox;
class QComboBox;
class QCustomPlot;
class QDialogButtonBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace linkage::ui {

class Document;

class BalanceDialog : public QDialog {
  Q_OBJECT

 public:
  explicit BalanceDialog(Document* doc, QWidget* parent = nullptr);
  ~BalanceDialog() override;

  // The bodies offered (pinned to the ground), in the design's order, and which are ticked.
  std::vector<BodyId> offeredBodies() const;
  void setBodyChecked(BodyId b, bool on);
  void setMeasure(BalanceMeasure m);
  void setBound(std::optional<double> kgMm);
  void setSteps(int steps);

  // For tests and tools.
  const BalanceResult* result() const { return result_ ? &*result_ : nullptr; }
  QString message() const;  // the error or note shown, "" for none
  QString summary() const;  // the peaks and the gap as shown
  QTableWidget* table() const { return table_; }
  QCustomPlot* plotWidget() const { return plot_; }
  QPushButton* applyButton() const;

 public Q_SLOTS:
  // Runs the balance with the choices made; false (and the reason shown) when it fails.
  bool compute();
  // The counterweights found added to the design: one undo step. False when there is nothing
  // to apply (no result, or the design changed since).
  bool apply();

 private:
  void buildWidgets();
  QWidget* buildChoices();
  void offerBodies();
  void showResult();
  QString headline(const BalanceResult& r) const;
  QString leftOut(const BalanceResult& r) const;
  void forget(const QString& why);
  void say(const QString& text, bool error);

  QPointer<Document> doc_;
  std::optional<BalanceResult> result_;
  bool applying_ = false;

  std::vector<std::pair<BodyId, QCheckBox*>> bodies_;
  QWidget* bodyBox_;
  QComboBox* measure_;
  QCheckBox* bounded_;
  QDoubleSpinBox* bound_;
  QSpinBox* steps_;
  QPushButton* compute_;
  QTableWidget* table_;
  QLabel *summary_, *message_;
  QCustomPlot* plot_;
  QDialogButtonBox* buttons_;
};

}  // namespace linkage::ui
