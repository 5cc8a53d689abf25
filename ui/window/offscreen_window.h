// The main window without a display, set up as the command line asks: for `linkage
// --screenshot` and for the frame benchmarks (bench/editor_frames_bench.cpp), which measure in
// the same window.
#pragma once

#include <QSize>
#include <QString>

namespace linkage::ui {

class MainWindow;

struct OffscreenOptions {
  QString model;  // a file or an example's name; empty: a new document
  double angleDeg = 0;
  bool ics = false, plots = false, dark = false, forces = false, cycle = false, cam = false,
       sensitivity = false;
  // The design checks: extreme positions, transmission arcs, the design-checks dock.
  bool extremes = false, transmission = false, checks = false;
  // The picture is the 3D view alone, at `size`, isometric (from the front for a
  // planar machine) (`--3d`).
  bool view3d = false;
  // The plane the canvas shows (`--plane`; "" the drawing plane).
  QString plane;
  QSize size{1280, 800};
};

// Reads --angle and --size (either may be empty: the default); false with the reason when one
// is not valid.
bool parseOffscreen(const QString& angle, const QString& size, OffscreenOptions& o, QString* why);

// Opens the model in `w`, shows what the options ask for, shows the window, fits the mechanism
// and turns the crank to the angle. Exit status: 0, or 2 with a message on standard error (a
// model that cannot be opened, a crank angle that cannot be reached).
int setUpOffscreen(MainWindow& w, const OffscreenOptions& o);

// The 3D view alone at the options' size, of the document of `w` (set up), isometric (a
// planar machine from the front) and fitted, as it is painted: what `--3d` writes and the 3D frame
// benchmark animates.
class View3dWidget;
View3dWidget* makeOffscreen3dView(MainWindow& w, const OffscreenOptions& o);

// The window as the options set it up (or its 3D view alone, `view3d`), written to the PNG `out`.
// Exit status: 0, or 2 with a message on standard error (setUpOffscreen's, or a file that cannot be
// written).
int writeScreenshot(const OffscreenOptions& o, const QString& out);

}  // namespace linkage::ui
