#include "window/export_feature.h"

#include <QAction>
#include <QDir>
#include <QFileDialog>
#include <QMessageBox>

#include "canvas/canvas_scene.h"
#include "canvas/canvas_view.h"
#include "document/document.h"
#include "document/file_folder.h"
#include "export/animation_export_dialog.h"
#include "export/motion_table_export.h"
#include "export/table_size_dialog.h"
#include "figures/figure_export.h"
#include "forces/forces_overlay.h"
#include "plots/plots_panel.h"
#include "window/main_window.h"
#include "window/message_strip.h"
#include "window/plots_feature.h"
#include "window/window_layout.h"

namespace linkage::ui {

ExportFeature::ExportFeature(MainWindow& w, WindowLayout& layout) : WindowFeature(&w), w_(w) {
  table = makeAction(&w, "exportTable", tr("Motion &Table (CSV)..."), QKeySequence(),
                     tr("Write the motion of the output points over revolutions as a CSV table"));
  connect(table, &QAction::triggered, this, &ExportFeature::exportMotionTable);
  figure = makeAction(&w, "exportFigure", tr("&Plot Figure..."), QKeySequence(),
                      tr("Write the plots as a PNG, PDF or SVG figure"));
  connect(figure, &QAction::triggered, this, &ExportFeature::exportFigure);
  animation = makeAction(&w, "exportAnimation", tr("&Animation..."), QKeySequence(),
                         tr("Write the animation as a GIF or a numbered PNG sequence"));
  connect(animation, &QAction::triggered, this, &ExportFeature::exportAnimation);
  layout.add(Slot::ExportTable, table);
  layout.add(Slot::ExportFigure, figure);
  layout.add(Slot::ExportAnimation, animation);
}

ExportFeature::~ExportFeature() = default;

void ExportFeature::exportMotionTable() {
  Document* doc = w_.document();
  if (!doc->solved()) {
    QMessageBox::warning(&w_, tr("Export"),
                         tr("The mechanism is not solved: %1")
                             .arg(QString::fromStdString(doc->solveStatus().message)));
    return;
  }
  TableSize size;
  if (!askTableSize(&w_, tr("Export Motion Table"), &size)) return;
  const QString path = QFileDialog::getSaveFileName(&w_, tr("Export Motion Table"),
                                                    suggestedFile(doc, QStringLiteral(".csv")),
                                                    tr("CSV tables (*.csv)"));
  if (path.isEmpty()) return;
  QString why;
  if (!linkage::ui::exportMotionTable(*doc, path, size.stepsPerRev, size.revs, &why))
    QMessageBox::warning(&w_, tr("Export"), why);
  else
    w_.messageStrip()->setMessage(tr("Wrote %1").arg(path), false);
}

void ExportFeature::exportFigure() {
  const QString path = QFileDialog::getSaveFileName(
      &w_, tr("Export Plot Figure"), suggestedFile(w_.document(), QStringLiteral(".svg")),
      tr("SVG (*.svg);;PDF (*.pdf);;PNG (*.png)"));
  if (path.isEmpty()) return;
  QString why;
  if (!w_.plots().panel()->exportFigure(path, QSize(1200, 900), &why))
    QMessageBox::warning(&w_, tr("Export"), why);
  else
    w_.messageStrip()->setMessage(tr("Wrote %1").arg(path), false);
}

QImage ExportFeature::renderFrame(double deg, QSize size) {
  // A scene and view of their own on this document (symbols are sized for the view that shows
  // them), fitted to the motion at the asked size, showing what the window shows.
  Document* doc = w_.document();
  if (!frameView_) {
    frameScene_ = std::make_unique<CanvasScene>();
    frameForces_ = std::make_unique<ForcesOverlay>(frameScene_.get());
    frameScene_->setDocument(doc);
    frameScene_->setPalette(w_.canvas()->palette());
    frameScene_->setCentresVisible(w_.scene()->centresVisible());
    frameScene_->setTracesVisible(w_.scene()->tracesVisible());
    frameView_ = std::make_unique<CanvasView>(frameScene_.get());
    frameView_->setGridVisible(w_.canvas()->gridVisible());
  }
  if (frameView_->size() != size) {
    frameView_->resize(size);
    frameView_->fitToMechanism();
  }
  if (doc->solved()) doc->setCrankDeg(deg);
  return frameView_->grab().toImage().convertToFormat(QImage::Format_RGB32);
}

void ExportFeature::endFrames() {
  frameView_.reset();
  frameForces_.reset();
  frameScene_.reset();
}

void ExportFeature::exportAnimation() {
  Document* doc = w_.document();
  if (!doc->solved()) {
    QMessageBox::warning(&w_, tr("Export"), tr("The mechanism is not solved"));
    return;
  }
  // The document's crank angle and the window's view are put back afterwards.
  CanvasView* view = w_.canvas();
  const double startDeg = doc->crankDeg();
  const QPointF centre = view->mapToScene(view->viewport()->rect().center());
  QString why;
  const bool ok = AnimationExportDialog::run(
      &w_, doc->kinematics().rpm(),
      [this](double deg, QSize size) { return renderFrame(deg, size); }, &why);
  endFrames();
  doc->setCrankDeg(startDeg);
  view->centerOn(centre);
  if (!ok && !why.isEmpty()) QMessageBox::warning(&w_, tr("Export"), why);
}

}  // namespace linkage::ui
