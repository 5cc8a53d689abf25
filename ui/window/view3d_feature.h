// Machines in space (issue 27): the 3D View dock (View > 3D View, Shift+V) with its standard
// views (front, top, side, isometric, along the plane the canvas edits) in its toolbar and in
// View > 3D View Direction, and the plane chooser in the View toolbar: which plane the canvas
// draws and edits (the others faint, or hidden by View > Hide Other Planes). The chooser is
// shown only for a machine with planes. A body picked in the 3D view brings its plane to the
// canvas. Edit > Add Plane (Shift+P) adds a plane (view3d/add_plane_dialog.h);
// Edit > Join with a Ball Rod (Shift+R) joins the two points selected (picked in the 3D view with
// Ctrl+click, any planes).
#pragma once

#include <string>

#include "window/window_feature.h"

class QComboBox;

namespace linkage::ui {

class MainWindow;
class View3dWidget;
class WindowLayout;

class View3dFeature : public WindowFeature {
 public:
  View3dFeature(MainWindow& w, WindowLayout& layout);
  void readSettings(const QSettings& s) override;
  void writeSettings(QSettings& s) const override;

  View3dWidget* view() const { return view_; }
  // The plane the canvas shows ("" the drawing plane), as the chooser sets it.
  void choosePlane(const std::string& name);

  QDockWidget* dock;
  QAction* show;  // the dock
  QAction* front;
  QAction* top;
  QAction* side;
  QAction* isometric;
  QAction* alongPlane;
  QAction* fit;
  QComboBox* planeChooser;
  QAction* planeChooserAction;  // its place in the toolbar (hidden for a planar machine)
  QAction* hideOtherPlanes;
  QAction* addPlane;  // Edit > Add Plane: the dialog, then one undo step
  // Edit > Join with a Ball Rod: the two points selected (in the 3D view, or on the canvas),
  // of any planes.
  QAction* addBallRod;

 private:
  void makeViewActions(MainWindow& w);
  // The chooser lists the design's planes again (after a new file or an edit).
  void listPlanes(MainWindow& w);
  // Edit > Add Plane: asks, adds it as one undo step and shows it on the canvas.
  void askForPlane(MainWindow& w);
  void joinWithBallRod(MainWindow& w);

  View3dWidget* view_;
};

}  // namespace linkage::ui
