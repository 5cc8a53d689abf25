// The machine in space (issue 27): every plane's bodies as plates, the ball rods, the ground's
// points and shaft axes, where the solver has them now, drawn with QPainter (Qt 3D cannot make
// its OpenGL context on the offscreen platform the screenshots and CI use) in an orthographic
// projection, far things first (the painter's algorithm), plates paler with distance. It follows
// the Document as the canvas does (every pose of the animation) and picks into the window's
// Selection as the canvas does.
//
// Mouse: left-drag orbits, middle-drag or Shift+left-drag pans, the wheel zooms about the
// cursor; a click picks a point, a rod or a body (Ctrl+click adds to or takes from the
// selection), a click on nothing clears it.
#pragma once

#include <QPointer>
#include <QWidget>
#include <optional>
#include <string>

#include "linkage/model.h"
#include "view3d/projection.h"
#include "view3d/scene3d.h"

namespace linkage::ui {

class Document;
class Selection;

class View3dWidget : public QWidget {
  Q_OBJECT

 public:
  explicit View3dWidget(QWidget* parent = nullptr);

  void setDocument(Document* doc);
  void setSelection(Selection* selection);
  // The plane the canvas edits ("" the drawing plane): outlined, its region shaded.
  void setPlane(const std::string& name);
  const std::string& plane() const { return plane_; }

  // A standard view, the whole machine fitted in it.
  void showView(Projection::View v);
  // Along the normal of the plane the canvas edits, its x to the right (as the canvas shows it).
  void showAlongPlane();
  // The whole machine in view, the direction kept.
  void fit();

  Projection& projection() { return proj_; }
  const Projection& projection() const { return proj_; }
  // What is drawn at the document's pose now (the solver's, or the drawing's when the solver
  // does not hold the design).
  Scene3d scene() const;

  // What a click at `px` picks (the nearest thing in front): a point, else a rod, else a body.
  struct Picked {
    PointId point;
    JointId joint;
    BodyId body;
    bool empty() const { return !point && !joint && !body; }
  };
  Picked pickAt(const QPointF& px) const;

  QSize sizeHint() const override { return {480, 360}; }

 Q_SIGNALS:
  // A body was picked (or the body of a picked point): its plane may become the canvas's.
  void bodyPicked(BodyId body);

 protected:
  void paintEvent(QPaintEvent*) override;
  void resizeEvent(QResizeEvent*) override;
  void mousePressEvent(QMouseEvent* e) override;
  void mouseMoveEvent(QMouseEvent* e) override;
  void mouseReleaseEvent(QMouseEvent* e) override;
  void wheelEvent(QWheelEvent* e) override;

 private:
  void fitIfAsked(const Scene3d& s);
  void select(const Picked& p, bool toggle);

  QPointer<Document> doc_;
  QPointer<Selection> selection_;
  std::string plane_;
  Projection proj_;
  bool fitAsked_ = true;
  enum class Drag { None, Orbit, Pan } drag_ = Drag::None;
  QPointF pressAt_, lastAt_;
  bool moved_ = false;
};

}  // namespace linkage::ui
