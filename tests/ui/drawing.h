// Drawing on the canvas as a user does, with mouse and key events only: tools by their keys,
// clicks at millimetre positions, Enter to end a link.
#pragma once

#include <QTest>

#include "canvas/canvas_view.h"
#include "window/features.h"

namespace linkage::ui::test {

// The window most tests start from: 1200 x 800, `example` open, shown and laid out.
inline bool showExample(MainWindow& w, const char* example) {
  w.resize(1200, 800);
  if (!w.openExample(example)) return false;
  w.show();
  QApplication::processEvents();
  return true;
}

struct Draw {
  MainWindow& w;
  QPoint at(double x, double y) const { return w.canvas()->mapFromScene(QPointF(x, y)); }
  void key(const char* k, Qt::KeyboardModifiers mods = Qt::NoModifier) const {
    QTest::keyClick(w.canvas(), QKeySequence(QString::fromLatin1(k))[0].key(), mods);
  }
  void key(Qt::Key k, Qt::KeyboardModifiers mods = Qt::NoModifier) const {
    QTest::keyClick(w.canvas(), k, mods);
  }
  void move(double x, double y, Qt::KeyboardModifiers mods = Qt::NoModifier) const {
    QMouseEvent e(QEvent::MouseMove, QPointF(at(x, y)),
                  w.canvas()->viewport()->mapToGlobal(QPointF(at(x, y))), Qt::NoButton,
                  Qt::NoButton, mods);
    QApplication::sendEvent(w.canvas()->viewport(), &e);
  }
  void click(double x, double y, Qt::KeyboardModifiers mods = Qt::NoModifier) const {
    move(x, y, mods);
    QTest::mouseClick(w.canvas()->viewport(), Qt::LeftButton, mods, at(x, y));
  }
  void rightClick(double x, double y) const {
    move(x, y);
    QTest::mouseClick(w.canvas()->viewport(), Qt::RightButton, {}, at(x, y));
  }
  // The Link tool: a click at each point, Enter.
  void link(std::initializer_list<std::pair<double, double>> points) const {
    key("L");
    for (const auto& [x, y] : points) click(x, y);
    key(Qt::Key_Return);
  }
  // A press, moves in steps and a release: a drag as a hand makes it.
  void drag(double x0, double y0, double x1, double y1, Qt::KeyboardModifiers mods = {},
            int steps = 10) const {
    move(x0, y0, mods);
    QTest::mousePress(w.canvas()->viewport(), Qt::LeftButton, mods, at(x0, y0));
    for (int i = 1; i <= steps; ++i) {
      const double t = double(i) / steps;
      const QPoint p = at(x0 + t * (x1 - x0), y0 + t * (y1 - y0));
      QMouseEvent e(QEvent::MouseMove, QPointF(p), w.canvas()->viewport()->mapToGlobal(QPointF(p)),
                    Qt::NoButton, Qt::LeftButton, mods);
      QApplication::sendEvent(w.canvas()->viewport(), &e);
      QApplication::processEvents();  // a frame: the drag solves once per frame
    }
    QTest::mouseRelease(w.canvas()->viewport(), Qt::LeftButton, mods, at(x1, y1));
  }
};

}  // namespace linkage::ui::test
