// How the canvas looks: symbol sizes in screen pixels (kept constant at any zoom, so a pin is a
// pin whether the view shows a needle bar or a loom), and colours that read on light and dark
// palettes alike.
#pragma once

#include <QColor>
#include <QPalette>

namespace linkage::ui {

struct CanvasStyle {
  // Pixels.
  static constexpr double barWidth = 11;
  static constexpr double pinRadius = 4.5;
  static constexpr double pointRadius = 2.2;
  static constexpr double channelWidth = 9;
  static constexpr double blockLength = 24;
  static constexpr double blockWidth = 14;
  static constexpr double pivotSize = 15;
  static constexpr double driverRadius = 20;
  static constexpr double outputRadius = 5;
  static constexpr double centreRadius = 4;
  // Outlines one pixel wide: the raster engine strokes those on its fast path (wider pens are
  // stroked by filling their outline, which cost most of a frame).
  static constexpr double outline = 1.0;

  bool dark = false;
  QColor paper, ink, faint, grid, gridMajor, highlight, warning, centre, kennedyCentre,
      velocityCentre, trace;

  static CanvasStyle fromPalette(const QPalette& p);
  // Each body its own colour, by textbook number (ground 1 is grey): hues spread by the golden
  // angle so that neighbours in number differ, saturation and value set for the palette.
  QColor body(int number) const;
  QColor bodyFill(int number) const;
};

}  // namespace linkage::ui
