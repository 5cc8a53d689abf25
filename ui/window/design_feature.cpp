#include "window/design_feature.h"

#include <QAction>
#include <QDockWidget>
#include <QSettings>

#include "design/checks_panel.h"
#include "design/design_choices.h"
#include "design/design_overlays.h"
#include "design/study_dialog.h"
#include "window/centres_feature.h"
#include "window/main_window.h"
#include "window/window_layout.h"

namespace linkage::ui {

DesignFeature::DesignFeature(MainWindow& w, WindowLayout& layout) : WindowFeature(&w), w_(w) {
  choices_ = new DesignChoices(&w);
  overlays_ = new DesignOverlays(w.scene(), choices_, &w);
  overlays_->setDocument(w.document());
  makeActions();
  makeDock();
  layout.add(Slot::ViewExtremes, showExtremes);
  layout.add(Slot::ViewTransmission, showTransmission);
  layout.add(Slot::ViewDesignChecksDock, dock->toggleViewAction());
  layout.add(Slot::AnalysisDesignChecks, show);
  layout.add(Slot::AnalysisStudy, parameterStudy);
  layout.add(Slot::AnalysisExtremes, showExtremes);
  layout.add(Slot::AnalysisTransmission, showTransmission);
}

void DesignFeature::makeActions() {
  showExtremes =
      makeToggle(&w_, "showExtremes", tr("&Extreme Positions"), QKeySequence(tr("Shift+E")),
                 tr("Draw the mechanism faintly where the chosen point (Design Checks) is at its "
                    "extremes, with the stroke"));
  connect(showExtremes, &QAction::toggled, overlays_, &DesignOverlays::setExtremesVisible);
  showTransmission =
      makeToggle(&w_, "showTransmission", tr("Transmission &Angles"), QKeySequence(tr("Shift+A")),
                 tr("Show each transmission angle at its joint, red outside the band"));
  connect(showTransmission, &QAction::toggled, overlays_, &DesignOverlays::setTransmissionVisible);
  parameterStudy = makeAction(&w_, "parameterStudy", tr("&Parameter Study..."), QKeySequence(),
                              tr("Vary one dimension over a range and compare the designs"));
  connect(parameterStudy, &QAction::triggered, this, [this] {
    StudyDialog* d = studyDialog();
    d->show();
    d->raise();
    d->activateWindow();
  });
}

void DesignFeature::makeDock() {
  panel_ = new ChecksPanel(choices_);
  panel_->setDocument(w_.document());
  dock = addDock(&w_, "designChecks", tr("Design Checks"), panel_, Qt::RightDockWidgetArea);
  // A tab beside the instant centres: under them the right side has no room for its tables.
  w_.tabifyDockWidget(w_.centres().dock, dock);
  // Computed only while seen (a tab behind the instant centres' is not: docks/dock_panel.h).
  dock->hide();
  show = raisingToggle(dock, "showDesignChecks", QKeySequence(tr("Shift+D")),
                       tr("Grashof's class of each four-bar loop, the transmission angles, the "
                          "limit positions and stroke"));
}

StudyDialog* DesignFeature::studyDialog() {
  if (!study_) study_ = new StudyDialog(w_.document(), &w_);
  return study_;
}

void DesignFeature::readSettings(const QSettings& s) {
  showExtremes->setChecked(s.value(QStringLiteral("extremes"), false).toBool());
  showTransmission->setChecked(s.value(QStringLiteral("transmission"), false).toBool());
}

void DesignFeature::writeSettings(QSettings& s) const {
  s.setValue(QStringLiteral("extremes"), showExtremes->isChecked());
  s.setValue(QStringLiteral("transmission"), showTransmission->isChecked());
}

}  // namespace linkage::ui
