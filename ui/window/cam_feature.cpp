#include "window/cam_feature.h"

#include <QAction>
#include <QDockWidget>
#include <algorithm>
#include <utility>

#include "cam/cam_panel.h"
#include "canvas/canvas_scene.h"
#include "canvas/clearance_marks.h"
#include "document/document.h"
#include "linkage/elements.h"
#include "window/main_window.h"
#include "window/plots_feature.h"
#include "window/window_layout.h"

namespace linkage::ui {

CamFeature::CamFeature(MainWindow& w, WindowLayout& layout) : WindowFeature(&w), w_(w) {
  panel_ = new CamPanel(w_.document());
  dock = addDock(&w_, "cam", tr("Cam"), panel_, Qt::BottomDockWidgetArea);
  dock->setFeatures(QDockWidget::DockWidgetClosable | QDockWidget::DockWidgetMovable);
  dock->hide();
  w_.tabifyDockWidget(w_.plots().dock, dock);
  showPanel = raisingToggle(dock, "showCamPanel", QKeySequence(tr("Shift+K")),
                            tr("Design a cam from its follower's motion: its programme in a "
                               "table beside s, s', s'', s''' and its pressure angle or "
                               "curvature, its base circle and roller found for the checks"));
  showPanel->setText(tr("Ca&m Design"));
  // The table and five plots want more height than the plots' dock keeps: taken when shown.
  connect(dock, &QDockWidget::visibilityChanged, this, [this](bool on) {
    if (on)
      w_.resizeDocks({dock}, {std::max(dock->height(), w_.height() * 45 / 100)}, Qt::Vertical);
  });
  auto* marks = new ClearanceMarksItem(w_.scene()->context());
  w_.scene()->addOverlay(marks);
  connect(panel_, &CamPanel::marksChanged, this,
          [marks](const std::vector<ClearanceMark>& m) { marks->setMarks(m); });
  layout.add(Slot::ViewCamDock, dock->toggleViewAction());
  layout.add(Slot::AnalysisCamDock, showPanel);
  // A cam made (a follower's "Drive by a Cam", or its redo): the dock shows it. A file opened
  // brings its cams with it, not made: they are known from the start.
  Document* doc = w_.document();
  connect(doc, &Document::contentsReplaced, this, [this] {
    known_.clear();
    replaced_ = true;
  });
  connect(doc, &Document::designChanged, this, [this, doc] {
    const JointType cam = elementKindNamed("cam")->type;
    JointId made;
    for (const Joint& j : doc->design().joints)
      if (j.type == cam && known_.insert(j.id).second) made = j.id;
    if (std::exchange(replaced_, false) || !made) return;
    panel_->showCam(made);
    dock->show();
    dock->raise();
  });
}

}  // namespace linkage::ui
