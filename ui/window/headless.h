// The editor without a display: a screenshot of the main window, or frame times measured in it
// (`linkage --screenshot`, `linkage --benchmark-frames`).
#pragma once

#include <QSize>
#include <QString>

namespace linkage::ui {

struct HeadlessOptions {
  QString model;         // a file or an example's name; empty: a new document
  QString screenshot;    // PNG to write, or empty
  int frames = 0;        // frames to measure, or 0
  int dragMoves = 0;     // mouse moves of a drag to measure, or 0
  bool reshape = false;  // the drag with Ctrl held: the design changes
  double angleDeg = 0;
  bool ics = false, plots = false, dark = false, forces = false;
  // The design checks: extreme positions, transmission arcs, the design-checks dock.
  bool extremes = false, transmission = false, checks = false;
  QSize size{1280, 800};
};

// Reads the numeric options; false with the reason when one is not valid.
bool parseHeadless(const QString& frames, const QString& angle, const QString& size,
                   HeadlessOptions& o, QString* why, const QString& dragMoves = QString());

// Exit status: 0, or 2 with a message on standard error (a model that cannot be opened, a
// crank angle that cannot be reached, a file that cannot be written).
int runHeadless(const HeadlessOptions& o);

}  // namespace linkage::ui
