// The Sensitivity dock's Tolerances tab (issue 29): a tolerance typed is carried through the
// motion on a thread of its own (the window answers meanwhile); the band drawn is the first
// order of the exact derivatives (one dimension: |dy/dp| T at every angle, against the
// Sensitivity's own derivative), and Monte Carlo samples stay within first order's worst case
// but for second-order terms, far from a toggle.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QSignalSpy>
#include <QTabWidget>
#include <QTest>

#include "design/sensitivity_panel.h"
#include "design/tolerance_view.h"
#include "document/document.h"
#include "figures/qcp.h"
#include "linkage/io/model_lookup.h"
#include "linkage/sensitivity.h"
#include "ui_test.h"

namespace linkage::ui {
namespace {

bool waitFor(ToleranceView* v) {
  QElapsedTimer t;
  t.start();
  // Two minutes: the sanitizers' build beside another test's Monte Carlo took over 30 s.
  while ((v->busy() || v->result().rows.empty()) && t.elapsed() < 120000) QTest::qWait(10);
  return !v->busy() && !v->result().rows.empty();
}

TEST(ToleranceView, TheBandIsTheDerivativeTimesTheTolerance) {
  Document doc;
  ASSERT_TRUE(doc.open(QString::fromStdString(*resolveModel("wanzer-inversion-2")), nullptr));
  SensitivityPanel panel(&doc);
  panel.resize(1000, 420);
  panel.show();
  panel.findChild<QTabWidget*>("sensTabs")->setCurrentIndex(1);
  QTest::qWait(60);
  ToleranceView* view = panel.tolerances();
  view->setTolerance("triangle.E-G", 0.05);
  EXPECT_TRUE(view->busy());  // on its own thread: the window answers meanwhile
  ASSERT_TRUE(waitFor(view)) << view->summary();
  const ToleranceResult& r = view->result();
  ASSERT_EQ(r.rows.size(), 360u);
  // Independently: the Sensitivity's derivative of needlebar.G's y at each angle.
  Kinematics k = doc.kinematics();
  Sensitivity s;
  std::vector<Dimension> dims;
  for (Dimension& d : dimensions(k.mechanism()))
    if (d.name == "triangle.E-G") dims.push_back(d);
  ASSERT_EQ(dims.size(), 1u);
  ASSERT_TRUE(s.prepare(k, dims).ok());
  const PointId G = *doc.design().findPoint("needlebar.G");
  for (int i = 0; i < 360; i += 15) {
    ASSERT_TRUE(k.moveTo(i).ok());
    ASSERT_TRUE(s.at(k).ok());
    EXPECT_NEAR(r.rows[i].worst.y(), 0.05 * std::abs(s.point(k, G, 0).y()), 1e-12) << i;
    EXPECT_NEAR(r.rows[i].rss.y(), r.rows[i].worst.y(), 1e-12) << i;  // one dimension
  }
  // Samples, each solved exactly: within the worst case but for second-order terms (where the
  // derivative passes 0 the band closes to first order only), which are a small part of the
  // band's peak for a tolerance this small.
  view->setSamples(200);
  ASSERT_TRUE(waitFor(view) && view->result().used == 200) << view->summary();
  double peak = 0, over = 0;
  for (const ToleranceRow& row : view->result().rows) {
    peak = std::max(peak, row.worst.y());
    over = std::max({over, row.hi.y() - row.nominal.y() - row.worst.y(),
                     row.nominal.y() - row.lo.y() - row.worst.y()});
  }
  EXPECT_LT(over, 0.02 * peak) << over << " " << peak;
  EXPECT_GT(peak, 0.01);
  EXPECT_TRUE(view->summary().contains("200 of 200 solved")) << view->summary();
  shot(&panel, "tolerance_view");
}

// A machine in space (the overedge machine): with z chosen the tab shows the band of the
// needle's world z (not a refusal): first order |dz/dp| T from Sensitivity World, the axis
// saying so.
TEST(ToleranceView, AMachineInSpaceShowsItsZBand) {
  Document doc;
  ASSERT_TRUE(doc.open(QString::fromStdString(*resolveModel("overedge-machine")), nullptr));
  SensitivityPanel panel(&doc);
  panel.resize(1000, 420);
  panel.show();
  auto* point = panel.findChild<QComboBox*>("sensPoint");
  const int at = point->findText("needlearm.N");
  ASSERT_GE(at, 0);
  point->setCurrentIndex(at);
  QTest::qWait(30);
  auto* component = panel.findChild<QComboBox*>("sensComponent");
  ASSERT_EQ(component->count(), 4);  // x, y, the length of the change, z
  component->setCurrentIndex(3);
  panel.findChild<QTabWidget*>("sensTabs")->setCurrentIndex(1);
  QTest::qWait(60);
  ToleranceView* view = panel.tolerances();
  view->setTolerance("planes.rocker.origin.z", 0.1);
  ASSERT_TRUE(waitFor(view)) << view->summary();
  const ToleranceResult& r = view->result();
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_TRUE(r.space);
  Kinematics k = doc.kinematics();
  std::vector<Dimension> dims;
  for (Dimension& d : dimensions(k.mechanism()))
    if (d.name == "planes.rocker.origin.z") dims.push_back(d);
  ASSERT_EQ(dims.size(), 1u);
  Sensitivity s;
  ASSERT_TRUE(s.prepare(k, dims, Sensitivity::Space::World).ok());
  const PointId N = *doc.design().findPoint("needlearm.N");
  double peak = 0;
  for (int i = 0; i < 360; i += 30) {
    ASSERT_TRUE(k.moveTo(i).ok() && s.at(k).ok());
    EXPECT_NEAR(r.rows[i].worst.z(), 0.1 * std::abs(s.point3(k, N, 0).z()), 1e-12) << i;
    peak = std::max(peak, r.rows[i].worst.z());
  }
  EXPECT_GT(peak, 0.01);
  auto* plot = view->findChild<QCustomPlot*>("tolPlot");
  EXPECT_TRUE(plot->yAxis->label().startsWith("z from the nominal, in the world"))
      << plot->yAxis->label().toStdString();
  EXPECT_TRUE(view->summary().contains("world's y")) << view->summary().toStdString();
  shot(&panel, "tolerance_view_space");
}

}  // namespace
}  // namespace linkage::ui
