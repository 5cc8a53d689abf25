#include "window/centres_feature.h"

#include <QAction>
#include <QDockWidget>
#include <QSettings>

#include "canvas/canvas_scene.h"
#include "canvas/canvas_view.h"
#include "centres/centres_panel.h"
#include "document/document.h"
#include "window/icons.h"
#include "window/main_window.h"
#include "window/window_layout.h"

namespace linkage::ui {

CentresFeature::CentresFeature(MainWindow& w, WindowLayout& layout) : WindowFeature(&w) {
  CanvasScene* scene = w.scene();
  // Not "Instant Centres": the dock of that name is beside it in the View menu.
  show = makeToggle(&w, "showCentres", tr("&Instant Centres on Canvas"), QKeySequence(tr("I")),
                    tr("Show every instant centre; hover one for its Kennedy lines"));
  connect(show, &QAction::toggled, scene, &CanvasScene::setCentresVisible);
  panel_ = new CentresPanel;
  dock = addDock(&w, "centres", tr("Instant Centres"), panel_, Qt::RightDockWidgetArea);
  panel_->setDocument(w.document());
  // The chain's distances belong to the instant-centre view: drawn while it is on.
  auto showChain = [this, scene] {
    scene->chainItem()->setChain(show->isChecked() ? panel_->chain() : std::nullopt);
  };
  connect(panel_, &CentresPanel::chainChanged, this, showChain);
  connect(show, &QAction::toggled, this, showChain);
  connect(panel_, &CentresPanel::centreChosen, w.canvas(), &CanvasView::setSelectedCentre);
  connect(w.document(), &Document::poseChanged, panel_, &CentresPanel::refresh);
  connect(w.document(), &Document::designChanged, panel_, &CentresPanel::refresh);
  layout.add(Slot::ViewCentres, show);
  layout.add(Slot::ViewBarCentres, show);
  layout.add(Slot::ViewCentresDock, dock->toggleViewAction());
}

void CentresFeature::applyIcons(const QPalette& p) {
  show->setIcon(themedIcon(QStringLiteral("centres"), p));
}

void CentresFeature::readSettings(const QSettings& s) {
  show->setChecked(s.value(QStringLiteral("centres"), false).toBool());
}

void CentresFeature::writeSettings(QSettings& s) const {
  s.setValue(QStringLiteral("centres"), show->isChecked());
}

}  // namespace linkage::ui
