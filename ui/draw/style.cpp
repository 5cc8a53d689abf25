#include "draw/style.h"

#include <cmath>

namespace linkage::ui {

CanvasStyle CanvasStyle::fromPalette(const QPalette& p) {
  CanvasStyle s;
  s.paper = p.color(QPalette::Base);
  s.ink = p.color(QPalette::Text);
  s.dark = s.paper.lightnessF() < 0.5;
  s.faint = s.ink;
  s.faint.setAlphaF(0.35);
  s.grid = s.ink;
  s.grid.setAlphaF(s.dark ? 0.10 : 0.07);
  s.gridMajor = s.ink;
  s.gridMajor.setAlphaF(s.dark ? 0.22 : 0.16);
  s.highlight = p.color(QPalette::Highlight);
  s.warning = s.dark ? QColor(255, 90, 80) : QColor(210, 30, 20);
  s.centre = s.dark ? QColor(255, 200, 60) : QColor(200, 110, 0);
  s.kennedyCentre = s.dark ? QColor(120, 200, 255) : QColor(0, 100, 200);
  s.velocityCentre = s.dark ? QColor(200, 160, 255) : QColor(120, 60, 180);
  s.trace = s.dark ? QColor(255, 140, 200) : QColor(200, 0, 110);
  return s;
}

QColor CanvasStyle::body(int number) const {
  if (number <= 1) return dark ? QColor(170, 170, 170) : QColor(90, 90, 90);
  const double hue = std::fmod(0.58 + (number - 2) * 0.381966, 1.0);
  return QColor::fromHsvF(hue, dark ? 0.55 : 0.75, dark ? 0.95 : 0.70);
}

QColor CanvasStyle::bodyFill(int number) const {
  QColor c = body(number);
  c.setAlphaF(dark ? 0.30 : 0.22);
  return c;
}

}  // namespace linkage::ui
