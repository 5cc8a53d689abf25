#include "canvas/clearance_marks.h"

#include <QFontMetricsF>
#include <QPainter>

#include "linkage/plane_view.h"

namespace linkage::ui {

namespace {

constexpr double kRingPx = 5;  // the rings' radius on screen
constexpr double kEndPx = 6;   // half a part's end bar

// The segment or slot where it is at the closest approach (`px` mm a pixel): a broad light
// band, each end a bar across it (the needle's point lower than drawn, the ring on it).
void paintPart(QPainter* p, const std::vector<Vec2>& part, QColor c, double px) {
  QPolygonF line;
  for (const Vec2& v : part) line << QPointF(v.x(), v.y());
  QColor band = c;
  band.setAlpha(80);
  p->setPen(cosmetic(band, 6));
  p->drawPolyline(line);
  p->setPen(cosmetic(c, 1.5));
  auto bar = [&](const QPointF& end, const QPointF& next) {
    const QLineF along(end, next);
    if (!(along.length() > 0)) return;
    const QPointF n = QPointF(-along.dy(), along.dx()) * (kEndPx * px / along.length());
    p->drawLine(end - n, end + n);
  };
  bar(line.front(), line[1]);
  bar(line.back(), line[line.size() - 2]);
}

}  // namespace

ClearanceMarksItem::ClearanceMarksItem(const CanvasContext* ctx) : CanvasItem(ctx) {
  setZValue(60);  // over the mechanism, under the tools' overlays
}

void ClearanceMarksItem::setMarks(std::vector<ClearanceMark> marks) {
  prepareGeometryChange();
  marks_ = std::move(marks);
  rebuild();
  update();
}

void ClearanceMarksItem::rebuild() {
  for (LabelItem* l : labels_) delete l;
  labels_.clear();
  shown_ = marks_;
  if (const PlaneView* view = ctx().view)
    for (ClearanceMark& m : shown_) {
      m.a = view->fromSolver(m.bodyA, m.a);
      m.b = view->fromSolver(m.bodyB, m.b);
      for (Vec2& v : m.part) v = view->fromSolver(m.bodyB, v);
    }
  for (const ClearanceMark& m : shown_) {
    auto* l = new LabelItem(m.text, this);
    // Beside the right ring, off the rings, the line between them and a part across them (a
    // needle through the ring, its point below it).
    const Vec2 right = m.a.x() >= m.b.x() ? m.a : m.b;
    QFont font;
    font.setBold(m.tooClose);
    const double half = QFontMetricsF(font).boundingRect(m.text).width() / 2;
    // Marks a label's height apart or less on screen (a cam's extremes at neighbouring angles):
    // each label a line under the one before.
    int line = 0;
    for (size_t k = 0; k + 1 < shown_.size() && &shown_[k] != &m; ++k) {
      const Vec2 other = shown_[k].a.x() >= shown_[k].b.x() ? shown_[k].a : shown_[k].b;
      if ((other - right).norm() < 18 * px()) ++line;
    }
    l->setPos(right.x(), right.y());
    l->setOffset(QPointF(kRingPx + 6 + half, -14 + 18 * line));
    l->setColours(m.tooClose ? style().warning : style().ink, style().paper);
    l->setBold(m.tooClose);
    labels_.push_back(l);
  }
}

QRectF ClearanceMarksItem::boundingRect() const {
  QRectF r;
  const double pad = 2 * kRingPx * px();
  for (const ClearanceMark& m : shown_) {
    r |= QRectF(QPointF(std::min(m.a.x(), m.b.x()), std::min(m.a.y(), m.b.y())),
                QPointF(std::max(m.a.x(), m.b.x()), std::max(m.a.y(), m.b.y())))
             .adjusted(-pad, -pad, pad, pad);
    const double end = 2 * kEndPx * px();
    for (const Vec2& v : m.part) r |= QRectF(v.x() - end, v.y() - end, 2 * end, 2 * end);
  }
  return r;
}

void ClearanceMarksItem::paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) {
  p->setRenderHint(QPainter::Antialiasing);
  p->setBrush(Qt::NoBrush);
  const double r = kRingPx * px();
  for (const ClearanceMark& m : shown_) {
    const QColor c = m.tooClose ? style().warning : style().ink;
    if (m.part.size() >= 2) paintPart(p, m.part, c, px());
    p->setPen(cosmetic(c, 1.2, Qt::DashLine));
    p->drawLine(QPointF(m.a.x(), m.a.y()), QPointF(m.b.x(), m.b.y()));
    p->setPen(cosmetic(c, 1.5));
    p->drawEllipse(QPointF(m.a.x(), m.a.y()), r, r);
    p->drawEllipse(QPointF(m.b.x(), m.b.y()), r, r);
  }
}

}  // namespace linkage::ui
