// The plots dock on a machine in space, driven through its controls as a user does: the distance
// between two points in space (the hook's point and the needle's, at right angles) and a
// direction tilted out of the x-y plane, each sample the solver's world motion there; the
// elevation offered only on a machine in space.
#include <gtest/gtest.h>

#include "ui_test.h"

#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QTest>
#include <cmath>

#include "document/document.h"
#include "drawing.h"
#include "plots/plots_panel.h"
#include "window/main_window.h"
#include "window/plots_feature.h"

namespace linkage::ui {
namespace {

template <class W>
W* child(MainWindow& w, const char* name) {
  W* c = w.findChild<W*>(name);
  EXPECT_NE(c, nullptr) << name;
  return c;
}

TEST(PlotsInSpace, TheDistanceFromTheHookToTheNeedleIsChosenInTheControls) {
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "lockstitch-bevel"));
  w.plots().dock->show();
  QApplication::processEvents();
  auto* component = child<QComboBox>(w, "plotComponent");
  auto* to = child<QComboBox>(w, "plotDistanceTo");
  ASSERT_TRUE(component && to);
  EXPECT_FALSE(to->isVisibleTo(&w));  // only for a distance
  component->setCurrentIndex(static_cast<int>(Quantity::Component::Distance));
  QApplication::processEvents();
  EXPECT_TRUE(to->isVisibleTo(&w));
  to->setCurrentIndex(to->findData("hook.K"));
  QApplication::processEvents();
  PlotsPanel* panel = w.plots().panel();
  EXPECT_EQ(panel->request().component, Quantity::Component::Distance);
  EXPECT_EQ(panel->request().other, "hook.K");
  ASSERT_TRUE(QTest::qWaitFor([&] { return panel->curves(0) != nullptr; }, 5000));
  const CurveSet* set = panel->curves(0);
  ASSERT_TRUE(set->status().ok()) << set->status().message;
  const Mechanism& m = w.document()->design();
  const PointId a = *m.findPoint(panel->request().target.toStdString()), b = *m.findPoint("hook.K");
  ASSERT_NE(a, b);
  const Curve& d = set->curve(Order::Position);
  const Curve& v = set->curve(Order::Velocity);
  ASSERT_FALSE(d.values.empty());
  Kinematics at = w.document()->kinematics();
  for (size_t i = 0; i < d.values.size(); i += 7) {
    ASSERT_TRUE(at.moveTo(d.crankDeg[i]).ok());
    const Kinematics::PointMotion3 p = at.motionInSpace(a), q = at.motionInSpace(b);
    const Vec3 D = p.position - q.position;
    EXPECT_NEAR(d.values[i], D.norm(), 1e-9 * at.size()) << d.crankDeg[i];
    EXPECT_NEAR(v.values[i], D.dot(p.velocity - q.velocity) / D.norm(),
                1e-9 * at.size() * at.omega())
        << d.crankDeg[i];
  }
  EXPECT_TRUE(panel->cursorText().contains("d to hook.K")) << panel->cursorText();
  shot(w.plots().dock, "plots-distance-in-space");
}

TEST(PlotsInSpace, ADirectionTiltedOutOfTheXYPlaneIsTheWorlds) {
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "rssr-crank-rocker"));
  w.plots().dock->show();
  QApplication::processEvents();
  auto* elevation = child<QDoubleSpinBox>(w, "plotElevation");
  ASSERT_TRUE(elevation);
  EXPECT_TRUE(elevation->isVisibleTo(&w));
  PlotsPanel* panel = w.plots().panel();
  CurveRequest r = panel->request();
  r.target = "rocker.C";
  r.component = Quantity::Component::Along;
  r.directionDeg = 30;
  r.elevationDeg = 45;
  panel->setRequest(r);
  QApplication::processEvents();
  EXPECT_DOUBLE_EQ(elevation->value(), 45);
  EXPECT_TRUE(elevation->isEnabled());
  const CurveSet* set = panel->curves(0);
  ASSERT_NE(set, nullptr);
  ASSERT_TRUE(set->status().ok()) << set->status().message;
  const double c = std::cos(M_PI / 4);
  const Vec3 u(c * std::cos(M_PI / 6), c * std::sin(M_PI / 6), std::sin(M_PI / 4));
  const Curve& pos = set->curve(Order::Position);
  Kinematics at = w.document()->kinematics();
  const PointId C = *at.mechanism().findPoint("rocker.C");
  for (size_t i = 0; i < pos.values.size(); i += 11) {
    ASSERT_TRUE(at.moveTo(pos.crankDeg[i]).ok());
    EXPECT_NEAR(pos.values[i], u.dot(at.motionInSpace(C).position), 1e-9 * at.size());
  }
  EXPECT_TRUE(panel->cursorText().contains(QString::fromUtf8("at 45° up"))) << panel->cursorText();
  shot(w.plots().dock, "plots-tilted-direction");
}

TEST(PlotsInSpace, APlanarMachineOffersNoElevation) {
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "four-bar-crank-rocker"));
  w.plots().dock->show();
  QApplication::processEvents();
  auto* elevation = child<QDoubleSpinBox>(w, "plotElevation");
  ASSERT_TRUE(elevation);
  EXPECT_FALSE(elevation->isVisibleTo(&w));
}

}  // namespace
}  // namespace linkage::ui
