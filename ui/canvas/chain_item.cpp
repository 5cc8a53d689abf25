#include "canvas/chain_item.h"

#include <QPainter>

#include "canvas/body_item.h"

namespace linkage::ui {

ChainItem::ChainItem(const CanvasContext* ctx) : CanvasItem(ctx) {
  setAcceptedMouseButtons(Qt::NoButton);
  setZValue(90);
}

void ChainItem::setChain(const std::optional<VelocityChain>& chain) {
  prepareGeometryChange();
  dims_.clear();
  if (chain && chain->status.ok()) {
    auto ic = [](int i, int j) {
      return QStringLiteral("IC(%1,%2)").arg(std::min(i, j)).arg(std::max(i, j));
    };
    for (const ChainStep& s : chain->steps) {
      if (s.centreAtInfinity) continue;
      if (s.fromMotion.kind == BodyMotion::Kind::Turns)
        dims_.push_back({s.fromMotion.pivot, s.centre,
                         QStringLiteral("|%1 P| %2").arg(ic(1, s.from)).arg(s.fromArm, 0, 'f', 2)});
      if (s.toMotion.kind == BodyMotion::Kind::Turns)
        dims_.push_back({s.toMotion.pivot, s.centre,
                         QStringLiteral("|%1 P| %2").arg(ic(1, s.to)).arg(s.toArm, 0, 'f', 2)});
    }
    if (chain->bodyMotion.kind == BodyMotion::Kind::Turns && chain->arm > 0)
      dims_.push_back({chain->bodyMotion.pivot, chain->position,
                       QStringLiteral("arm %1").arg(chain->arm, 0, 'f', 2)});
  }
  update();
}

QRectF ChainItem::boundingRect() const {
  QRectF r;
  for (const Dimension& d : dims_) r = r.united(QRectF(toQt(d.a), toQt(d.b)).normalized());
  const double m = 80 * px();
  return dims_.empty() ? QRectF() : r.adjusted(-m, -m, m, m);
}

void ChainItem::paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) {
  const CanvasStyle& st = style();
  const double u = px();
  p->setRenderHint(QPainter::Antialiasing);
  for (const Dimension& d : dims_) {
    const Vec2 v = d.b - d.a;
    if (v.norm() == 0) continue;
    const Vec2 n = perp(v.normalized()) * (5 * u);
    p->setPen(cosmetic(st.kennedyCentre, 1.0));
    p->drawLine(toQt(d.a), toQt(d.b));
    for (const Vec2& e : {d.a, d.b}) p->drawLine(toQt(e - n), toQt(e + n));
    // The label upright in device coordinates at the middle.
    const QPointF mid = p->worldTransform().map(toQt((d.a + d.b) / 2));
    p->save();
    p->resetTransform();
    QRectF r = p->fontMetrics().boundingRect(d.label);
    r.moveCenter(mid + QPointF(0, -10));
    ctx().labels.take(r.adjusted(-2, 0, 2, 0));  // the centres' labels step aside from it
    QColor back = st.paper;
    back.setAlphaF(0.8);
    p->fillRect(r.adjusted(-2, 0, 2, 0), back);
    p->setPen(st.kennedyCentre);
    p->drawText(r, Qt::AlignCenter, d.label);
    p->restore();
  }
}

}  // namespace linkage::ui
