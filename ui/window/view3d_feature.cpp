#include "window/view3d_feature.h"

#include <QAction>
#include <QComboBox>
#include <QDockWidget>
#include <QMenu>
#include <QSettings>
#include <QToolBar>
#include <QVBoxLayout>

#include "canvas/canvas_scene.h"
#include "document/commands.h"
#include "document/document.h"
#include "linkage/edits.h"
#include "linkage/elements.h"
#include "linkage/space.h"
#include "tools/selection.h"
#include "view3d/add_plane_dialog.h"
#include "view3d/view3d_widget.h"
#include "window/main_window.h"
#include "window/message_strip.h"
#include "window/properties_feature.h"
#include "window/tools_feature.h"
#include "window/window_layout.h"

namespace linkage::ui {

View3dFeature::View3dFeature(MainWindow& w, WindowLayout& layout) : WindowFeature(&w) {
  auto* panel = new QWidget;
  auto* box = new QVBoxLayout(panel);
  box->setContentsMargins(0, 0, 0, 0);
  box->setSpacing(0);
  auto* bar = new QToolBar(tr("3D View"), panel);
  bar->setObjectName(QStringLiteral("view3dToolBar"));
  bar->setToolButtonStyle(Qt::ToolButtonTextOnly);
  view_ = new View3dWidget(panel);
  view_->setDocument(w.document());
  view_->setSelection(w.tools().selection());
  box->addWidget(bar);
  box->addWidget(view_, 1);
  dock = addDock(&w, "view3d", tr("3D View"), panel, Qt::RightDockWidgetArea);
  // Beside the Properties (the canvas keeps the middle); hidden until asked for.
  w.tabifyDockWidget(w.properties().dock, dock);
  dock->hide();
  show = raisingToggle(dock, "show3dView", QKeySequence(tr("Shift+V")),
                       tr("Show the machine in space: every plane's bodies and the ball rods"));
  makeViewActions(w);
  for (QAction* a : {front, top, side, isometric, alongPlane, fit}) bar->addAction(a);
  QMenu* directions = layout.addMenu(Slot::View3dDirections, tr("3D View &Direction"));
  for (QAction* a : {front, top, side, isometric, alongPlane, fit}) directions->addAction(a);
  layout.add(Slot::View3dDock, show);

  planeChooser = new QComboBox;
  planeChooser->setObjectName(QStringLiteral("planeChooser"));
  planeChooser->setToolTip(tr("The plane the canvas draws and edits"));
  planeChooser->setStatusTip(
      tr("Choose the plane the canvas draws and edits; new bodies go in it"));
  planeChooserAction = layout.addWidget(Slot::ViewBarPlane, planeChooser);
  hideOtherPlanes = makeToggle(&w, "hideOtherPlanes", tr("&Hide Other Planes"), QKeySequence(),
                               tr("Draw only the bodies of the plane the canvas edits (the "
                                  "others are faint otherwise)"));
  layout.add(Slot::ViewHideOtherPlanes, hideOtherPlanes);
  connect(hideOtherPlanes, &QAction::toggled, w.scene(), &CanvasScene::setOtherPlanesHidden);
  connect(planeChooser, &QComboBox::currentIndexChanged, this, [this](int i) {
    if (i >= 0) choosePlane(planeChooser->itemData(i).toString().toStdString());
  });
  connect(view_, &View3dWidget::bodyPicked, this, [this, &w](BodyId b) {
    if (const Body* body = w.document()->design().body(b); body && !body->ground)
      choosePlane(body->plane);
  });
  addPlane = makeAction(&w, "addPlane", tr("Add &Plane..."), QKeySequence(tr("Shift+P")),
                        tr("Add a plane for a machine in space: typed, square to a shaft, or "
                           "inclined about x"));
  connect(addPlane, &QAction::triggered, this, [this, &w] { askForPlane(w); });
  layout.add(Slot::EditAddPlane, addPlane);
  addBallRod =
      makeAction(&w, "addBallRod", tr("Join with a &Ball Rod"), QKeySequence(tr("Shift+R")),
                 tr("A rod with a ball at each end between the two points selected "
                    "(Ctrl+click them in the 3D view: any planes)"));
  connect(addBallRod, &QAction::triggered, this, [this, &w] { joinWithBallRod(w); });
  layout.add(Slot::EditBallRod, addBallRod);
  auto twoPoints = [this, &w] {
    const Selection* s = w.tools().selection();
    addBallRod->setEnabled(s->points.size() == 2 && s->size() == 2);
  };
  connect(w.tools().selection(), &Selection::changed, this, twoPoints);
  twoPoints();
  connect(w.document(), &Document::designChanged, this, [this, &w] { listPlanes(w); });
  listPlanes(w);
}

void View3dFeature::makeViewActions(MainWindow& w) {
  auto view = [this, &w](const char* name, const QString& text, const char* key, const QString& tip,
                         Projection::View v) {
    QAction* a = makeAction(&w, name, text, QKeySequence(tr(key)), tip);
    connect(a, &QAction::triggered, view_, [this, v] {
      dock->show();
      view_->showView(v);
    });
    return a;
  };
  front = view("view3dFront", tr("&Front"), "Alt+1",
               tr("3D view from the front: the drawing plane as drawn (x right, y up)"),
               Projection::View::Front);
  top = view("view3dTop", tr("&Top"), "Alt+2", tr("3D view from above (x right, z down)"),
             Projection::View::Top);
  side = view("view3dSide", tr("&Side"), "Alt+3", tr("3D view from the right side (z left, y up)"),
              Projection::View::Side);
  isometric = view("view3dIsometric", tr("&Isometric"), "Alt+4",
                   tr("3D view from (1, 1, 1): x, y and z foreshortened alike"),
                   Projection::View::Isometric);
  alongPlane =
      makeAction(&w, "view3dAlongPlane", tr("&Along the Plane's Normal"), QKeySequence(tr("Alt+5")),
                 tr("3D view square onto the plane the canvas edits, its x right"));
  connect(alongPlane, &QAction::triggered, view_, [this] {
    dock->show();
    view_->showAlongPlane();
  });
  fit = makeAction(&w, "view3dFit", tr("Fit &3D View"), QKeySequence(tr("Alt+0")),
                   tr("The whole machine in the 3D view, from where it is seen now"));
  connect(fit, &QAction::triggered, view_, &View3dWidget::fit);
}

void View3dFeature::listPlanes(MainWindow& w) {
  const Mechanism& m = w.document()->design();
  const QString chosen = QString::fromStdString(w.scene()->shownPlane());
  QSignalBlocker quiet(planeChooser);
  planeChooser->clear();
  planeChooser->addItem(tr("drawing"), QString());
  if (m.planes)
    for (const Plane& p : *m.planes)
      planeChooser->addItem(QString::fromStdString(p.name), QString::fromStdString(p.name));
  const int at = planeChooser->findData(chosen);
  planeChooser->setCurrentIndex(at >= 0 ? at : 0);
  // A plane no longer there (another file, an undo): the drawing plane.
  if (at < 0) choosePlane({});
  planeChooserAction->setVisible(isSpatial(m));
  hideOtherPlanes->setEnabled(isSpatial(m));
}

void View3dFeature::askForPlane(MainWindow& w) {
  Document* doc = w.document();
  AddPlaneDialog d(doc->design(), &w);
  if (d.exec() != QDialog::Accepted) return;
  std::string why;
  const std::optional<Plane> p = d.plane(&why);
  Mechanism m = doc->design();
  if (!p || !linkage::addPlane(m, *p, &why)) return;  // the dialog checked it
  commitEdit(doc, tr("Add plane %1").arg(QString::fromStdString(p->name)), std::move(m));
  choosePlane(p->name);
}

void View3dFeature::joinWithBallRod(MainWindow& w) {
  const Selection* s = w.tools().selection();
  if (s->points.size() != 2) return;
  Document* doc = w.document();
  Mechanism m = doc->design();
  std::string why;
  const JointId rod = linkage::addBallRod(m, s->points[0], s->points[1], &why);
  if (!rod) {
    w.messageStrip()->setMessage(QString::fromStdString(why), true);
    return;
  }
  const QString name = QString::fromStdString(jointName(m, rod));
  commitEdit(doc, tr("Add %1").arg(name), std::move(m));
}

void View3dFeature::choosePlane(const std::string& name) {
  const std::string plane = name == "drawing" ? std::string() : name;
  auto* w = static_cast<MainWindow*>(parent());
  w->scene()->setShownPlane(plane);
  view_->setPlane(plane);
  const int at = planeChooser->findData(QString::fromStdString(plane));
  if (at >= 0 && at != planeChooser->currentIndex()) {
    QSignalBlocker quiet(planeChooser);
    planeChooser->setCurrentIndex(at);
  }
}

void View3dFeature::readSettings(const QSettings& s) {
  hideOtherPlanes->setChecked(s.value(QStringLiteral("hideOtherPlanes"), false).toBool());
}

void View3dFeature::writeSettings(QSettings& s) const {
  s.setValue(QStringLiteral("hideOtherPlanes"), hideOtherPlanes->isChecked());
}

}  // namespace linkage::ui
