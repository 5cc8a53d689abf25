#include "view3d/view3d_widget.h"

#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>
#include <cmath>

#include "document/document.h"
#include "linkage/space.h"
#include "tools/selection.h"
#include "view3d/scene3d_painter.h"

namespace linkage::ui {

namespace {

double distanceToSegment(const QPointF& p, const QPointF& a, const QPointF& b) {
  const QPointF ab = b - a;
  const double len2 = QPointF::dotProduct(ab, ab);
  const double t = len2 > 0 ? std::clamp(QPointF::dotProduct(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  const QPointF d = p - (a + t * ab);
  return std::hypot(d.x(), d.y());
}

constexpr double kPointReach = 7, kRodReach = 5, kBarReach = CanvasStyle::barWidth / 2 + 2;

}  // namespace

View3dWidget::View3dWidget(QWidget* parent) : QWidget(parent) {
  setObjectName(QStringLiteral("view3d"));
  setAttribute(Qt::WA_OpaquePaintEvent);
  setMouseTracking(false);
  setFocusPolicy(Qt::ClickFocus);
  setMinimumSize(160, 120);
  // Isometric at first: a machine in space shows its depth, a planar one still reads.
  proj_.setRotation(Projection::rotationOf(Projection::View::Isometric));
  setToolTip(
      tr("Left-drag orbits, middle- or Shift+left-drag pans, the wheel zooms; click "
         "picks a body or point"));
}

void View3dWidget::setDocument(Document* doc) {
  if (doc_) disconnect(doc_, nullptr, this, nullptr);
  doc_ = doc;
  fitAsked_ = true;
  if (doc_) {
    // Every pose of the animation, every edit: painted again when seen (update() of a hidden
    // widget does nothing).
    connect(doc_, &Document::poseChanged, this, qOverload<>(&QWidget::update));
    connect(doc_, &Document::designChanged, this, qOverload<>(&QWidget::update));
    connect(doc_, &Document::contentsReplaced, this, [this] {
      // Another machine: a planar one as drawn (from the front), one in space from aside.
      proj_.setRotation(Projection::rotationOf(
          isSpatial(doc_->design()) ? Projection::View::Isometric : Projection::View::Front));
      fitAsked_ = true;
      update();
    });
  }
  update();
}

void View3dWidget::setSelection(Selection* selection) {
  if (selection_) disconnect(selection_, nullptr, this, nullptr);
  selection_ = selection;
  if (selection_) connect(selection_, &Selection::changed, this, qOverload<>(&QWidget::update));
  update();
}

void View3dWidget::setPlane(const std::string& name) {
  plane_ = name == "drawing" ? std::string() : name;
  update();
}

void View3dWidget::showView(Projection::View v) {
  proj_.setRotation(Projection::rotationOf(v));
  fit();
}

void View3dWidget::showAlongPlane() {
  if (!doc_) return;
  const Plane* p = planeNamed(doc_->design(), plane_);
  proj_.setRotation(Projection::along(p ? *p : drawingPlane()));
  fit();
}

void View3dWidget::fit() {
  fitAsked_ = true;
  update();
}

Scene3d View3dWidget::scene() const {
  if (!doc_) return {};
  const Kinematics& k = doc_->kinematics();
  // The solver's pose while it holds the design; the drawing otherwise (what the user is
  // drawing, an edit it refused), as the canvas does.
  if (doc_->solved()) {
    const Mechanism& m = k.mechanism();
    // The solver moves a body in its plane class's frame: a sketch point of it (a slot's end) is
    // mapped into that frame, moved, and lifted to the world at the plane's depth in it.
    const PlaneClasses pc = planeClasses(m);
    auto bodyPoint = [&k, &m, &pc](BodyId b, const Vec2& sketch) {
      const Body* body = m.body(b);
      const PlaneInClass& in = pc.of(body ? body->plane : std::string());
      return pc.frames[in.cls].world(k.motionOf(b, in.toClass(sketch)).position, in.depth);
    };
    return describeScene3d(m, {[&k](PointId p) { return k.motionInSpace(p).position; }, bodyPoint});
  }
  const Mechanism& m = doc_->design();
  auto drawn = [&m](PointId id) {
    const Point* p = m.point(id);
    return p ? worldOf(m, *p) : Vec3::Constant(NAN);
  };
  return describeScene3d(
      m, {drawn, [&m](BodyId b, const Vec2& sketch) { return planeOf(m, b).world(sketch); }});
}

void View3dWidget::fitIfAsked(const Scene3d& s) {
  if (!fitAsked_ || s.empty()) return;
  fitAsked_ = false;
  proj_.fit(s.extent(), size());
}

void View3dWidget::paintEvent(QPaintEvent*) {
  QPainter p(this);
  Scene3dLook look;
  look.style = CanvasStyle::fromPalette(palette());
  p.fillRect(rect(), look.style.paper);
  const Scene3d s = scene();
  fitIfAsked(s);
  if (doc_ && isSpatial(doc_->design())) {
    look.plane = planeNamed(doc_->design(), plane_);
    look.planeName = plane_;
  }
  if (selection_) {
    look.bodies = selection_->bodies;
    look.points = selection_->points;
    look.joints = selection_->joints;
  }
  paintScene3d(p, s, proj_, look);
}

void View3dWidget::resizeEvent(QResizeEvent* e) {
  // The machine stays in the middle as the dock is resized.
  const QPointF shift((width() - e->oldSize().width()) / 2.0,
                      (height() - e->oldSize().height()) / 2.0);
  if (e->oldSize().isValid()) proj_.pan(shift);
  QWidget::resizeEvent(e);
}

View3dWidget::Picked View3dWidget::pickAt(const QPointF& px) const {
  const Scene3d s = scene();
  Picked out;
  double best = -INFINITY;
  auto near = [&](const Vec3& at, double reach) {
    const QPointF d = proj_.toScreen(at) - px;
    return std::hypot(d.x(), d.y()) <= reach;
  };
  for (const Scene3d::Mark& m : s.points)
    if (near(m.at, kPointReach) && proj_.depth(m.at) > best) {
      best = proj_.depth(m.at);
      out.point = m.point;
    }
  if (out.point) return out;
  for (const Scene3d::Rod& r : s.rods)
    if (distanceToSegment(px, proj_.toScreen(r.a), proj_.toScreen(r.b)) <= kRodReach &&
        proj_.depth(0.5 * (r.a + r.b)) > best) {
      best = proj_.depth(0.5 * (r.a + r.b));
      out.joint = r.joint;
    }
  if (out.joint) return out;
  for (const Scene3d::Plate& pl : s.plates) {
    if (pl.outline.empty()) continue;
    QPolygonF poly;
    double depth = 0;
    for (const Vec3& v : pl.outline) {
      poly << proj_.toScreen(v);
      depth += proj_.depth(v) / pl.outline.size();
    }
    const bool hit = poly.size() == 1   ? near(pl.outline[0], kPointReach)
                     : poly.size() == 2 ? distanceToSegment(px, poly[0], poly[1]) <= kBarReach
                                        : poly.containsPoint(px, Qt::OddEvenFill);
    if (hit && depth > best) {
      best = depth;
      out.body = pl.body;
    }
  }
  return out;
}

void View3dWidget::select(const Picked& p, bool toggle) {
  if (!selection_) return;
  if (!toggle) selection_->clear();
  if (p.point) selection_->add(p.point, toggle);
  if (p.joint) selection_->add(p.joint, toggle);
  if (p.body) selection_->add(p.body, toggle);
  BodyId body = p.body;
  if (p.point && doc_)
    if (const Point* q = doc_->design().point(p.point)) body = q->body;
  if (body) emit bodyPicked(body);
}

void View3dWidget::mousePressEvent(QMouseEvent* e) {
  pressAt_ = lastAt_ = e->position();
  moved_ = false;
  const bool pan = e->button() == Qt::MiddleButton ||
                   (e->button() == Qt::LeftButton && (e->modifiers() & Qt::ShiftModifier));
  drag_ = pan ? Drag::Pan : e->button() == Qt::LeftButton ? Drag::Orbit : Drag::None;
  if (drag_ != Drag::None) setCursor(pan ? Qt::ClosedHandCursor : Qt::SizeAllCursor);
}

void View3dWidget::mouseMoveEvent(QMouseEvent* e) {
  const QPointF d = e->position() - lastAt_;
  lastAt_ = e->position();
  // A click that wobbles a pixel or two is still a click.
  const QPointF total = e->position() - pressAt_;
  if (std::hypot(total.x(), total.y()) > 3) moved_ = true;
  if (!moved_ || drag_ == Drag::None) return;
  if (drag_ == Drag::Orbit) {
    // The turn is about the machine's middle, where the fit put it.
    proj_.orbit(d.x(), d.y());
  } else {
    proj_.pan(d);
  }
  update();
}

void View3dWidget::mouseReleaseEvent(QMouseEvent* e) {
  const bool click = !moved_ && drag_ == Drag::Orbit && e->button() == Qt::LeftButton;
  drag_ = Drag::None;
  unsetCursor();
  if (click) select(pickAt(e->position()), e->modifiers() & Qt::ControlModifier);
}

void View3dWidget::wheelEvent(QWheelEvent* e) {
  const double steps = e->angleDelta().y() / 120.0;
  if (steps == 0) return;
  proj_.zoomAbout(e->position(), std::pow(1.2, steps));
  update();
  e->accept();
}

}  // namespace linkage::ui
