// How long the plots take: sampling the curves of a mechanism, the figure, moving the cursor,
// exports; and how exact the spectral jerk is against the slider-crank's closed form. Prints
// medians (Release build, offscreen): `build/bench/linkage_plots_bench`. Not a test: numbers
// for docs/benchmarks.md.
#include <QApplication>
#include <QImage>
#include <QPainter>
#include <QTemporaryDir>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "bench_common.h"
#include "export/animation_export.h"
#include "figures/figure_export.h"
#include "figures/qcp.h"
#include "linkage/extremes.h"
#include "linkage/motion_samples.h"
#include "plots/curve_set.h"
#include "plots/motion_figure.h"
#include "reference/dual.h"

namespace {

using namespace linkage;
using Clock = std::chrono::steady_clock;

// Median over 7 rounds of the time per call, each round at least 0.2 s (or `minCalls`).
double medianSeconds(const std::function<void()>& f, int minCalls = 1) {
  std::vector<double> rounds;
  for (int r = 0; r < 7; ++r) {
    int calls = 0;
    const auto start = Clock::now();
    double elapsed = 0;
    do {
      f();
      ++calls;
      elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    } while (elapsed < 0.2 || calls < minCalls);
    rounds.push_back(elapsed / calls);
  }
  std::sort(rounds.begin(), rounds.end());
  return rounds[3];
}

void row(const char* what, double seconds) {
  if (seconds < 1e-3)
    std::printf("| %s | %.1f us |\n", what, seconds * 1e6);
  else
    std::printf("| %s | %.2f ms |\n", what, seconds * 1e3);
}

void solverSide() {
  const Mechanism m = bench::example("wanzer-inversion-2");
  Kinematics k;
  k.load(m);
  const PointId G = m.outputs.at(0);
  SampleSpec spec;
  spec.points = {G};
  std::printf("\n| Wanzer inversion 2, point G, 360 steps x 1 revolution | median |\n|---|---|\n");
  row("sample positions, velocities, accelerations", medianSeconds([&] { sampleMotion(k, spec); }));
  spec.accelerations = false;
  row("sample positions and velocities only", medianSeconds([&] { sampleMotion(k, spec); }));
  spec.accelerations = true;
  const MotionSamples s = sampleMotion(k, spec);
  const Quantity y = Quantity::ofPoint(G, Quantity::Component::Y);
  row("three curves (position, velocity, acceleration)", medianSeconds([&] {
        for (int o = 0; o < 3; ++o) curveOf(s, y, static_cast<Order>(o));
      }));
  row("jerk curve (spectral derivative)", medianSeconds([&] { curveOf(s, y, Order::Jerk); }));
  row("extremes of the three, placed between samples", medianSeconds([&] {
        for (int o = 0; o < 3; ++o) extremesOf(s, y, static_cast<Order>(o));
      }));
  row("harmonics of the three (k <= 20)", medianSeconds([&] {
        for (int o = 0; o < 3; ++o) harmonicsOf(s, y, static_cast<Order>(o), 20);
      }));
  ui::CurveRequest req;
  req.target = "needlebar.G";
  row("CurveSet: all of the above for three orders",
      medianSeconds([&] { ui::CurveSet set(k, req, "w"); }));
  req.orders = {true, true, true, true};
  row("CurveSet with jerk", medianSeconds([&] { ui::CurveSet set(k, req, "w"); }));
}

void jerkAccuracy() {
  std::printf(
      "\n| slider-crank, lambda | steps per revolution | max jerk error / peak jerk | "
      "error estimate / peak |\n|---|---|---|---|\n");
  for (double l : {50.0, 30.0}) {
    const Mechanism m =
        bench::example(l == 50 ? "slider-crank-22a-lambda-0.3" : "slider-crank-22a-lambda-0.5");
    Kinematics k;
    k.load(m);
    const PointId B = *m.findPoint("needlebar.B");
    for (long long steps : {24LL, 36LL, 90LL, 360LL, 3600LL}) {
      SampleSpec spec;
      spec.points = {B};
      spec.steps = steps;
      const MotionSamples s = sampleMotion(k, spec);
      const Curve j = curveOf(s, Quantity::ofPoint(B, Quantity::Component::Y), Order::Jerk);
      double err = 0, peak = 0;
      for (long long i = 0; i < s.size(); ++i) {
        const __float128 phi = __float128(s.crankDeg[i]) * linkref::pi<__float128>() / 180;
        const double ref = double(
            linkref::slider_crank_jerk(linkref::slider_crank_22a<__float128>(__float128(l)), phi)
                .jy);
        err = std::max(err, std::abs(j.values[i] - ref));
        peak = std::max(peak, std::abs(ref));
      }
      std::printf("| %.1f | %lld | %.1e | %.1e |\n", 15 / l, steps, err / peak,
                  j.errorEstimate / peak);
    }
  }
}

void uiSide() {
  const Mechanism m = bench::example("wanzer-inversion-2");
  Kinematics k;
  k.load(m);
  ui::CurveRequest req;
  req.target = "needlebar.G";
  ui::CurveSet set(k, req, "Wanzer needle bar, inversion 2");
  QCustomPlot plot;
  plot.resize(700, 600);
  plot.show();
  QApplication::processEvents();
  ui::MotionFigure figure(&plot);
  ui::MotionFigure::Options opt;
  std::printf("\n| figure of 3 plots, 700 x 600 px, offscreen | median |\n|---|---|\n");
  row("build the figure (layout, data, full replot)",
      medianSeconds([&] { figure.build({&set}, opt); }));
  row("full replot", medianSeconds([&] { plot.replot(); }));
  row("full replot + paint", medianSeconds([&] {
        plot.replot();
        plot.repaint();
      }));
  double deg = 0;
  row("cursor moved: its layer replotted", medianSeconds([&] {
        deg = std::fmod(deg + 1, 360);
        figure.setCursor(deg);
      }));
  row("cursor moved + paint", medianSeconds([&] {
        deg = std::fmod(deg + 1, 360);
        figure.setCursor(deg);
        plot.repaint();
      }));
  row("values at the cursor (solver copy moved 1 degree)", medianSeconds([&] {
        deg = std::fmod(deg + 1, 360);
        set.valuesAt(deg);
      }));
  QTemporaryDir dir;
  for (const char* ext : {"png", "pdf", "svg"}) {
    const QString path = dir.filePath(QString("f.%1").arg(ext));
    const std::string what = std::string("export 1200 x 900 ") + ext;
    row(what.c_str(),
        medianSeconds([&] { ui::exportPlot(&plot, path, QSize(1200, 900), nullptr); }));
  }
  // A GIF of 72 frames, 640 x 480, of a scene with antialiased links (the renderer's own time
  // included, as the canvas's would be).
  ui::AnimationSpec spec;
  spec.path = dir.filePath("a.gif");
  spec.frames = 72;
  const ui::FrameRenderer render = [](double a, QSize size) {
    QImage img(size, QImage::Format_RGB32);
    img.fill(Qt::white);
    QPainter p(&img);
    p.setRenderHint(QPainter::Antialiasing);
    p.translate(size.width() / 2.0, size.height() / 2.0);
    p.rotate(-a);
    p.setPen(QPen(QColor(31, 119, 180), 8));
    p.drawLine(QPointF(0, 0), QPointF(150, 0));
    p.setPen(QPen(QColor(214, 39, 40), 5));
    p.drawLine(QPointF(150, 0), QPointF(-60, 140));
    return img;
  };
  const double rendering = medianSeconds([&] { render(33, spec.size); });
  row("GIF frame: render (stand-in scene)", rendering);
  const double gif = medianSeconds([&] { ui::exportAnimation(spec, render, nullptr); }, 1);
  row("GIF of 72 frames 640 x 480, all", gif);
  row("GIF per frame, less rendering", gif / 72 - rendering * (72 + 12) / 72);
}

}  // namespace

int main(int argc, char** argv) {
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  solverSide();
  jerkAccuracy();
  uiSide();
  return 0;
}
