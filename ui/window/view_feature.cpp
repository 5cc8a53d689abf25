#include "window/view_feature.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QSettings>
#include <QStyle>

#include "canvas/canvas_scene.h"
#include "canvas/canvas_view.h"
#include "window/icons.h"
#include "window/main_window.h"
#include "window/window_layout.h"

namespace linkage::ui {

ViewFeature::ViewFeature(MainWindow& w, WindowLayout& layout) : WindowFeature(&w) {
  makeZoomActions(w);
  showGrid = makeToggle(&w, "showGrid", tr("&Grid"), QKeySequence(tr("#")),
                        tr("Show the millimetre grid"));
  connect(showGrid, &QAction::toggled, w.canvas(), &CanvasView::setGridVisible);
  showTraces = makeToggle(&w, "showTraces", tr("&Traced Paths"), QKeySequence(tr("Shift+T")),
                          tr("Show the paths of the output points over a revolution"));
  connect(showTraces, &QAction::toggled, w.scene(), &CanvasScene::setTracesVisible);
  darkPalette = makeToggle(&w, "darkPalette", tr("&Dark Palette"), QKeySequence(),
                           tr("Light text on a dark background, for every window"));
  connect(darkPalette, &QAction::toggled, this, &ViewFeature::setDarkPalette);
  detachablePanels = makeToggle(&w, "detachablePanels", tr("&Detachable Panels"), QKeySequence(),
                                tr("Let the panels float out of the window"));
  connect(detachablePanels, &QAction::toggled, this, [&w](bool on) {
    for (QDockWidget* d : w.findChildren<QDockWidget*>())
      d->setFeatures(d->features().setFlag(QDockWidget::DockWidgetFloatable, on));
  });
  layout.add(Slot::ViewFit, fit);
  layout.add(Slot::ViewZoomIn, zoomIn);
  layout.add(Slot::ViewZoomOut, zoomOut);
  layout.add(Slot::ViewActualSize, actualSize);
  layout.add(Slot::ViewGrid, showGrid);
  layout.add(Slot::ViewTraces, showTraces);
  layout.add(Slot::ViewDark, darkPalette);
  layout.add(Slot::ViewDetachable, detachablePanels);
  layout.add(Slot::ViewBarFit, fit);
  layout.add(Slot::ViewBarGrid, showGrid);
  layout.add(Slot::ViewBarTraces, showTraces);
}

void ViewFeature::makeZoomActions(MainWindow& w) {
  CanvasView* view = w.canvas();
  fit = makeAction(&w, "fit", tr("&Fit to View"), QKeySequence(tr("F")),
                   tr("Show the whole mechanism"));
  connect(fit, &QAction::triggered, view, &CanvasView::fitToMechanism);
  zoomIn = makeAction(&w, "zoomIn", tr("Zoom &In"), QKeySequence::ZoomIn, tr("Zoom in"));
  connect(zoomIn, &QAction::triggered, view, [view] { view->zoomBy(1.25); });
  zoomOut = makeAction(&w, "zoomOut", tr("Zoom &Out"), QKeySequence::ZoomOut, tr("Zoom out"));
  connect(zoomOut, &QAction::triggered, view, [view] { view->zoomBy(0.8); });
  actualSize = makeAction(&w, "actualSize", tr("&Actual Size"), QKeySequence(tr("Ctrl+1")),
                          tr("A millimetre on the screen for a millimetre of the mechanism"));
  connect(actualSize, &QAction::triggered, view,
          [view] { view->zoomBy(view->actualSizeZoom() / view->zoom()); });
}

void ViewFeature::applyIcons(const QPalette& p) {
  fit->setIcon(themedIcon(QStringLiteral("fit"), p));
  showGrid->setIcon(themedIcon(QStringLiteral("grid"), p));
  showTraces->setIcon(themedIcon(QStringLiteral("traces"), p));
}

void ViewFeature::readSettings(const QSettings& s) {
  showGrid->setChecked(s.value(QStringLiteral("grid"), true).toBool());
  showTraces->setChecked(s.value(QStringLiteral("traces"), true).toBool());
  darkPalette->setChecked(s.value(QStringLiteral("dark"), false).toBool());
  detachablePanels->setChecked(s.value(QStringLiteral("detachable"), false).toBool());
}

void ViewFeature::writeSettings(QSettings& s) const {
  s.setValue(QStringLiteral("grid"), showGrid->isChecked());
  s.setValue(QStringLiteral("traces"), showTraces->isChecked());
  s.setValue(QStringLiteral("dark"), darkPalette->isChecked());
  s.setValue(QStringLiteral("detachable"), detachablePanels->isChecked());
}

void ViewFeature::setDarkPalette(bool on) {
  if (on) {
    QPalette p;
    p.setColor(QPalette::Window, QColor(45, 45, 48));
    p.setColor(QPalette::WindowText, QColor(225, 225, 225));
    p.setColor(QPalette::Base, QColor(30, 30, 32));
    p.setColor(QPalette::AlternateBase, QColor(45, 45, 48));
    p.setColor(QPalette::Text, QColor(230, 230, 230));
    p.setColor(QPalette::Button, QColor(55, 55, 58));
    p.setColor(QPalette::ButtonText, QColor(225, 225, 225));
    p.setColor(QPalette::Highlight, QColor(60, 130, 220));
    p.setColor(QPalette::HighlightedText, Qt::white);
    p.setColor(QPalette::ToolTipBase, QColor(60, 60, 64));
    p.setColor(QPalette::ToolTipText, QColor(230, 230, 230));
    p.setColor(QPalette::PlaceholderText, QColor(150, 150, 150));
    for (auto role : {QPalette::WindowText, QPalette::Text, QPalette::ButtonText})
      p.setColor(QPalette::Disabled, role, QColor(120, 120, 120));
    QApplication::setPalette(p);
  } else {
    QApplication::setPalette(QApplication::style()->standardPalette());
  }
  for (MainWindow* w : MainWindow::windows()) {
    w->view().darkPalette->setChecked(on);
    w->scene()->setPalette(w->canvas()->palette());
    w->canvas()->resetCachedContent();
  }
}

}  // namespace linkage::ui
