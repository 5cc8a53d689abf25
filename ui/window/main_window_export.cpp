// File > Export: the motion table, the plots' figure and the animation.
#include <QApplication>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QMessageBox>

#include "canvas/canvas_scene.h"
#include "canvas/canvas_view.h"
#include "document/document.h"
#include "export/animation_export_dialog.h"
#include "export/figure_export.h"
#include "export/motion_table_export.h"
#include "export/table_size_dialog.h"
#include "plots/plots_panel.h"
#include "window/main_window.h"

namespace linkage::ui {

namespace {

// Beside the mechanism's file (MainWindow::fileFolder), named after it.
QString suggested(const QString& folder, const Document& d, const QString& suffix) {
  QString base = d.displayName();
  base.remove(QStringLiteral(".linkage.json"));
  return QDir(folder).filePath(base + suffix);
}

}  // namespace

void MainWindow::exportMotionTable() {
  if (!doc_->solved()) {
    QMessageBox::warning(this, tr("Export"),
                         tr("The mechanism is not solved: %1")
                             .arg(QString::fromStdString(doc_->solveStatus().message)));
    return;
  }
  TableSize size;
  if (!askTableSize(this, tr("Export Motion Table"), &size)) return;
  const QString path = QFileDialog::getSaveFileName(
      this, tr("Export Motion Table"), suggested(fileFolder(), *doc_, QStringLiteral(".csv")),
      tr("CSV tables (*.csv)"));
  if (path.isEmpty()) return;
  QString why;
  if (!linkage::ui::exportMotionTable(*doc_, path, size.stepsPerRev, size.revs, &why))
    QMessageBox::warning(this, tr("Export"), why);
  else
    showMessage(tr("Wrote %1").arg(path), false);
}

void MainWindow::exportFigure() {
  const QString path = QFileDialog::getSaveFileName(
      this, tr("Export Plot Figure"), suggested(fileFolder(), *doc_, QStringLiteral(".svg")),
      tr("SVG (*.svg);;PDF (*.pdf);;PNG (*.png)"));
  if (path.isEmpty()) return;
  QString why;
  if (!plots_->exportFigure(path, QSize(1200, 900), &why))
    QMessageBox::warning(this, tr("Export"), why);
  else
    showMessage(tr("Wrote %1").arg(path), false);
}

QImage MainWindow::renderFrame(double deg, QSize size) {
  // A scene and view of their own on this document (symbols are sized for the view that shows
  // them), fitted to the motion at the asked size, showing what the window shows.
  if (!frameView_) {
    frameScene_ = std::make_unique<CanvasScene>();
    frameScene_->setDocument(doc_);
    frameScene_->setPalette(view_->palette());
    frameScene_->setCentresVisible(scene_->centresVisible());
    frameScene_->setTracesVisible(scene_->tracesVisible());
    frameView_ = std::make_unique<CanvasView>(frameScene_.get());
    frameView_->setGridVisible(view_->gridVisible());
  }
  if (frameView_->size() != size) {
    frameView_->resize(size);
    frameView_->fitToMechanism();
  }
  if (doc_->solved()) doc_->setCrankDeg(deg);
  return frameView_->grab().toImage().convertToFormat(QImage::Format_RGB32);
}

void MainWindow::endFrames() {
  frameView_.reset();
  frameScene_.reset();
}

void MainWindow::exportAnimation() {
  if (!doc_->solved()) {
    QMessageBox::warning(this, tr("Export"), tr("The mechanism is not solved"));
    return;
  }
  // The document's crank angle and the window's view are put back afterwards.
  const double startDeg = doc_->crankDeg();
  const QPointF centre = view_->mapToScene(view_->viewport()->rect().center());
  QString why;
  const bool ok = AnimationExportDialog::run(
      this, doc_->kinematics().rpm(),
      [this](double deg, QSize size) { return renderFrame(deg, size); }, &why);
  endFrames();
  doc_->setCrankDeg(startDeg);
  view_->centerOn(centre);
  if (!ok && !why.isEmpty()) QMessageBox::warning(this, tr("Export"), why);
}

}  // namespace linkage::ui
