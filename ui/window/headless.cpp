#include "window/headless.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QImage>
#include <QRegularExpression>
#include <algorithm>
#include <cstdio>
#include <vector>

#include <QMouseEvent>
#include <cmath>

#include "canvas/canvas_view.h"
#include "document/document.h"
#include "window/features.h"

namespace linkage::ui {

bool parseHeadless(const QString& frames, const QString& angle, const QString& size,
                   HeadlessOptions& o, QString* why, const QString& dragMoves) {
  bool ok = true;
  if (!dragMoves.isEmpty()) {
    o.dragMoves = dragMoves.toInt(&ok);
    if (!ok || o.dragMoves < 1) {
      *why =
          QStringLiteral("--benchmark-drag: \"%1\" is not a whole number of moves").arg(dragMoves);
      return false;
    }
  }
  if (!frames.isEmpty()) {
    o.frames = frames.toInt(&ok);
    if (!ok || o.frames < 1) {
      *why =
          QStringLiteral("--benchmark-frames: \"%1\" is not a whole number of frames").arg(frames);
      return false;
    }
  }
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

struct PaintCounter : QObject {
  int paints = 0;
  bool eventFilter(QObject*, QEvent* e) override {
    if (e->type() == QEvent::Paint) ++paints;
    return false;
  }
};

void settle() {
  for (int i = 0; i < 3; ++i) QCoreApplication::processEvents();
}

double percentile(std::vector<double> v, double p) {
  std::sort(v.begin(), v.end());
  const size_t i = std::min(v.size() - 1, static_cast<size_t>(p * (v.size() - 1) + 0.5));
  return v[i];
}

// Mouse moves of a drag of the first output point in the real window, each measured from the
// move event to the redrawn frame: the event handled, the mechanism solved (the crank turned,
// or with Ctrl the design changed and re-solved), the canvas, docks and plots brought up to
// date and painted by the event loop, until nothing is left to do.
int benchmarkDrag(MainWindow& w, const HeadlessOptions& o) {
  Document* d = w.document();
  if (!d->solved() || d->design().outputs.empty()) {
    std::fprintf(stderr,
                 "linkage: --benchmark-drag needs a solved mechanism with an output point\n");
    return 2;
  }
  CanvasView* v = w.canvas();
  QWidget* port = v->viewport();
  const Qt::KeyboardModifiers mods = o.reshape ? Qt::ControlModifier : Qt::NoModifier;
  const Vec2 start = d->kinematics().position(d->design().outputs[0]);
  auto send = [&](QEvent::Type type, const Vec2& at, Qt::MouseButton b, Qt::MouseButtons bs) {
    const QPointF p = v->mapFromScene(QPointF(at.x(), at.y()));
    QMouseEvent e(type, p, port->mapToGlobal(p), b, bs, mods);
    QApplication::sendEvent(port, &e);
  };
  auto drain = [] {
    for (int i = 0; i < 4; ++i) QCoreApplication::processEvents();
  };
  send(QEvent::MouseMove, start, Qt::NoButton, Qt::NoButton);
  send(QEvent::MouseButtonPress, start, Qt::LeftButton, Qt::LeftButton);
  drain();
  // A circle of a tenth of the mechanism's size about where the point was: the crank turns to
  // follow (or, with Ctrl, the point is moved in its link).
  const double r = 0.1 * d->kinematics().size();
  std::vector<double> ms;
  QElapsedTimer t;
  for (int i = 1; i <= o.dragMoves; ++i) {
    const double a = 2 * M_PI * i / std::max(o.dragMoves, 60);
    const Vec2 at = start + r * Vec2(std::sin(a), 1 - std::cos(a));
    t.start();
    send(QEvent::MouseMove, at, Qt::NoButton, Qt::LeftButton);
    drain();
    ms.push_back(t.nsecsElapsed() * 1e-6);
  }
  send(QEvent::MouseButtonRelease, start, Qt::LeftButton, Qt::NoButton);
  drain();
  std::printf("drag %s moves %d median_ms %.3f p99_ms %.3f max_ms %.3f\n",
              o.reshape ? "design" : "motion", o.dragMoves, percentile(ms, 0.5),
              percentile(ms, 0.99), *std::max_element(ms.begin(), ms.end()));
  return 0;
}

}  // namespace

int runHeadless(const HeadlessOptions& o) {
  MainWindow w;
  w.resize(o.size);
  if (o.dark) w.view().darkPalette->setChecked(true);
  QString why;
  if (!o.model.isEmpty() && !w.openNameOrPath(o.model, &why)) {
    std::fprintf(stderr, "linkage: %s\n", qPrintable(why));
    return 2;
  }
  w.centres().show->setChecked(o.ics);
  w.forces().show->setChecked(o.forces);
  if (o.forces) {
    w.forces().dock->show();
    w.forces().dock->raise();
  }
  if (o.ics) w.centres().dock->raise();
  w.plots().dock->setVisible(o.plots);
  w.designChecks().showExtremes->setChecked(o.extremes);
  w.designChecks().showTransmission->setChecked(o.transmission);
  if (o.checks) w.designChecks().show->trigger();
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
  settle();
  if (!o.screenshot.isEmpty()) {
    const QImage img = w.grab().toImage();
    if (!img.save(o.screenshot, "PNG")) {
      std::fprintf(stderr, "linkage: cannot write %s\n", qPrintable(o.screenshot));
      return 2;
    }
  }
  if (o.frames > 0) {
    if (!d->solved()) {
      std::fprintf(stderr, "linkage: the mechanism is not solved: %s\n",
                   d->solveStatus().message.c_str());
      return 2;
    }
    // Each frame as the running editor makes it: the solve to the next crank angle (2 degrees
    // on, a frame of the Wanzer at x1/10 of 240 rpm and 60 frames a second), the scene and the
    // docks updated, then the event loop paints every widget that changed and flushes the
    // window. Paints of the canvas are counted, to prove each frame was drawn.
    PaintCounter canvasPaints;
    w.canvas()->viewport()->installEventFilter(&canvasPaints);
    std::vector<double> ms;
    ms.reserve(o.frames);
    QElapsedTimer t;
    double deg = d->crankDeg();
    for (int f = 0; f < o.frames; ++f) {
      t.start();
      deg += 2.0;
      if (!d->setCrankDeg(deg).ok()) deg = d->crankDeg();
      QCoreApplication::processEvents();
      ms.push_back(t.nsecsElapsed() * 1e-6);
    }
    if (canvasPaints.paints < o.frames) {
      std::fprintf(stderr, "linkage: only %d of %d frames were painted\n", canvasPaints.paints,
                   o.frames);
      return 2;
    }
    std::printf("frames %d median_ms %.3f p99_ms %.3f max_ms %.3f\n", o.frames, percentile(ms, 0.5),
                percentile(ms, 0.99), *std::max_element(ms.begin(), ms.end()));
  }
  if (o.dragMoves > 0) return benchmarkDrag(w, o);
  return 0;
}

}  // namespace linkage::ui
