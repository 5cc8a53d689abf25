#include "view3d/scene3d_painter.h"

#include <QPainterPath>
#include <algorithm>
#include <cmath>

namespace linkage::ui {

namespace {

template <class Id>
bool has(const std::vector<Id>& v, Id id) {
  return std::find(v.begin(), v.end(), id) != v.end();
}

QColor mix(const QColor& a, const QColor& b, double t) {
  return QColor::fromRgbF(a.redF() + (b.redF() - a.redF()) * t,
                          a.greenF() + (b.greenF() - a.greenF()) * t,
                          a.blueF() + (b.blueF() - a.blueF()) * t, a.alphaF());
}

QPen pen(const QColor& c, double width, Qt::PenStyle style = Qt::SolidLine) {
  QPen p(c, width, style, Qt::RoundCap, Qt::RoundJoin);
  return p;
}

// What to paint, with its depth: the painter's algorithm paints in ascending depth.
struct Entry {
  double depth;
  enum class Kind { Plate, Rod, Axis, Point, Groove } kind;
  size_t index;
};

class ScenePainter {
 public:
  ScenePainter(QPainter& p, const Scene3d& s, const Projection& proj, const Scene3dLook& look)
      : p_(p), s_(s), proj_(proj), look_(look) {
    size_ = std::max((s.hi - s.lo).norm(), 1e-9);
    // The depths the scene spans now, for its shading.
    near_ = -size_;
    far_ = size_;
    for (const Scene3d::Mark& m : s.points) {
      near_ = std::max(near_, proj.depth(m.at));
      far_ = std::min(far_, proj.depth(m.at));
    }
  }

  void paint() {
    paintPlaneRegion();
    std::vector<Entry> order = entries();
    std::stable_sort(order.begin(), order.end(),
                     [](const Entry& a, const Entry& b) { return a.depth < b.depth; });
    for (const Entry& e : order) switch (e.kind) {
        case Entry::Kind::Plate:
          paintPlate(s_.plates[e.index]);
          break;
        case Entry::Kind::Rod:
          paintRod(s_.rods[e.index]);
          break;
        case Entry::Kind::Axis:
          paintAxis(s_.axes[e.index]);
          break;
        case Entry::Kind::Point:
          paintPoint(s_.points[e.index]);
          break;
        case Entry::Kind::Groove:
          paintGroove(s_.grooves[e.index], look_.style.ink);
          break;
      }
    paintTriad();
  }

 private:
  double fog(double depth) const {
    const double span = near_ - far_;
    return span > 1e-9 ? std::clamp((near_ - depth) / span, 0.0, 1.0) : 0.0;
  }

  std::vector<Entry> entries() const {
    std::vector<Entry> out;
    // A body's points are painted with its plate (a plate tilted away must not cover its own
    // pins); a rod after the nearer of its ends' plates, the ground's points a little nearer
    // than they are, the shafts a little farther.
    const double lift = 0.02 * size_;
    for (size_t i = 0; i < s_.plates.size(); ++i) {
      const auto& o = s_.plates[i].outline;
      if (o.empty()) continue;
      double d = 0;
      for (const Vec3& v : o) d += proj_.depth(v);
      out.push_back({d / o.size(), Entry::Kind::Plate, i});
    }
    for (size_t i = 0; i < s_.rods.size(); ++i)
      out.push_back({std::max(proj_.depth(s_.rods[i].a), proj_.depth(s_.rods[i].b)) + lift,
                     Entry::Kind::Rod, i});
    for (size_t i = 0; i < s_.axes.size(); ++i)
      out.push_back({proj_.depth(s_.axes[i].at) - lift, Entry::Kind::Axis, i});
    // A ground slot as near as the ground's points: what runs in it is drawn over it.
    for (size_t i = 0; i < s_.grooves.size(); ++i) {
      const auto& path = s_.grooves[i].path;
      if (!s_.grooves[i].ground || path.empty()) continue;
      double d = 0;
      for (const Vec3& v : path) d += proj_.depth(v);
      out.push_back({d / path.size() + lift, Entry::Kind::Groove, i});
    }
    for (size_t i = 0; i < s_.points.size(); ++i)
      if (s_.points[i].ground)
        out.push_back({proj_.depth(s_.points[i].at) + 2 * lift, Entry::Kind::Point, i});
    return out;
  }

  void paintPlate(const Scene3d::Plate& pl) {
    const CanvasStyle& st = look_.style;
    double d = 0;
    for (const Vec3& v : pl.outline) d += proj_.depth(v);
    const double t = 0.6 * fog(d / pl.outline.size());
    const QColor fill = mix(st.bodyFill(pl.number), st.paper, t);
    const bool selected = has(look_.bodies, pl.body);
    const QColor edge = selected ? st.highlight : mix(st.body(pl.number), st.paper, 0.5 * t);
    const double w = selected ? 2.5 : 1.2;
    for (const auto& [foot, tip] : pl.studs) {
      p_.setPen(pen(edge, 3));
      p_.drawLine(proj_.toScreen(foot), proj_.toScreen(tip));
    }
    if (pl.outline.size() == 1) {
      p_.setPen(pen(edge, w));
      p_.setBrush(fill);
      p_.drawEllipse(proj_.toScreen(pl.outline[0]), 6, 6);
    } else if (pl.outline.size() == 2) {
      const QPointF a = proj_.toScreen(pl.outline[0]), b = proj_.toScreen(pl.outline[1]);
      p_.setPen(pen(edge, CanvasStyle::barWidth + 2 * w));
      p_.drawLine(a, b);
      p_.setPen(pen(fill, CanvasStyle::barWidth));
      p_.drawLine(a, b);
    } else {
      QPolygonF poly;
      for (const Vec3& v : pl.outline) poly << proj_.toScreen(v);
      p_.setPen(pen(edge, w));
      p_.setBrush(fill);
      p_.drawPolygon(poly);
    }
    for (const Scene3d::Groove& g : s_.grooves)
      if (g.body == pl.body) paintGroove(g, edge);
    for (const Scene3d::Mark& m : s_.points)
      if (m.body == pl.body) paintPoint(m);
  }

  // A slot as the canvas draws one: its rim in `rim`, the paper showing through along it.
  void paintGroove(const Scene3d::Groove& g, const QColor& rim) {
    QPolygonF line;
    for (const Vec3& v : g.path) line << proj_.toScreen(v);
    p_.setBrush(Qt::NoBrush);
    p_.setPen(pen(rim, 8));
    p_.drawPolyline(line);
    p_.setPen(pen(look_.style.paper, 5));
    p_.drawPolyline(line);
  }

  void paintRod(const Scene3d::Rod& r) {
    const CanvasStyle& st = look_.style;
    const QColor c = has(look_.joints, r.joint) ? st.highlight : st.ink;
    const QPointF a = proj_.toScreen(r.a), b = proj_.toScreen(r.b);
    p_.setPen(pen(c, 3));
    p_.drawLine(a, b);
    p_.setPen(pen(c, 1.5));
    p_.setBrush(mix(st.paper, c, 0.25));
    for (const QPointF& end : {a, b}) p_.drawEllipse(end, 5.5, 5.5);
  }

  void paintAxis(const Scene3d::Axis& a) {
    const double reach = 0.15 * size_;
    p_.setPen(pen(look_.style.faint, 1.2, Qt::DashDotLine));
    p_.drawLine(proj_.toScreen(a.at - reach * a.direction),
                proj_.toScreen(a.at + reach * a.direction));
  }

  void paintPoint(const Scene3d::Mark& m) {
    const CanvasStyle& st = look_.style;
    const QPointF at = proj_.toScreen(m.at);
    if (m.ground) {
      // A ground pivot: a small hatched square, as the canvas's frame symbols.
      p_.setPen(pen(st.ink, 1.2));
      p_.setBrush(QBrush(st.ink, Qt::BDiagPattern));
      p_.drawRect(QRectF(at - QPointF(5, 5), QSizeF(10, 10)));
    } else {
      p_.setPen(pen(st.ink, 1));
      p_.setBrush(st.paper);
      p_.drawEllipse(at, CanvasStyle::pointRadius + 1, CanvasStyle::pointRadius + 1);
    }
    if (has(look_.points, m.point)) {
      p_.setPen(pen(st.highlight, 2));
      p_.setBrush(Qt::NoBrush);
      p_.drawEllipse(at, 8, 8);
    }
  }

  void paintPlaneRegion();
  void paintTriad();

  QPainter& p_;
  const Scene3d& s_;
  const Projection& proj_;
  const Scene3dLook& look_;
  double size_ = 1, near_ = 0, far_ = 0;
};

// The plane the canvas edits: the rectangle of its axes that holds its bodies, with a margin,
// shaded, so that a user sees which plane the 2D canvas shows.
void ScenePainter::paintPlaneRegion() {
  if (!look_.plane) return;
  const Plane& pl = *look_.plane;
  Vec2 lo(1e300, 1e300), hi(-1e300, -1e300);
  for (const Scene3d::Plate& plate : s_.plates) {
    if (plate.plane != look_.planeName) continue;
    for (const Vec3& v : plate.outline) {
      const Vec2 q((v - pl.origin).dot(pl.xAxis), (v - pl.origin).dot(pl.yAxis));
      lo = lo.cwiseMin(q);
      hi = hi.cwiseMax(q);
    }
  }
  if (!(lo.x() <= hi.x())) return;  // no body in it
  const double margin = 0.08 * size_;
  lo -= Vec2(margin, margin);
  hi += Vec2(margin, margin);
  QPolygonF quad;
  for (const Vec2& c : {lo, Vec2(hi.x(), lo.y()), hi, Vec2(lo.x(), hi.y())})
    quad << proj_.toScreen(pl.world(c));
  QColor fill = look_.style.highlight;
  fill.setAlphaF(0.10);
  QColor edge = look_.style.highlight;
  edge.setAlphaF(0.7);
  p_.setPen(pen(edge, 1.2, Qt::DashLine));
  p_.setBrush(fill);
  p_.drawPolygon(quad);
}

// Which way the world's axes point now: x, y, z from a corner.
void ScenePainter::paintTriad() {
  const QRect r = p_.viewport();
  const QPointF o(r.left() + 34, r.bottom() - 34);
  const char* names[3] = {"x", "y", "z"};
  const QColor colours[3] = {QColor(200, 60, 50), QColor(40, 150, 60), QColor(50, 90, 210)};
  for (int k = 0; k < 3; ++k) {
    const Vec3 v = proj_.rotation() * Vec3::Unit(k);
    const QPointF tip = o + 24 * QPointF(v.x(), -v.y());
    p_.setPen(pen(colours[k], 2));
    p_.drawLine(o, tip);
    p_.drawText(QRectF(tip + 6 * QPointF(v.x(), -v.y()) - QPointF(6, 7), QSizeF(12, 14)),
                Qt::AlignCenter, QString::fromLatin1(names[k]));
  }
}

}  // namespace

void paintScene3d(QPainter& p, const Scene3d& s, const Projection& proj, const Scene3dLook& look) {
  p.setRenderHint(QPainter::Antialiasing);
  ScenePainter(p, s, proj, look).paint();
}

}  // namespace linkage::ui
