#include "forces/dynamics_item.h"

#include <QGraphicsScene>
#include <QPainter>
#include <QWidget>
#include <cmath>
#include <numbers>

namespace linkage::ui {

QColor loadColour(const CanvasStyle& s) {
  return s.dark ? QColor(255, 160, 60) : QColor(205, 90, 0);
}

QColor reactionColour(const CanvasStyle& s) {
  return s.dark ? QColor(200, 140, 255) : QColor(120, 40, 170);
}

namespace {

// An arrow from `from` to `to` (scene units), its head `head` scene units long.
void arrow(QPainter* p, const QPointF& from, const QPointF& to, double head, const QPen& pen) {
  const QPointF d = to - from;
  const double n = std::hypot(d.x(), d.y());
  if (!(n > 0)) return;
  const QPointF u = d / n, v(-u.y(), u.x());
  const double h = std::min(head, 0.6 * n);
  p->setPen(pen);
  p->drawLine(from, to - 0.5 * h * u);
  p->setPen(Qt::NoPen);
  p->setBrush(pen.color());
  p->drawPolygon(QPolygonF() << to << to - h * u + 0.4 * h * v << to - h * u - 0.4 * h * v);
}

}  // namespace

DynamicsItem::DynamicsItem(const CanvasContext* ctx) : CanvasItem(ctx) {
  setAcceptedMouseButtons(Qt::NoButton);
  setZValue(90);  // over the bodies and joints, under the instant centres
}

void DynamicsItem::setMarks(DynamicsMarks marks) {
  marks_ = std::move(marks);
  update();
}

QRectF DynamicsItem::boundingRect() const {
  // Arrows scaled by forces and a legend in the view's corner: the whole scene.
  return scene() ? scene()->sceneRect() : QRectF();
}

void DynamicsItem::paintText(QPainter* p, const QPointF& at, const QString& text,
                             const QColor& ink) const {
  // Upright, of constant size: in device coordinates, on a backing of the paper colour.
  const QPointF d = p->worldTransform().map(at);
  p->save();
  p->resetTransform();
  const QRect box = p->fontMetrics().boundingRect(text);
  const QRectF r = QRectF(box).adjusted(-2, 0, 2, 0).translated(d.x() + 6 - box.left(), d.y() - 6);
  QColor back = style().paper;
  back.setAlphaF(0.75);
  p->fillRect(r, back);
  p->setPen(ink);
  p->drawText(r, Qt::AlignCenter, text);
  p->restore();
}

void DynamicsItem::paintMass(QPainter* p, const DynamicsMarks::Mass& m) const {
  const double u = px(), r = 6 * u;
  // The centre-of-mass symbol: a circle with two opposite quarters filled.
  p->setPen(cosmetic(style().ink, 1));
  p->setBrush(style().paper);
  p->drawEllipse(m.com, r, r);
  p->setBrush(style().ink);
  const QRectF box(m.com - QPointF(r, r), m.com + QPointF(r, r));
  p->drawPie(box, 0, 90 * 16);
  p->drawPie(box, 180 * 16, 90 * 16);
  for (size_t i = 0; i < m.counterweights.size(); ++i) {
    // Radius of a steel disk 10 mm thick, but at least a few pixels: a visible size order.
    const double kg = m.counterweightKg[i];
    const double mm = std::sqrt(std::max(kg, 0.0) / (7850e-9 * 10 * std::numbers::pi));
    const double rc = std::clamp(mm, 5 * u, 40 * u);
    p->setPen(cosmetic(style().ink, 1));
    QColor fill = style().ink;
    fill.setAlphaF(0.45);
    p->setBrush(fill);
    p->drawEllipse(m.counterweights[i], rc, rc);
    // Grams to a kilogram, kilograms from there ("2e+03 g" read as nothing a hand weighs).
    const QString weight = kg < 1 ? QStringLiteral("%1 g").arg(kg * 1000, 0, 'f', kg < 0.01 ? 1 : 0)
                                  : QStringLiteral("%1 kg").arg(kg, 0, 'f', kg < 10 ? 2 : 1);
    paintText(p, m.counterweights[i] + QPointF(rc, 0), weight, style().ink);
  }
}

void DynamicsItem::paintLoad(QPainter* p, const DynamicsMarks::Load& l) const {
  const double u = px();
  QColor ink = loadColour(style());
  if (!l.active) ink.setAlphaF(0.45);
  const QPen pen = cosmetic(ink, 2, l.active ? Qt::SolidLine : Qt::DashLine);
  QPointF labelAt = l.at;
  if (l.torque) {
    // Three quarters of a circle around the point, the head showing the sense.
    const double r = 16 * u;
    const QRectF box(l.at - QPointF(r, r), l.at + QPointF(r, r));
    p->setPen(pen);
    p->setBrush(Qt::NoBrush);
    const double sweep = l.torqueNm >= 0 ? 270 : -270;  // degrees; y up in the scene
    p->drawArc(box, 0, static_cast<int>(sweep * 16));
    const double end = sweep * std::numbers::pi / 180;
    const QPointF tip = l.at + r * QPointF(std::cos(end), std::sin(end));
    const QPointF along = (l.torqueNm >= 0 ? 1.0 : -1.0) * QPointF(-std::sin(end), std::cos(end));
    arrow(p, tip - 4 * u * along, tip + 4 * u * along, 9 * u, pen);
    labelAt = l.at + QPointF(r, r);
  } else {
    const double n = std::hypot(l.forceN.x(), l.forceN.y());
    if (!(n > 0)) return;
    // A load pushes on its point: the head at the point, a fixed length on screen.
    const QPointF d = l.forceN / n;
    arrow(p, l.at - 44 * u * d, l.at - 4 * u * d, 10 * u, pen);
    labelAt = l.at - 44 * u * d;
  }
  paintText(p, labelAt, l.label, ink);
}

void DynamicsItem::paintReaction(QPainter* p, const DynamicsMarks::Reaction& r) const {
  const QColor ink = reactionColour(style());
  if (!r.determined) {
    paintText(p, r.at, QStringLiteral("not determined"), ink);
    return;
  }
  const QPointF to = r.at + marks_.mmPerN * r.forceN;
  arrow(p, r.at, to, 10 * px(), cosmetic(ink, 2.5));
}

void DynamicsItem::paintLegend(QPainter* p, const QRectF& device) const {
  if (marks_.legend.isEmpty()) return;
  p->save();
  p->resetTransform();
  const QRect box = p->fontMetrics().boundingRect(device.toRect().adjusted(10, 10, -10, -10),
                                                  Qt::AlignLeft | Qt::TextWordWrap, marks_.legend);
  QColor back = style().paper;
  back.setAlphaF(0.85);
  p->fillRect(box.adjusted(-4, -3, 4, 3), back);
  p->setPen(reactionColour(style()));
  p->drawText(box, Qt::AlignLeft | Qt::TextWordWrap, marks_.legend);
  p->restore();
}

void DynamicsItem::paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget* widget) {
  if (marks_.masses.empty() && marks_.loads.empty() && marks_.reactions.empty() &&
      marks_.legend.isEmpty())
    return;
  p->setRenderHint(QPainter::Antialiasing);
  for (const DynamicsMarks::Mass& m : marks_.masses) paintMass(p, m);
  for (const DynamicsMarks::Reaction& r : marks_.reactions) paintReaction(p, r);
  for (const DynamicsMarks::Load& l : marks_.loads) paintLoad(p, l);
  const QRectF device =
      widget ? QRectF(widget->rect()) : p->worldTransform().mapRect(boundingRect());
  paintLegend(p, device);
}

}  // namespace linkage::ui
