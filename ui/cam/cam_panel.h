// The Cam dock (issue 28, "Design from the motion"): a cam designed from its follower's motion.
// The cam chosen (a cam joint of the design), its follower, its base circle and roller (typed,
// or found: the smallest base that keeps the pressure angle within a limit, the largest roller
// that does not undercut), its programme in a table (cam/cam_table.h) beside the follower's
// s, s', s'', s''' and the check against the cam angle (cam/cam_figure.h), the checks' extremes
// in words. Every edit is one undo step of the document (the cam cut again, the machine
// solved), a dragged segment's end one step when it is let go; the canvas draws the new
// profile as it goes. The cursor follows the cam's angle at the pose.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "canvas/clearance_marks.h"
#include "docks/dock_panel.h"
#include "document/document.h"
#include "linkage/cam_checks.h"
#include "linkage/model.h"

class QComboBox;
class QCustomPlot;
class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace linkage::ui {

class CamFigure;
class CamTable;

class CamPanel : public DockPanel {
  Q_OBJECT

 public:
  explicit CamPanel(Document* doc, QWidget* parent = nullptr);
  ~CamPanel() override;

  // The cam shown (a cam joint of the design), none when the design has none.
  JointId camShown() const { return shown_; }
  void showCam(JointId j);
  CamFigure* figure() const { return figure_.get(); }
  CamTable* table() const { return table_; }
  // The checks' words, as shown (for tests and tools).
  QString checksText() const;

  // For the X tests' probe (ui/window/probe.h): the cam shown, its segments, checks and
  // message, where the table's cells, the buttons and the segments' ends on the plots are.
  QStringList probeLines() const;

  // The buttons' work: false with why where nothing is found or the edit is refused.
  bool findBase(QString* why);
  bool findRoller(QString* why);

  // The checks' extremes on the cam at the pose (world, mm), as the canvas rings them.
  const std::vector<ClearanceMark>& marks() const { return marks_; }

 Q_SIGNALS:
  // While the dock is seen: the checks' extremes where they occur on the cam, turning with it
  // (a ring and its words at each; the warning colour past the limit or undercutting); none
  // when it is not.
  void marksChanged(const std::vector<linkage::ui::ClearanceMark>& marks);

 protected:
  void compute() override;
  void cameIntoView() override;
  void leftView() override;

 private:
  void buildControls();
  QWidget* buildSizes();
  void refreshCams();
  void showChecks(const cam::CamGeometry& g, const cam::CamChecks& c);
  void followPose();
  // Edits the shown cam's copy of the design by `change` as one undo step, or says why not.
  bool edit(const QString& text, const std::function<bool(Mechanism&, std::string&)>& change,
            QString* why = nullptr);
  void endDragged(int k, double deg, bool done);
  void say(const QString& message);
  double limitDeg() const;

  Document* doc_;
  std::vector<JointId> cams_;
  JointId shown_, limitFor_;
  BodyId camBody_, guideBody_;
  std::optional<cam::CamGeometry> geometry_;
  std::optional<cam::CamChecks> checks_;
  Vec2 centre_ = Vec2::Zero();  // the cam's centre as drawn
  std::vector<ClearanceMark> marks_;
  std::optional<DocumentState> dragBefore_;
  QComboBox* choice_;
  QLabel *follower_, *checksText_, *message_;
  QDoubleSpinBox *base_, *roller_, *limit_;
  QPushButton *findBase_, *findRoller_;
  CamTable* table_;
  QCustomPlot* plot_;
  std::unique_ptr<CamFigure> figure_;
};

}  // namespace linkage::ui
