// What the editor's design checks cost a frame and an edit: the canvas of the 876 needle
// mechanism painted with the extreme positions and the transmission arcs off and on (the same
// view, rounds interleaved so that a loaded machine slows both alike), the arcs' work per pose,
// and the extreme poses' search per design. Prints medians (Release build, offscreen):
// `build/bench/linkage_design_bench [EXAMPLE]`. Not a test: numbers for docs/benchmarks.md.
#include <QAction>
#include <QApplication>
#include <QImage>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <vector>

#include "canvas/canvas_view.h"
#include "design/design_overlays.h"
#include "design/extremes_item.h"
#include "design/transmission_item.h"
#include "document/document.h"
#include "window/features.h"

namespace {

using namespace linkage;
using namespace linkage::ui;
using Clock = std::chrono::steady_clock;

double seconds(const std::function<void()>& f, int calls) {
  const auto start = Clock::now();
  for (int i = 0; i < calls; ++i) f();
  return std::chrono::duration<double>(Clock::now() - start).count() / calls;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

void row(const char* what, double s) {
  if (s < 1e-3)
    std::printf("| %s | %.1f us |\n", what, s * 1e6);
  else
    std::printf("| %s | %.2f ms |\n", what, s * 1e3);
}

}  // namespace

int main(int argc, char** argv) {
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("linkage-bench"));
  const QString example = argc > 1 ? QString::fromLocal8Bit(argv[1]) : "needle-876-alpha-35";
  MainWindow w;
  w.resize(1280, 800);
  if (!w.openExample(example)) return 2;
  w.show();
  for (int i = 0; i < 3; ++i) QApplication::processEvents();
  w.canvas()->fitToMechanism();
  Document* d = w.document();
  d->setCrankDeg(60);
  QWidget* canvas = w.canvas()->viewport();
  QImage image(canvas->size(), QImage::Format_ARGB32_Premultiplied);
  QAction* extremes = w.designChecks().showExtremes;
  QAction* arcs = w.designChecks().showTransmission;
  // The canvas painted, as a frame paints it (the whole viewport), with each combination.
  const std::pair<bool, bool> states[] = {
      {false, false}, {true, false}, {false, true}, {true, true}};
  std::vector<double> paint[4];
  for (int round = 0; round < 15; ++round)
    for (int s = 0; s < 4; ++s) {
      extremes->setChecked(states[s].first);
      arcs->setChecked(states[s].second);
      QApplication::processEvents();
      paint[s].push_back(seconds([&] { canvas->render(&image); }, 40));
    }
  std::printf("\n| %s, canvas %dx%d px, crank 60 deg | median of 15 |\n|---|---|\n",
              qPrintable(example), canvas->width(), canvas->height());
  row("paint the canvas, overlays off", median(paint[0]));
  row("paint the canvas, extreme positions on", median(paint[1]));
  row("paint the canvas, transmission arcs on", median(paint[2]));
  row("paint the canvas, both on", median(paint[3]));

  // Per pose: the arcs read the angles (no solve); per design: the extremes are searched.
  TransmissionItem* item = w.designChecks().overlays()->transmissionItem();
  const Kinematics& k = d->kinematics();
  std::vector<double> pose, search;
  for (int round = 0; round < 15; ++round) {
    pose.push_back(seconds([&] { item->setPose(k); }, 2000));
    const std::optional<LimitMeasure> what = LimitMeasure::along(
        d->design().outputs.front(), defaultDirection(d->design(), d->design().outputs.front()));
    search.push_back(seconds([&] { findExtremePoses(k, *what); }, 20));
  }
  std::printf("| arcs at a pose (TransmissionItem::setPose, %zu joints) | %.1f us |\n",
              item->joints().size(), median(pose) * 1e6);
  row("extreme poses of the output (findLimits, the poses, their drawings)", median(search));
  return 0;
}
