#include "design/transmission_item.h"

#include <QGraphicsScene>
#include <QPainter>
#include <QWidget>
#include <cmath>

#include "canvas/body_item.h"
#include "design/overlay_labels.h"

namespace linkage::ui {

namespace {

constexpr double kDeg = M_PI / 180;
constexpr double kRadiusPx = 22;

Vec2 unit(const Vec2& v) {
  const double n = v.norm();
  return n > 0 ? Vec2(v / n) : Vec2::Zero();
}

// The arc from the first direction to the second the short way: it starts at whichever of the
// two the other lies counter-clockwise of.
void span(TransmissionArc& a, const Vec2& u, const Vec2& v) {
  const double turn = std::atan2(cross(u, v), u.dot(v)) / kDeg;
  a.from = turn >= 0 ? u : v;
  a.sweepDeg = std::abs(turn);
}

}  // namespace

TransmissionItem::TransmissionItem(const CanvasContext* ctx) : CanvasItem(ctx) {
  setAcceptedMouseButtons(Qt::NoButton);
}

void TransmissionItem::setJoints(std::vector<TransmissionJoint> joints) {
  joints_ = std::move(joints);
  arcs_.clear();
  update();
}

void TransmissionItem::setBand(const TransmissionBand& band) {
  band_ = band;
  for (TransmissionArc& a : arcs_) a.outside = a.mu < band_.lo || a.mu > band_.hi;
  update();
}

void TransmissionItem::setPose(const Kinematics& k) {
  arcs_.clear();
  if (!k.valid()) {
    update();
    return;
  }
  arcs_.reserve(joints_.size());
  for (size_t i = 0; i < joints_.size(); ++i) {
    const TransmissionJoint& t = joints_[i];
    TransmissionArc a;
    a.index = static_cast<int>(i);
    a.centre = t.linkAt.at(k);
    const Vec2 rod = unit(t.linkOuter.at(k) - a.centre);
    if (t.kind == TransmissionKind::Dyad) {
      span(a, rod, unit(t.otherOuter.at(k) - t.otherAt.at(k)));
    } else {
      const Kinematics::Segment s = k.slotEnds(t.slot);
      a.normal = perp(unit(s.p1 - s.p0));
      if (a.normal.dot(rod) < 0) a.normal = -a.normal;
      span(a, a.normal, rod);
    }
    a.mu = transmissionAngle(k, t).deg;
    a.outside = a.mu < band_.lo || a.mu > band_.hi;
    if (!a.centre.allFinite() || !std::isfinite(a.mu)) continue;
    arcs_.push_back(a);
  }
  update();
}

QColor TransmissionItem::colourOf(const TransmissionArc& a) const {
  return a.outside ? style().warning : style().kennedyCentre;
}

QRectF TransmissionItem::boundingRect() const {
  // Values are drawn in device pixels beside the arcs.
  return arcs_.empty() || !scene() ? QRectF() : scene()->sceneRect();
}

void TransmissionItem::paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) {
  if (arcs_.empty()) return;
  const double u = px(), r = kRadiusPx * u;
  p->setRenderHint(QPainter::Antialiasing);
  p->setBrush(Qt::NoBrush);
  OverlayLabels labels(p, style().paper, &ctx().labels);
  for (const TransmissionArc& a : arcs_) {
    const QColor ink = colourOf(a);
    if (a.normal != Vec2::Zero()) {
      // The normal of the slot, the line a rod's angle is measured from.
      p->setPen(cosmetic(ink, 1, Qt::DashLine));
      p->drawLine(toQt(a.centre), toQt(a.centre + 1.5 * r * a.normal));
    }
    const double a0 = std::atan2(a.from.y(), a.from.x());
    const int n = std::max(2, static_cast<int>(std::ceil(a.sweepDeg / 6)));
    QPolygonF arc;
    arc.reserve(n + 1);
    for (int k = 0; k <= n; ++k) {
      const double t = a0 + a.sweepDeg * kDeg * k / n;
      arc << toQt(a.centre + r * Vec2(std::cos(t), std::sin(t)));
    }
    p->setPen(cosmetic(ink, a.outside ? 2.5 : 1.8));
    p->drawPolyline(arc);
    // The value outside the arc on its bisector, else across the joint from it.
    const double mid = a0 + a.sweepDeg * kDeg / 2;
    auto beside = [&](const Vec2& b) {
      const Qt::Alignment side = b.x() > 0.3    ? Qt::AlignLeft
                                 : b.x() < -0.3 ? Qt::AlignRight
                                                : Qt::AlignHCenter;
      return OverlayLabels::Place{toQt(a.centre + (r + 5 * u) * b),
                                  QPointF(0, side == Qt::AlignHCenter ? -8 * b.y() : 0), side};
    };
    const Vec2 b(std::cos(mid), std::sin(mid));
    labels.paint({beside(b), beside(-b)},
                 QString::fromUtf8("\u03bc%1 %2\u00b0").arg(a.index + 1).arg(a.mu, 0, 'f', 1), ink);
  }
}

}  // namespace linkage::ui
