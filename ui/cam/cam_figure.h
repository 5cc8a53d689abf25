// A cam's motion programme against the cam angle (linkage/cam.h): the follower's s and its
// first three derivatives in the cam angle (per radian: the programme's own, whatever the cam's
// speed), one plot each, and under them the check the follower has (linkage/cam_checks.h): the
// pressure angle with its limit either side (roller and knife edge), or the surface's radius of
// curvature (flat face). The segments are marked across every plot (their ends, the laws
// named over the first) and their ends dragged along the angle; each check's extreme is marked
// where it occurs, from the exact checks (not the samples). The cursor at the cam's angle of
// the pose (figures/crank_figure.h).
#pragma once

#include <QObject>
#include <QPointF>
#include <QString>
#include <vector>

#include "figures/crank_figure.h"
#include "linkage/cam_checks.h"

class QCustomPlot;
class QCPAxisRect;

namespace linkage::cam {
struct CamChecks;
}

namespace linkage::ui {

class CamFigure : public QObject, public CrankFigure {
  Q_OBJECT

 public:
  explicit CamFigure(QCustomPlot* plot);

  // The programme and checks of g; `limitDeg` the pressure angle's limit drawn.
  void build(const cam::CamGeometry& g, const cam::CamChecks& checks, double limitDeg);
  // Nothing to draw: the plot says why.
  void showNothing(const QString& why);

  // For tests and tools: the plots drawn (5 with a programme), the pixel of a cam angle and
  // value on plot `rect` (0 s, 1 s', 2 s'', 3 s''', 4 the check), and the segment ends drawn.
  int rects() const { return static_cast<int>(rects_.size()); }
  QPointF pixelAt(int rect, double camDeg, double value) const;
  const std::vector<double>& ends() const { return ends_; }
  // The end of segment k (not the last, which is 360) near a pixel: k, or -1.
  int endNear(const QPointF& pixel) const;

 Q_SIGNALS:
  // The end of segment k dragged to `deg` (between its neighbours'); `done` on release.
  void endDragged(int k, double deg, bool done);

 protected:
  bool eventFilter(QObject* watched, QEvent* e) override;

 private:
  QCPAxisRect* addRect(int row, const QString& label);
  void drawCurves(const cam::CamGeometry& g);
  void drawCheck(const cam::CamGeometry& g, const cam::CamChecks& checks, double limitDeg);
  void markSegments(const cam::Program& p);
  void markExtreme(QCPAxisRect* rect, double deg, double value, const QString& text);

  std::vector<QCPAxisRect*> rects_;
  std::vector<double> ends_;  // the segments' ends but the last (degrees)
  int dragged_ = -1;
};

}  // namespace linkage::ui
