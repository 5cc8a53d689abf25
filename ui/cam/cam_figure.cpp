#include "cam/cam_figure.h"

#include <QMouseEvent>
#include <cmath>

#include "figures/qcp.h"

namespace linkage::ui {

namespace {

constexpr int kPlots = 5;
constexpr double kGrab = 5;  // px: how near a segment's end a press takes it

// The curves of one segment: s and its derivatives in the cam angle (programme units), from
// the law itself so that a jump at a segment's end (a harmonic rise after a dwell) is drawn
// as one: the values at both ends of each segment.
void addSegment(const cam::Program& p, size_t k, double factor, QVector<double>& keys,
                std::array<QVector<double>, 4>& values) {
  const cam::Segment& seg = p.segments()[k];
  const double start = p.startOf(k), end = seg.toDeg * M_PI / 180, beta = end - start;
  const double rise = seg.rise * p.scale(), base = p.baseOf(k);
  const int n = std::max(8, static_cast<int>(std::ceil((end - start) * 180 / M_PI * 2)));
  for (int i = 0; i <= n; ++i) {
    const double x = static_cast<double>(i) / n;
    const cam::Normalised l = seg.law ? cam::evaluate(*seg.law, x) : cam::Normalised{};
    keys.push_back((start + x * beta) * 180 / M_PI);
    values[0].push_back(factor * (base + rise * l.s));
    values[1].push_back(factor * rise * l.v / beta);
    values[2].push_back(factor * rise * l.a / (beta * beta));
    values[3].push_back(factor * rise * l.j / (beta * beta * beta));
  }
}

QString unitOf(const cam::CamGeometry& g) {
  return g.motion == cam::FollowerMotion::Oscillating ? QStringLiteral("°") : QStringLiteral("mm");
}

}  // namespace

CamFigure::CamFigure(QCustomPlot* plot) : CrankFigure(plot) {
  plot_->installEventFilter(this);
  plot_->setMouseTracking(true);
}

QCPAxisRect* CamFigure::addRect(int row, const QString& label) {
  auto* rect = new QCPAxisRect(plot_);
  plot_->plotLayout()->addElement(row, 0, rect);
  QCPAxis* x = rect->axis(QCPAxis::atBottom);
  setCrankAxis(x, 360, row == kPlots - 1 ? tr("cam angle (°)") : QString(), 8);
  x->setTickLabels(row == kPlots - 1);
  // The name in the top right corner on a backing (an axis label would not fit a short plot).
  auto* name = new QCPItemText(plot_);
  name->setClipAxisRect(rect);
  name->position->setType(QCPItemPosition::ptAxisRectRatio);
  name->position->setAxisRect(rect);
  name->position->setCoords(0.995, 0.03);
  name->setPositionAlignment(Qt::AlignRight | Qt::AlignTop);
  name->setText(label);
  name->setBrush(QBrush(QColor(255, 255, 255, 210)));
  rect->axis(QCPAxis::atLeft)->ticker()->setTickCount(3);
  rect->setMargins(QMargins(0, row == 0 ? 18 : 0, 0, 0));
  rect->setAutoMargins(QCP::msLeft | QCP::msRight |
                       (row == kPlots - 1 ? QCP::msBottom : QCP::msNone));
  if (!rects_.empty()) {
    // The plots' left edges in a column, so the angles line up.
    auto* group = rects_[0]->marginGroup(QCP::msLeft);
    if (!group) {
      group = new QCPMarginGroup(plot_);
      rects_[0]->setMarginGroup(QCP::msLeft, group);
    }
    rect->setMarginGroup(QCP::msLeft, group);
  }
  rects_.push_back(rect);
  addCursorLine(rect);
  return rect;
}

void CamFigure::showNothing(const QString& why) {
  clearPlot();
  plot_->plotLayout()->clear();
  rects_.clear();
  ends_.clear();
  auto* text = new QCPTextElement(plot_, why);
  plot_->plotLayout()->addElement(0, 0, text);
  plot_->replot();
}

void CamFigure::build(const cam::CamGeometry& g, const cam::CamChecks& checks, double limitDeg) {
  clearPlot();
  plot_->plotLayout()->clear();
  rects_.clear();
  const QString u = unitOf(g);
  const QString labels[kPlots - 1] = {tr("s (%1)").arg(u), tr("s' (%1/rad)").arg(u),
                                      tr("s'' (%1/rad²)").arg(u), tr("s''' (%1/rad³)").arg(u)};
  for (int r = 0; r < kPlots - 1; ++r) addRect(r, labels[r]);
  addRect(kPlots - 1,
          g.face == cam::FollowerFace::Flat ? tr("surface radius (mm)") : tr("pressure angle (°)"));
  drawCurves(g);
  drawCheck(g, checks, limitDeg);
  markSegments(g.program);
  plot_->replot();
}

void CamFigure::drawCurves(const cam::CamGeometry& g) {
  const double factor = g.motion == cam::FollowerMotion::Oscillating ? 180 / M_PI : 1.0;
  QVector<double> keys;
  std::array<QVector<double>, 4> values;
  for (size_t k = 0; k < g.program.segments().size(); ++k)
    addSegment(g.program, k, factor, keys, values);
  const QColor colours[4] = {QColor(31, 119, 180), QColor(44, 160, 44), QColor(214, 39, 40),
                             QColor(148, 103, 189)};
  for (int r = 0; r < 4; ++r) {
    QCPGraph* graph =
        plot_->addGraph(rects_[r]->axis(QCPAxis::atBottom), rects_[r]->axis(QCPAxis::atLeft));
    graph->setPen(QPen(colours[r], 1.5));
    graph->setData(keys, values[r], true);
    bool found = false;
    const QCPRange range = graph->data()->valueRange(found);
    const double pad = std::max(1e-9, 0.08 * (range.upper - range.lower));
    rects_[r]->axis(QCPAxis::atLeft)->setRange(range.lower - pad, range.upper + pad);
    if (r == 0) addCursorDot(graph);
  }
}

void CamFigure::drawCheck(const cam::CamGeometry& g, const cam::CamChecks& checks,
                          double limitDeg) {
  QCPAxisRect* rect = rects_[kPlots - 1];
  const bool flat = g.face == cam::FollowerFace::Flat;
  QVector<double> keys, values;
  for (int i = 0; i <= 720; ++i) {
    const cam::CamPoint p = cam::camPointAt(g, i * M_PI / 360);
    keys.push_back(i / 2.0);
    values.push_back(flat ? p.radiusMm : p.pressureDeg);
  }
  QCPGraph* graph = plot_->addGraph(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
  graph->setPen(QPen(QColor(80, 80, 80), 1.5));
  graph->setData(keys, values, true);
  bool found = false;
  QCPRange range = graph->data()->valueRange(found);
  auto level = [&](double y, const QColor& c) {
    auto* line = new QCPItemStraightLine(plot_);
    line->setClipAxisRect(rect);
    line->point1->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
    line->point2->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
    line->point1->setCoords(0, y);
    line->point2->setCoords(360, y);
    line->setPen(QPen(c, 1, Qt::DashLine));
    range.expand(y);
  };
  if (flat) {
    level(0, QColor(200, 0, 0));
    if (checks.surfaceRadiusMin.found) {
      const cam::CamExtreme& e = checks.surfaceRadiusMin;
      markExtreme(rect, e.atDeg, e.value,
                  tr("least %1 mm at %2°").arg(e.value, 0, 'f', 2).arg(e.atDeg, 0, 'f', 1));
    }
  } else {
    level(limitDeg, QColor(200, 0, 0));
    level(-limitDeg, QColor(200, 0, 0));
    if (checks.pressureMax.found) {
      const cam::CamExtreme& e = checks.pressureMax;
      const double signedDeg = cam::camPointAt(g, e.atDeg * M_PI / 180).pressureDeg;
      markExtreme(rect, e.atDeg, std::copysign(e.value, signedDeg),
                  tr("largest %1° at %2°").arg(e.value, 0, 'f', 2).arg(e.atDeg, 0, 'f', 1));
    }
  }
  const double pad = std::max(1e-9, 0.15 * (range.upper - range.lower));
  rect->axis(QCPAxis::atLeft)->setRange(range.lower - pad, range.upper + pad);
}

void CamFigure::markExtreme(QCPAxisRect* rect, double deg, double value, const QString& text) {
  QCPGraph* dot = plot_->addGraph(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
  dot->setLineStyle(QCPGraph::lsNone);
  dot->setScatterStyle(
      QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(QColor(200, 0, 0), 2), QBrush(Qt::white), 8));
  dot->addData(deg, value);
  auto* label = new QCPItemText(plot_);
  label->setClipAxisRect(rect);
  label->position->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
  label->position->setCoords(deg, value);
  label->setPositionAlignment((deg > 240 ? Qt::AlignRight : Qt::AlignLeft) | Qt::AlignBottom);
  label->setPadding(QMargins(6, 0, 6, 2));
  label->setText(text);
  label->setColor(QColor(200, 0, 0));
}

void CamFigure::markSegments(const cam::Program& p) {
  ends_.clear();
  const auto& segs = p.segments();
  for (size_t k = 0; k + 1 < segs.size(); ++k) ends_.push_back(segs[k].toDeg);
  for (QCPAxisRect* rect : rects_)
    for (double end : ends_) {
      auto* line = new QCPItemStraightLine(plot_);
      line->setClipAxisRect(rect);
      line->point1->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
      line->point2->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
      line->point1->setCoords(end, 0);
      line->point2->setCoords(end, 1);
      line->setPen(QPen(QColor(150, 150, 150), 1));
    }
  double from = 0;
  // A name wider than its segment is left out (the table names every segment).
  const double width = std::max({200, rects_[0]->width(), plot_->width() - 90});
  const QFontMetricsF metrics(plot_->font());
  for (const cam::Segment& s : segs) {
    const QString text = s.law ? QString::fromLatin1(cam::lawName(*s.law)) : tr("dwell");
    if (metrics.horizontalAdvance(text) + 6 > (s.toDeg - from) / 360 * width) {
      from = s.toDeg;
      continue;
    }
    auto* name = new QCPItemText(plot_);
    name->setClipAxisRect(rects_[0]);
    name->position->setAxisRect(rects_[0]);
    name->position->setAxes(rects_[0]->axis(QCPAxis::atBottom), nullptr);
    name->position->setTypeX(QCPItemPosition::ptPlotCoords);
    name->position->setTypeY(QCPItemPosition::ptAxisRectRatio);
    // Over the plot, in its top margin: the curves and the plot's name stay clear.
    name->setClipToAxisRect(false);
    name->position->setCoords((from + s.toDeg) / 2, -0.01);
    name->setPositionAlignment(Qt::AlignHCenter | Qt::AlignBottom);
    name->setText(text);
    name->setColor(QColor(90, 90, 90));
    from = s.toDeg;
  }
}

QPointF CamFigure::pixelAt(int rect, double camDeg, double value) const {
  if (rect < 0 || rect >= rects()) return {};
  return {rects_[rect]->axis(QCPAxis::atBottom)->coordToPixel(camDeg),
          rects_[rect]->axis(QCPAxis::atLeft)->coordToPixel(value)};
}

int CamFigure::endNear(const QPointF& pixel) const {
  for (QCPAxisRect* rect : rects_) {
    if (!rect->rect().contains(pixel.toPoint())) continue;
    for (size_t k = 0; k < ends_.size(); ++k)
      if (std::abs(rect->axis(QCPAxis::atBottom)->coordToPixel(ends_[k]) - pixel.x()) <= kGrab)
        return static_cast<int>(k);
  }
  return -1;
}

bool CamFigure::eventFilter(QObject* watched, QEvent* e) {
  if (watched != plot_) return false;
  const auto type = e->type();
  if (type != QEvent::MouseButtonPress && type != QEvent::MouseMove &&
      type != QEvent::MouseButtonRelease)
    return false;
  const auto* m = static_cast<QMouseEvent*>(e);
  if (type == QEvent::MouseButtonPress && m->button() == Qt::LeftButton) {
    dragged_ = endNear(m->position());
    return dragged_ >= 0;
  }
  if (dragged_ < 0) {
    if (type == QEvent::MouseMove)
      plot_->setCursor(endNear(m->position()) >= 0 ? Qt::SplitHCursor : Qt::ArrowCursor);
    return false;
  }
  // Whole half degrees, a degree clear of the neighbouring ends.
  const size_t k = static_cast<size_t>(dragged_);
  const double lo = (k > 0 ? ends_[k - 1] : 0) + 1,
               hi = (k + 1 < ends_.size() ? ends_[k + 1] : 360) - 1;
  const double x = rects_[0]->axis(QCPAxis::atBottom)->pixelToCoord(m->position().x());
  const double deg = std::clamp(std::round(x * 2) / 2, lo, hi);
  const bool done = type == QEvent::MouseButtonRelease;
  if (done) dragged_ = -1;
  Q_EMIT endDragged(static_cast<int>(k), deg, done);
  return true;
}

}  // namespace linkage::ui
