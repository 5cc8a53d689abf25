#include "window/offscreen_window.h"

#include <QAction>
#include <QCoreApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QImage>
#include <QRegularExpression>
#include <QThread>
#include <cmath>
#include <cstdio>
#include <memory>

#include "canvas/canvas_scene.h"
#include "canvas/canvas_view.h"
#include "document/document.h"
#include "linkage/space.h"
#include "view3d/view3d_widget.h"
#include "window/cam_feature.h"
#include "window/centres_feature.h"
#include "window/cycle_feature.h"
#include "window/design_feature.h"
#include "window/forces_feature.h"
#include "window/main_window.h"
#include "window/plots_feature.h"
#include "window/sensitivity_feature.h"
#include "window/tools_feature.h"
#include "window/view3d_feature.h"
#include "window/view_feature.h"

namespace linkage::ui {

bool parseOffscreen(const QString& angle, const QString& size, OffscreenOptions& o, QString* why) {
  bool ok = true;
  if (!angle.isEmpty()) {
    o.angleDeg = angle.toDouble(&ok);
    if (!ok || !std::isfinite(o.angleDeg)) {
      *why = QStringLiteral("--angle: \"%1\" is not a number").arg(angle);
      return false;
    }
  }
  if (!size.isEmpty()) {
    const auto m = QRegularExpression(QStringLiteral("^(\\d+)x(\\d+)$")).match(size);
    if (!m.hasMatch() || m.captured(1).toInt() < 200 || m.captured(2).toInt() < 150 ||
        m.captured(1).toInt() > 8000 || m.captured(2).toInt() > 8000) {
      *why = QStringLiteral("--size: \"%1\" is not WxH between 200x150 and 8000x8000").arg(size);
      return false;
    }
    o.size = QSize(m.captured(1).toInt(), m.captured(2).toInt());
  }
  return true;
}

namespace {

void settle() {
  for (int i = 0; i < 3; ++i) QCoreApplication::processEvents();
}

// The overlays and docks the options ask for.
void showAsked(MainWindow& w, const OffscreenOptions& o) {
  w.centres().show->setChecked(o.ics);
  w.forces().show->setChecked(o.forces);
  if (o.forces) {
    w.forces().dock->show();
    w.forces().dock->raise();
  }
  if (o.cycle) {
    w.cycle().dock->show();
    w.cycle().dock->raise();
  }
  if (o.sensitivity) {
    w.sensitivity().dock->show();
    w.sensitivity().dock->raise();
  }
  if (o.cam) {
    w.cams().dock->show();
    w.cams().dock->raise();
  }
  if (o.ics) w.centres().dock->raise();
  w.plots().dock->setVisible(o.plots);
  w.designChecks().showExtremes->setChecked(o.extremes);
  w.designChecks().showTransmission->setChecked(o.transmission);
  if (o.checks) w.designChecks().show->trigger();
}

}  // namespace

int setUpOffscreen(MainWindow& w, const OffscreenOptions& o) {
  w.resize(o.size);
  if (o.dark) w.view().darkPalette->setChecked(true);
  QString why;
  if (!o.model.isEmpty() && !w.openNameOrPath(o.model, &why)) {
    std::fprintf(stderr, "linkage: %s\n", qPrintable(why));
    return 2;
  }
  showAsked(w, o);
  if (!o.plane.isEmpty()) {
    const Mechanism& m = w.document()->design();
    if (o.plane != QStringLiteral("drawing") && !planeNamed(m, o.plane.toStdString())) {
      std::fprintf(stderr, "linkage: --plane: the model has no plane \"%s\"\n",
                   qPrintable(o.plane));
      return 2;
    }
    w.view3d().choosePlane(o.plane.toStdString());
  }
  w.show();
  settle();
  w.canvas()->fitToMechanism();
  Document* d = w.document();
  if (o.angleDeg != 0 && d->solved()) {
    const Status s = d->setCrankDeg(o.angleDeg);
    if (!s.ok()) {
      std::fprintf(stderr, "linkage: %s\n", s.message.c_str());
      return 2;
    }
  }
  // Panels that throttle their text (the chain of centres, at most ten a second) catch up with
  // the last pose: a picture is of one pose.
  QElapsedTimer waited;
  waited.start();
  while (waited.elapsed() < 150) {
    QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
    QThread::msleep(5);
  }
  return 0;
}

View3dWidget* makeOffscreen3dView(MainWindow& w, const OffscreenOptions& o) {
  auto* v = new View3dWidget;
  v->setAttribute(Qt::WA_DeleteOnClose);
  v->setDocument(w.document());
  v->setSelection(w.tools().selection());
  v->setPlane(w.scene()->shownPlane());
  v->resize(o.size);
  v->showView(isSpatial(w.document()->design()) ? Projection::View::Isometric
                                                : Projection::View::Front);
  v->show();
  settle();
  return v;
}

int writeScreenshot(const OffscreenOptions& o, const QString& out) {
  MainWindow w;
  if (const int status = setUpOffscreen(w, o)) return status;

  QImage img;
  if (o.view3d) {
    std::unique_ptr<View3dWidget> v(makeOffscreen3dView(w, o));
    img = v->grab().toImage();
  } else {
    img = w.grab().toImage();
  }
  if (!img.save(out, "PNG")) {
    std::fprintf(stderr, "linkage: cannot write %s\n", qPrintable(out));
    return 2;
  }
  return 0;
}

}  // namespace linkage::ui
