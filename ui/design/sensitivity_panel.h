// The Sensitivity dock (issue 29, "Sensitivities, exact"): which dimensions matter most for a
// chosen output, a point's x, y or the length of its move (position, velocity or acceleration),
// or its stroke (along its slot, else y: linkage/stroke_sensitivity.h), or a watched
// clearance's closest approach (linkage/clearance_sensitivity.h), or a timing window's start or
// end (linkage/window_sensitivity.h), or a dyad's transmission angle
// (linkage/transmission_sensitivity.h), as a ranked bar chart: for each dimension
// (linkage/sensitivity.h, named as the typed dimensions are) its derivative at the crank angle
// (signed, in colour) over the largest of its size over a turn (grey, every 5 degrees), the largest
// first. Exact, from the constraint Jacobian, never by differences. Computed while seen
// (docks/dock_panel.h); the text under the chart names the one that matters most, and what the
// solver cannot differentiate yet is said. Its second tab carries tolerances through the motion
// (design/tolerance_view.h) for the same output.
#pragma once

#include <QString>
#include <QStringList>
#include <functional>
#include <tuple>
#include <utility>
#include <vector>

#include "docks/dock_panel.h"
#include "linkage/elements.h"
#include "linkage/kinematics.h"
#include "linkage/model.h"
#include "linkage/sensitivity.h"

class QComboBox;
class QCustomPlot;
class QLabel;
class QTabWidget;

namespace linkage::ui {

class Document;
class ToleranceView;

class SensitivityPanel : public DockPanel {
  Q_OBJECT

 public:
  explicit SensitivityPanel(Document* doc, QWidget* parent = nullptr);

  // What is shown (for tests and the probe): the dimensions ranked, the largest first, with
  // their derivative at the crank angle and their largest size over a turn.
  struct Bar {
    std::string dimension;
    double now = 0, peak = 0;
  };
  const std::vector<Bar>& bars() const { return bars_; }
  QString summary() const;
  QComboBox* pointBox() const { return point_; }
  QComboBox* quantityBox() const { return quantity_; }
  QComboBox* componentBox() const { return component_; }
  QStringList probeLines() const;
  // How often the turn's largest derivatives were computed (tests: not again for a new pose).
  int turnComputations() const { return turnComputations_; }
  ToleranceView* tolerances() const { return tolerances_; }

 protected:
  void compute() override;

 private:
  void fillPoints();
  void draw();
  void showNothing(const QString& why);
  // The stroke's derivatives (the envelope theorem at its limit positions) as the bars.
  void strokeBars(const Kinematics& k, PointId p, int which);
  // The least distance of the file's clearance n (linkage/clearance_sensitivity.h).
  void clearanceBars(int n);
  // A window's first interval's start or end (linkage/window_sensitivity.h): end n of the list.
  void windowBars(int n);
  // Transmission angle n (as linkage-cli transmission numbers them): at the crank angle and the
  // turn's largest, as a point's; what is not a dyad between points said.
  void transmissionBars(int n);
  // The shaking force's component `which` (x, y, the length of the change;
  // linkage/shaking_sensitivity.h), at the crank angle and the turn's largest.
  void shakingBars(int which);
  // The shaking moment (about the drawing's origin; in space the world's, the component box's
  // component), likewise.
  void momentBars();
  // Joint m.joints[j]'s reaction's component `which` (linkage/force_sensitivity.h), likewise.
  void reactionBars(size_t j, int which);
  // What the joint bears here, for the line under the chart.
  QString reactionSummary(const Kinematics& k, const Joint& joint, const JointReaction& r,
                          bool rod) const;
  // The bars of one derivative a dimension, ranked and drawn with the axis's label; false when
  // there are none.
  bool showValues(const std::vector<Dimension>& dims, const std::vector<double>& derivative,
                  const QString& axis);
  void rank();  // the bars, the largest (over a turn) first
  // Each dimension's bar (its derivative now(d) here, none where the pose has none; its largest
  // over the turn), ranked and drawn, the axis in `unit` per unit of the dimension.
  void turnBars(const std::vector<Dimension>& dims, bool here,
                const std::function<double(int)>& now, const std::vector<double>& peak,
                const QString& unit);
  // Each dimension's largest |f| over a turn from k's pose (on a copy), of the design and the
  // output `key` (a point, quantity, component; a transmission angle: no point, -1, its number):
  // computed again only when either changed.
  using PerDimension = std::function<double(const Sensitivity&, const Kinematics&, int dim)>;
  const std::vector<double>& turnPeaks(const std::tuple<PointId, int, int>& key, Sensitivity& s,
                                       Kinematics k, const PerDimension& f);
  // The component z (the world's) offered on a machine in space only.
  void offerZ(bool space);

  Document* doc_;
  QComboBox *point_, *quantity_, *component_;
  QCustomPlot* plot_;
  QLabel* summary_;
  QTabWidget* tabs_;
  ToleranceView* tolerances_;
  std::vector<PointId> points_;
  // After the points: the file's watched clearances, then windows' ends, then transmission angles.
  QStringList clearances_;
  int windowsFrom_ = 0;            // where the windows' ends start in clearances_
  int transmissionsFrom_ = 0;      // where the transmission angles start
  int shakingAt_ = -1;             // the shaking force's entry (a design with masses), else -1
  std::vector<size_t> reactions_;  // the joints whose reactions follow it (m.joints' indices)
  int momentAt_ = -1;              // after them the shaking moment's (planar, masses), else -1
  std::vector<Bar> bars_;
  bool deadHere_ = false;
  // The tolerances' band is of a design and an output: computed again only when they change.
  bool toleranceStale_ = true;
  std::pair<PointId, int> toleranceFor_;
  // The turn's largest derivatives, of a design and an output (point, quantity, component).
  bool turnStale_ = true;
  std::tuple<PointId, int, int> turnFor_;
  std::vector<double> turnPeak_;
  int turnComputations_ = 0;
};

}  // namespace linkage::ui
