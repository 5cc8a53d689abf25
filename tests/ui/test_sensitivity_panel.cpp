// The Sensitivity dock (issue 29): the dimensions ranked by how much they move the chosen
// output, against what must hold whatever the mechanism (moving the whole ground moves every
// point by as much: the ground points' x and y derivatives of a point's y add up to 0 and 1, the
// ground's slots moved with them where they move),
// the ranking by the turn's largest, and what cannot be differentiated yet said.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QTemporaryDir>
#include <QTest>
#include <memory>

#include "design/sensitivity_panel.h"
#include "document/document.h"
#include "examples.h"
#include "linkage/clearance_sensitivity.h"
#include "linkage/force_sensitivity.h"
#include "linkage/io/model_file.h"
#include "linkage/io/model_lookup.h"
#include "linkage/limits.h"
#include "linkage/shaking_sensitivity.h"
#include "linkage/stroke_sensitivity.h"
#include "linkage/timing.h"
#include "linkage/transmission_sensitivity.h"
#include "linkage/window_sensitivity.h"
#include "spatial_fixtures.h"
#include "ui_test.h"

namespace linkage::ui {
namespace {

void settle(SensitivityPanel& panel) {
  QTest::qWait(40);
  QElapsedTimer t;
  t.start();
  while (panel.redrawPending() && t.elapsed() < 10000) QTest::qWait(5);
}

// Component `which` chosen in its box as a user does, the redraw waited for.
void pick(SensitivityPanel& panel, int which) {
  panel.componentBox()->setCurrentIndex(which);
  Q_EMIT panel.componentBox()->activated(which);
  settle(panel);
}

// `text` chosen in the Output box as a user does (its activation), the redraw waited for; false
// where the box has no such entry.
bool choose(SensitivityPanel& panel, const QString& text) {
  const int at = panel.pointBox()->findText(text);
  if (at < 0) return false;
  panel.pointBox()->setCurrentIndex(at);
  Q_EMIT panel.pointBox()->activated(at);
  settle(panel);
  return true;
}

TEST(SensitivityPanel, TheGroundsDimensionsMoveThePointAsAWhole) {
  Document doc;
  ASSERT_TRUE(doc.open(QString::fromStdString(*resolveModel("wanzer-inversion-2")), nullptr));
  doc.setCrankDeg(40);
  SensitivityPanel panel(&doc);
  panel.resize(900, 400);
  panel.show();
  settle(panel);
  ASSERT_EQ(panel.pointBox()->currentText(), "needlebar.G");  // the first output
  ASSERT_FALSE(panel.bars().empty());
  double x = 0, y = 0;
  for (const SensitivityPanel::Bar& b : panel.bars()) {
    EXPECT_GE(b.peak, std::abs(b.now)) << b.dimension;
    if (b.dimension.rfind("ground.", 0) != 0) continue;
    const std::string axis = b.dimension.substr(b.dimension.size() - 2);
    if (axis == ".x") x += b.now;
    if (axis == ".y") y += b.now;
  }
  // The needle's slot is vertical: moving the ground up leaves its offset, moving it sideways
  // does not (so x's sum is not asked here: the four-bar's below has no slot).
  EXPECT_NEAR(y, 1, 1e-12);
  for (size_t i = 1; i < panel.bars().size(); ++i)
    EXPECT_GE(panel.bars()[i - 1].peak, panel.bars()[i].peak);
  EXPECT_TRUE(panel.summary().startsWith("Matters most: " +
                                         QString::fromStdString(panel.bars()[0].dimension)))
      << panel.summary();
}

// Only what follows the pose is computed again when it changes: a point's derivatives at the
// crank angle, not the turn's largest (of the design and the output), nor a stroke.
TEST(SensitivityPanel, ANewPoseComputesOnlyWhatFollowsIt) {
  Document doc;
  ASSERT_TRUE(doc.open(QString::fromStdString(*resolveModel("wanzer-inversion-2")), nullptr));
  SensitivityPanel panel(&doc);
  panel.resize(900, 400);
  panel.show();
  settle(panel);
  ASSERT_EQ(panel.turnComputations(), 1);
  const double before = panel.bars()[0].peak;
  for (double deg : {30.0, 60.0, 90.0}) {
    doc.setCrankDeg(deg);
    settle(panel);
  }
  EXPECT_EQ(panel.turnComputations(), 1);
  EXPECT_EQ(panel.bars()[0].peak, before);
  Mechanism m = doc.design();
  m.point(*m.findPoint("ground.A"))->pos.x() += 1;
  doc.setDesign(m);
  settle(panel);
  EXPECT_EQ(panel.turnComputations(), 2);
  panel.quantityBox()->setCurrentIndex(3);
  Q_EMIT panel.quantityBox()->activated(3);
  settle(panel);
  doc.setCrankDeg(120);
  EXPECT_FALSE(panel.redrawPending());  // a stroke does not follow the pose
}

TEST(SensitivityPanel, AFourBarsPointMovesWithItsGround) {
  Document doc;
  ASSERT_TRUE(doc.open(QString::fromStdString(*resolveModel("four-bar-crank-rocker")), nullptr));
  doc.setCrankDeg(100);
  SensitivityPanel panel(&doc);
  panel.resize(900, 400);
  panel.show();
  settle(panel);
  for (int component : {0, 1}) {
    pick(panel, component);
    ASSERT_FALSE(panel.bars().empty());
    double x = 0, y = 0;
    for (const SensitivityPanel::Bar& b : panel.bars()) {
      if (b.dimension.rfind("ground.", 0) != 0) continue;
      (b.dimension.substr(b.dimension.size() - 2) == ".x" ? x : y) += b.now;
    }
    EXPECT_NEAR(x, component == 0 ? 1 : 0, 1e-12) << component;
    EXPECT_NEAR(y, component == 1 ? 1 : 0, 1e-12) << component;
  }
}

// The stroke: the library's envelope-theorem derivatives (tests/test_stroke_sensitivity.cpp
// holds them to closed forms and Euler's sum), ranked; the summary names the stroke.
TEST(SensitivityPanel, TheStrokesDimensionsRanked) {
  Document doc;
  ASSERT_TRUE(doc.open(QString::fromStdString(*resolveModel("wanzer-inversion-2")), nullptr));
  SensitivityPanel panel(&doc);
  panel.resize(900, 400);
  panel.show();
  settle(panel);
  panel.quantityBox()->setCurrentIndex(3);
  Q_EMIT panel.quantityBox()->activated(3);
  settle(panel);
  const Mechanism& m = doc.design();
  const PointId G = *m.findPoint("needlebar.G");
  const StrokeSensitivity want =
      strokeSensitivity(doc.kinematics(), G, defaultDirection(m, G), dimensions(m));
  ASSERT_TRUE(want.status.ok());
  ASSERT_EQ(panel.bars().size(), want.dims.size());
  for (const SensitivityPanel::Bar& b : panel.bars())
    for (size_t d = 0; d < want.dims.size(); ++d)
      if (want.dims[d].name == b.dimension) EXPECT_EQ(b.now, want.derivative[d]) << b.dimension;
  EXPECT_TRUE(panel.summary().startsWith("The stroke (35.7209 mm")) << panel.summary();
  shot(&panel, "stroke_sensitivity");
}

// A watched clearance's closest approach: after the points in the output list; its derivatives
// the library's (tests/test_clearance_sensitivity.cpp holds them to a closed form and Euler's
// sum); the machine's own hook-to-needle clearance touches (0: no derivative) and says so.
TEST(SensitivityPanel, AClearancesClosestApproach) {
  Document doc;
  ASSERT_TRUE(doc.open(QString::fromStdString(*resolveModel("lockstitch-machine")), nullptr));
  Mechanism m = doc.design();
  m.timing.clearances.push_back(
      {*m.findPoint("hook.K"), ClearancePart::of(*m.findPoint("needlebar.N")), {}});
  doc.setContents(m, QString());
  SensitivityPanel panel(&doc);
  panel.resize(900, 400);
  panel.show();
  settle(panel);
  const int n = panel.pointBox()->findText("closest approach: hook.K to needlebar.N");
  ASSERT_GE(n, 1);  // the file's own (to the needle's segment), then this one
  ASSERT_TRUE(panel.pointBox()->itemText(n - 1).startsWith("closest approach: hook.K to"));
  panel.pointBox()->setCurrentIndex(n - 1);
  Q_EMIT panel.pointBox()->activated(n - 1);
  settle(panel);
  EXPECT_TRUE(panel.bars().empty());
  EXPECT_TRUE(panel.summary().contains("touch")) << panel.summary();
  panel.pointBox()->setCurrentIndex(n);
  Q_EMIT panel.pointBox()->activated(n);
  settle(panel);
  const ClearanceSensitivity want =
      clearanceSensitivity(doc.kinematics(), m.timing.clearances[1], dimensions(m));
  ASSERT_TRUE(want.status.ok()) << want.status.message;
  ASSERT_EQ(panel.bars().size(), want.dims.size());
  for (const SensitivityPanel::Bar& b : panel.bars())
    for (size_t d = 0; d < want.dims.size(); ++d)
      if (want.dims[d].name == b.dimension) EXPECT_EQ(b.now, want.derivative[d]) << b.dimension;
  EXPECT_TRUE(panel.summary().startsWith("The closest approach")) << panel.summary();
}

// A window's start and end: after the clearances; the library's derivatives
// (tests/test_window_sensitivity.cpp holds them to the slider-crank's closed form).
TEST(SensitivityPanel, AWindowsEnds) {
  Document doc;
  ASSERT_TRUE(doc.open(QString::fromStdString(*resolveModel("lockstitch-machine")), nullptr));
  SensitivityPanel panel(&doc);
  panel.resize(900, 400);
  panel.show();
  settle(panel);
  ASSERT_TRUE(choose(panel, "window needle: its end"));
  const Mechanism& m = doc.design();
  const WindowSensitivity want = windowSensitivity(doc.kinematics(), "needle", dimensions(m));
  ASSERT_TRUE(want.status.ok()) << want.status.message;
  ASSERT_EQ(panel.bars().size(), want.dims.size());
  for (const SensitivityPanel::Bar& b : panel.bars())
    for (size_t d = 0; d < want.dims.size(); ++d)
      if (want.dims[d].name == b.dimension)
        EXPECT_EQ(b.now, want.intervals[0].dTo[d]) << b.dimension;
  EXPECT_TRUE(panel.summary().startsWith("Window needle closes at crank 228.41"))
      << panel.summary();
}

// A window on a machine in space, on a point's world z (it was left out of the list): its end's
// derivatives, the library's (tests/test_spatial_window_sensitivity.cpp holds them to the
// lockstitch machine's closed form).
TEST(SensitivityPanel, AWindowInSpace) {
  const Mechanism m = test::exampleWithWindow("lockstitch-bevel", "low=vshaft.M:z>6");
  QTemporaryDir dir;
  const QString path = dir.filePath("bevel.linkage.json");
  ASSERT_TRUE(saveMechanismFile(m, path.toStdString()).ok);
  Document doc;
  ASSERT_TRUE(doc.open(path, nullptr));
  SensitivityPanel panel(&doc);
  panel.resize(900, 400);
  panel.show();
  settle(panel);
  ASSERT_TRUE(choose(panel, "window low: its start"));
  const WindowSensitivity want =
      windowSensitivity(doc.kinematics(), "low", dimensions(doc.design()));
  ASSERT_TRUE(want.status.ok()) << want.status.message;
  ASSERT_EQ(panel.bars().size(), want.dims.size());
  for (const SensitivityPanel::Bar& b : panel.bars())
    for (size_t d = 0; d < want.dims.size(); ++d)
      if (want.dims[d].name == b.dimension)
        EXPECT_EQ(b.now, want.intervals[0].dFrom[d]) << b.dimension;
  EXPECT_TRUE(panel.summary().startsWith("Window low opens at crank 210")) << panel.summary();
  shot(&panel, "space_window_sensitivity");
}

// A dyad's transmission angle: after the windows, numbered as linkage-cli transmission numbers
// them; at the crank angle the library's derivatives (tests/test_transmission_sensitivity.cpp
// holds them to the law of cosines), which add up to 0 weighted by the lengths (an angle is
// scale-free); followed by the pose, the turn's largest not computed again for it.
TEST(SensitivityPanel, ATransmissionAngle) {
  Document doc;
  ASSERT_TRUE(doc.open(QString::fromStdString(*resolveModel("four-bar-crank-rocker")), nullptr));
  doc.setCrankDeg(100);
  SensitivityPanel panel(&doc);
  panel.resize(900, 400);
  panel.show();
  settle(panel);
  const int at = panel.pointBox()->findText("transmission angle 0: mu:coupler.B");
  ASSERT_EQ(at, panel.pointBox()->count() - 1);
  panel.pointBox()->setCurrentIndex(at);
  Q_EMIT panel.pointBox()->activated(at);
  settle(panel);
  const int turns = panel.turnComputations();
  for (double deg : {100.0, 250.0}) {
    doc.setCrankDeg(deg);
    settle(panel);
    const Mechanism& m = doc.design();
    const Kinematics& k = doc.kinematics();
    Sensitivity s;
    ASSERT_TRUE(s.prepare(k, dimensions(m)).ok());
    ASSERT_TRUE(s.at(k).ok());
    const std::vector<double> want = transmissionAngleDerivatives(k, transmissionJoints(m)[0], s);
    ASSERT_EQ(panel.bars().size(), want.size());
    double euler = 0, size = 0;
    for (const SensitivityPanel::Bar& b : panel.bars())
      for (size_t d = 0; d < want.size(); ++d)
        if (s.dims()[d].name == b.dimension) {
          EXPECT_EQ(b.now, want[d]) << b.dimension;
          EXPECT_GE(b.peak, std::abs(b.now)) << b.dimension;
          euler += s.dims()[d].value * b.now;
          size += std::abs(s.dims()[d].value * b.now);
        }
    EXPECT_NEAR(euler, 0, 1e-12 * size) << deg;
    EXPECT_TRUE(panel.summary().startsWith("mu:coupler.B is ")) << panel.summary();
  }
  EXPECT_EQ(panel.turnComputations(), turns);
  shot(&panel, "transmission_sensitivity");
}

// On a machine in space a transmission angle lies in its plane: the overedge machine's lower
// gripper (a dyad in the gripper plane), the library's derivatives from the world's
// sensitivities (tests/test_spatial_transmission_sensitivity.cpp holds them to changed designs),
// a plane's origin among the bars; not "Not yet".
TEST(SensitivityPanel, ATransmissionAngleInSpace) {
  Document doc;
  ASSERT_TRUE(doc.open(QString::fromStdString(*resolveModel("overedge-machine")), nullptr));
  doc.setCrankDeg(140);
  SensitivityPanel panel(&doc);
  panel.resize(900, 400);
  panel.show();
  settle(panel);
  ASSERT_TRUE(choose(panel, "transmission angle 1: mu:lowerlink.M"));
  EXPECT_TRUE(panel.summary().startsWith("mu:lowerlink.M is ")) << panel.summary();
  const Mechanism& m = doc.design();
  const Kinematics& k = doc.kinematics();
  Sensitivity s;
  ASSERT_TRUE(s.prepare(k, dimensions(m), Sensitivity::Space::World).ok());
  ASSERT_TRUE(s.at(k).ok());
  const std::vector<double> want = transmissionAngleDerivatives(k, transmissionJoints(m)[1], s);
  ASSERT_EQ(panel.bars().size(), want.size());
  bool origin = false;
  for (const SensitivityPanel::Bar& b : panel.bars())
    for (size_t d = 0; d < want.size(); ++d)
      if (s.dims()[d].name == b.dimension) {
        EXPECT_EQ(b.now, want[d]) << b.dimension;
        origin = origin || b.dimension.rfind("planes.", 0) == 0;
      }
  EXPECT_TRUE(origin);
  shot(&panel, "transmission_sensitivity_space");
}

// A machine in space (the RSSR: a crank in the drawing plane, a rocker in an inclined plane, a
// ball rod): the dock offers the world's z besides x and y; moving the whole machine along x (the
// ground's x and the rocker plane's origin's x) moves the rocker point by (1, 0, 0): its x bars
// add up to 1 and its z bars to 0 over those dimensions. A planar design again: no z.
TEST(SensitivityPanel, AMachineInSpaceShowsTheWorldsXYAndZ) {
  Document doc;
  ASSERT_TRUE(doc.open(QString::fromStdString(*resolveModel("rssr-crank-rocker")), nullptr));
  doc.setCrankDeg(70);
  SensitivityPanel panel(&doc);
  panel.resize(900, 400);
  panel.show();
  settle(panel);
  ASSERT_EQ(panel.pointBox()->currentText(), "rocker.C");
  ASSERT_EQ(panel.componentBox()->count(), 4);
  EXPECT_EQ(panel.componentBox()->itemText(3), "z");
  auto sumAlongX = [&] {
    double sum = 0;
    for (const SensitivityPanel::Bar& b : panel.bars())
      if (b.dimension == "ground.O.x" || b.dimension == "ground.H.x" ||
          b.dimension == "planes.rocker.origin.x")
        sum += b.now;
    return sum;
  };
  pick(panel, 0);
  ASSERT_FALSE(panel.bars().empty());
  EXPECT_NEAR(sumAlongX(), 1, 1e-12);
  pick(panel, 3);
  EXPECT_NEAR(sumAlongX(), 0, 1e-12);
  bool rod = false;
  for (const SensitivityPanel::Bar& b : panel.bars())
    rod = rod || (b.dimension == "ball-rod:crank.A.length" && std::abs(b.now) > 1e-3);
  EXPECT_TRUE(rod) << "the rod's length moves the rocker point's z";
  ASSERT_TRUE(doc.open(QString::fromStdString(*resolveModel("four-bar-crank-rocker")), nullptr));
  settle(panel);
  EXPECT_EQ(panel.componentBox()->count(), 3);
  EXPECT_EQ(panel.componentBox()->currentIndex(), 1);
}

// The RSSR with masses in a file of its own at crank angle 70, the dock shown on it.
class RssrDock : public ::testing::Test {
 protected:
  void SetUp() override {
    const QString path = dir_.filePath("rssr.linkage.json");
    ASSERT_TRUE(saveMechanismFile(test::rssrWithMasses(), path.toStdString()).ok);
    ASSERT_TRUE(doc.open(path, nullptr));
    doc.setCrankDeg(70);
    panel_ = std::make_unique<SensitivityPanel>(&doc);
    panel_->resize(900, 400);
    panel_->show();
    settle(*panel_);
  }
  QTemporaryDir dir_;
  Document doc;
  std::unique_ptr<SensitivityPanel> panel_;
};

// The shaking force (a design with masses: the drop feed): its x, y and the length of its
// change per unit of each dimension, the library's (tests/test_optimize_shaking.cpp holds it to
// a slider-crank's closed form) at each pose, the turn's largest computed once per component.
// On a machine in space the shaking force is the world's, its z the fourth component: the RSSR
// with masses, the library's derivatives (tests/test_spatial_force_sensitivity.cpp holds them to
// changed designs).
TEST_F(RssrDock, TheShakingForceInSpace) {
  SensitivityPanel& panel = *panel_;
  ASSERT_TRUE(choose(panel, "shaking force"));
  ASSERT_EQ(panel.componentBox()->count(), 4);
  pick(panel, 3);  // z
  Kinematics k = doc.kinematics();
  k.setAccelerations(true);
  Sensitivity s;
  ASSERT_TRUE(s.prepare(k, dimensions(k.mechanism()), Sensitivity::Space::World).ok());
  ASSERT_TRUE(s.at(k).ok());
  ASSERT_EQ(panel.bars().size(), s.dims().size());
  double largest = 0;
  for (const SensitivityPanel::Bar& b : panel.bars())
    for (size_t d = 0; d < s.dims().size(); ++d)
      if (s.dims()[d].name == b.dimension) {
        // (to rounding: the panel's turn moved its own copy of the pose in between)
        const double want = shakingForceSensitivity3(k, s, static_cast<int>(d)).z();
        EXPECT_NEAR(b.now, want, 1e-12 * (1 + std::abs(want))) << b.dimension;
        largest = std::max(largest, std::abs(b.now));
      }
  EXPECT_GT(largest, 1e-3);
  EXPECT_TRUE(panel.summary().startsWith("The frame feels ")) << panel.summary();
  shot(&panel, "space_shaking_sensitivity");
}

// A bearing's reaction on a machine in space: in its plane class's frame (x, y), and its z the
// normal force the rocker's pin takes out of the plane; the library's derivatives.
TEST_F(RssrDock, ABearingsReactionInSpace) {
  SensitivityPanel& panel = *panel_;
  ASSERT_TRUE(choose(panel, "reaction at pin:ground.H"));
  ASSERT_EQ(panel.componentBox()->count(), 4);
  const JointForceSensitivity f =
      jointForceSensitivity(doc.kinematics(), doc.design().joints[1].id, dimensions(doc.design()));
  ASSERT_TRUE(f.status.ok()) << f.status.message;
  for (int which : {0, 3}) {  // x, then z
    pick(panel, which);
    ASSERT_EQ(panel.bars().size(), f.dims.size());
    double largest = 0;
    for (const SensitivityPanel::Bar& b : panel.bars())
      for (size_t d = 0; d < f.dims.size(); ++d)
        if (f.dims[d].name == b.dimension) {
          EXPECT_EQ(b.now, which == 3 ? f.change[d].normalN : f.change[d].force.x()) << b.dimension;
          largest = std::max(largest, std::abs(b.now));
        }
    EXPECT_GT(largest, 1e-4) << which;
  }
  EXPECT_TRUE(panel.summary().startsWith("The pin bears ")) << panel.summary();
  EXPECT_TRUE(panel.summary().contains("out of the plane")) << panel.summary();
  shot(&panel, "space_bearing_sensitivity");
  // A pin between two moving bodies bears nothing out of the plane: no z offered (the overedge
  // machine with masses).
  {
    const QString path = dir_.filePath("overedge.linkage.json");
    ASSERT_TRUE(saveMechanismFile(test::withMasses(test::example("overedge-machine"), 7),
                                  path.toStdString())
                    .ok);
    Document overedge;
    ASSERT_TRUE(overedge.open(path, nullptr));
    SensitivityPanel other(&overedge);
    other.show();
    settle(other);
    ASSERT_TRUE(choose(other, "reaction at pin:needlerock.C"));
    EXPECT_EQ(other.componentBox()->count(), 3);
    ASSERT_TRUE(choose(other, "reaction at pin:ground.H"));
    EXPECT_EQ(other.componentBox()->count(), 4);
  }
  // A ball rod's reaction is its tension: one number, no component to choose.
  ASSERT_TRUE(choose(panel, "reaction at ball-rod:crank.A"));
  EXPECT_FALSE(panel.componentBox()->isEnabled());
  const JointForceSensitivity rod =
      jointForceSensitivity(doc.kinematics(), doc.design().joints[2].id, dimensions(doc.design()));
  ASSERT_TRUE(rod.status.ok()) << rod.status.message;
  ASSERT_EQ(panel.bars().size(), rod.dims.size());
  for (const SensitivityPanel::Bar& b : panel.bars())
    for (size_t d = 0; d < rod.dims.size(); ++d)
      if (rod.dims[d].name == b.dimension) EXPECT_EQ(b.now, rod.change[d].axialN) << b.dimension;
  EXPECT_TRUE(panel.summary().startsWith(
      QString("The ball-rod's tension is %1 N").arg(rod.reaction.axialN, 0, 'g', 4)))
      << panel.summary();
}

TEST(SensitivityPanel, TheShakingForce) {
  Document doc;
  ASSERT_TRUE(doc.open(QString::fromStdString(*resolveModel("drop-feed")), nullptr));
  doc.setCrankDeg(40);
  SensitivityPanel panel(&doc);
  panel.resize(900, 400);
  panel.show();
  settle(panel);
  ASSERT_TRUE(choose(panel, "shaking force"));  // the pins' reactions after it
  const int at = panel.pointBox()->currentIndex();
  EXPECT_TRUE(panel.componentBox()->isEnabled());
  for (int which : {0, 1, 2}) {
    pick(panel, which);
    const int turns = panel.turnComputations();
    for (double deg : {40.0, 200.0}) {
      doc.setCrankDeg(deg);
      settle(panel);
      Kinematics k = doc.kinematics();
      k.setAccelerations(true);
      Sensitivity s;
      ASSERT_TRUE(s.prepare(k, dimensions(k.mechanism())).ok());
      ASSERT_TRUE(s.at(k).ok());
      ASSERT_EQ(panel.bars().size(), s.dims().size());
      double largest = 0;
      for (const SensitivityPanel::Bar& b : panel.bars())
        for (size_t d = 0; d < s.dims().size(); ++d)
          if (s.dims()[d].name == b.dimension) {
            const Vec2 f = shakingForceSensitivity(k, s, static_cast<int>(d));
            EXPECT_EQ(b.now, which == 2 ? f.norm() : f[which]) << b.dimension;
            EXPECT_GE(b.peak, std::abs(b.now)) << b.dimension;
            largest = std::max(largest, std::abs(b.now));
          }
      EXPECT_GT(largest, 0.01) << which << " at " << deg;
      EXPECT_TRUE(panel.summary().startsWith("The frame feels ")) << panel.summary();
    }
    EXPECT_EQ(panel.turnComputations(), turns) << "once for the component, not again per pose";
  }
  shot(&panel, "shaking_sensitivity");
  // A pin's reaction, after the shaking force: the library's derivatives, the turn once.
  const int pin = panel.pointBox()->findText("reaction at pin:ground.L");
  ASSERT_EQ(pin, at + 2);  // pin:ground.M first
  panel.pointBox()->setCurrentIndex(pin);
  Q_EMIT panel.pointBox()->activated(pin);
  pick(panel, 1);
  const int turns = panel.turnComputations();
  for (double deg : {40.0, 200.0}) {
    doc.setCrankDeg(deg);
    settle(panel);
    const Kinematics& k = doc.kinematics();
    const JointForceSensitivity f =
        jointForceSensitivity(k, doc.design().joints[1].id, dimensions(doc.design()));
    ASSERT_TRUE(f.status.ok()) << f.status.message;
    ASSERT_EQ(panel.bars().size(), f.dims.size());
    for (const SensitivityPanel::Bar& b : panel.bars())
      for (size_t d = 0; d < f.dims.size(); ++d)
        if (f.dims[d].name == b.dimension) EXPECT_EQ(b.now, f.derivative[d].y()) << b.dimension;
    EXPECT_TRUE(panel.summary().startsWith("The pin bears ")) << panel.summary();
  }
  EXPECT_EQ(panel.turnComputations(), turns);
  shot(&panel, "reaction_sensitivity");
  // A design without masses has no such entry.
  ASSERT_TRUE(doc.open(QString::fromStdString(*resolveModel("four-bar-crank-rocker")), nullptr));
  settle(panel);
  const Mechanism& m = doc.design();
  const bool masses = std::any_of(m.bodies.begin(), m.bodies.end(),
                                  [](const Body& b) { return !b.ground && b.mass; });
  EXPECT_EQ(panel.pointBox()->findText("shaking force") >= 0, masses);
}

// The shaking moment (after the reactions): the library's derivatives at two crank angles, the
// turn's largest computed once; a machine without masses has no such entry.
TEST(SensitivityPanel, TheShakingMoment) {
  Document doc;
  ASSERT_TRUE(doc.open(QString::fromStdString(*resolveModel("drop-feed")), nullptr));
  doc.setCrankDeg(40);
  SensitivityPanel panel(&doc);
  panel.resize(900, 400);
  panel.show();
  settle(panel);
  ASSERT_TRUE(choose(panel, "shaking moment"));
  EXPECT_EQ(panel.pointBox()->currentIndex(), panel.pointBox()->count() - 1);
  EXPECT_FALSE(panel.componentBox()->isEnabled());
  const int turns = panel.turnComputations();
  for (double deg : {40.0, 200.0}) {
    doc.setCrankDeg(deg);
    settle(panel);
    Kinematics k = doc.kinematics();
    k.setAccelerations(true);
    Sensitivity s;
    ASSERT_TRUE(s.prepare(k, dimensions(k.mechanism())).ok());
    ASSERT_TRUE(s.at(k).ok());
    ASSERT_EQ(panel.bars().size(), s.dims().size());
    double largest = 0;
    for (const SensitivityPanel::Bar& b : panel.bars())
      for (size_t d = 0; d < s.dims().size(); ++d)
        if (s.dims()[d].name == b.dimension) {
          EXPECT_EQ(b.now, shakingMomentSensitivity(k, s, static_cast<int>(d))) << b.dimension;
          EXPECT_GE(b.peak, std::abs(b.now)) << b.dimension;
          largest = std::max(largest, std::abs(b.now));
        }
    EXPECT_GT(largest, 1e-3) << deg;
    EXPECT_TRUE(panel.summary().startsWith("The frame feels a moment of ")) << panel.summary();
  }
  EXPECT_EQ(panel.turnComputations(), turns) << "once for the moment, not again per pose";
  shot(&panel, "shaking_moment_sensitivity");
  ASSERT_TRUE(doc.open(QString::fromStdString(*resolveModel("overedge-machine")), nullptr));
  settle(panel);
  EXPECT_LT(panel.pointBox()->findText("shaking moment"), 0);  // no masses
}

// On a machine in space the shaking moment is the world's (about its origin): each component
// the component box chooses is the library's, and the length of the change is |dM|.
TEST_F(RssrDock, TheShakingMomentOnAMachineInSpace) {
  SensitivityPanel& panel = *panel_;
  ASSERT_TRUE(choose(panel, "shaking moment"));
  EXPECT_TRUE(panel.componentBox()->isEnabled());
  Kinematics k = doc.kinematics();
  k.setAccelerations(true);
  Sensitivity s;
  ASSERT_TRUE(s.prepare(k, dimensions(k.mechanism()), Sensitivity::Space::World).ok());
  ASSERT_TRUE(s.at(k).ok());
  ASSERT_EQ(panel.componentBox()->count(), 4);  // x, y, the length of the change, z
  for (int which : {0, 1, 2, 3}) {
    pick(panel, which);
    ASSERT_EQ(panel.bars().size(), s.dims().size());
    double largest = 0;
    for (const SensitivityPanel::Bar& b : panel.bars())
      for (size_t d = 0; d < s.dims().size(); ++d)
        if (s.dims()[d].name == b.dimension) {
          // (to rounding: the panel's turn moved its own copy of the pose in between)
          const Vec3 dm = shakingMomentSensitivity3(k, s, static_cast<int>(d));
          const double want = which == 2 ? dm.norm() : dm[which == 3 ? 2 : which];
          EXPECT_NEAR(b.now, want, 1e-12 * (1 + std::abs(want))) << b.dimension;
          largest = std::max(largest, std::abs(b.now));
        }
    EXPECT_GT(largest, 1e-3) << which;
  }
  EXPECT_TRUE(panel.summary().startsWith("The frame feels a moment of ")) << panel.summary();
  EXPECT_TRUE(panel.summary().contains("about the world's origin")) << panel.summary();
  shot(&panel, "shaking_moment_sensitivity_space");
}

// A stroke on a machine in space along the world's axis the component box chooses (the length
// of a change: y, as the command line's default): the library's derivatives along it.
TEST(SensitivityPanel, AStrokeInSpaceAlongTheAxisChosen) {
  Document doc;
  ASSERT_TRUE(doc.open(QString::fromStdString(*resolveModel("rssr-crank-rocker")), nullptr));
  SensitivityPanel panel(&doc);
  panel.resize(900, 400);
  panel.show();
  settle(panel);
  ASSERT_TRUE(choose(panel, "rocker.C"));
  panel.quantityBox()->setCurrentIndex(3);
  Q_EMIT panel.quantityBox()->activated(3);
  settle(panel);
  EXPECT_TRUE(panel.componentBox()->isEnabled());
  const Mechanism& m = doc.design();
  const PointId C = *m.findPoint("rocker.C");
  for (int which : {3, 0, 2}) {
    pick(panel, which);
    const Vec3 along = which == 3 ? Vec3::UnitZ() : which == 0 ? Vec3::UnitX() : Vec3::UnitY();
    const StrokeSensitivity want = strokeSensitivity(doc.kinematics(), C, along, dimensions(m));
    ASSERT_TRUE(want.status.ok()) << want.status.message;
    ASSERT_EQ(panel.bars().size(), want.dims.size());
    for (const SensitivityPanel::Bar& b : panel.bars())
      for (size_t d = 0; d < want.dims.size(); ++d)
        if (want.dims[d].name == b.dimension) EXPECT_EQ(b.now, want.derivative[d]) << b.dimension;
    const QString head = which == 2   ? "The stroke ("
                         : which == 3 ? "The stroke along z ("
                                      : "The stroke along x (";
    EXPECT_TRUE(panel.summary().startsWith(head)) << panel.summary().toStdString();
  }
  shot(&panel, "stroke_sensitivity_space");
}

// A gear's reaction (its tooth force, restated where the teeth meet): the library's derivatives
// of its y.
TEST(SensitivityPanel, AGearsReaction) {
  Document doc;
  ASSERT_TRUE(doc.open(QString::fromStdString(*resolveModel("drop-feed")), nullptr));
  doc.setCrankDeg(40);
  SensitivityPanel panel(&doc);
  panel.resize(900, 400);
  panel.show();
  settle(panel);
  ASSERT_TRUE(choose(panel, "reaction at gear:armshaft.M"));
  pick(panel, 1);
  const Mechanism& m = doc.design();
  size_t g = 0;
  while (g < m.joints.size() && std::string(kindOf(m.joints[g]).name) != "gear") ++g;
  ASSERT_LT(g, m.joints.size());
  const JointForceSensitivity f =
      jointForceSensitivity(doc.kinematics(), m.joints[g].id, dimensions(m));
  ASSERT_TRUE(f.status.ok()) << f.status.message;
  ASSERT_EQ(panel.bars().size(), f.dims.size());
  for (const SensitivityPanel::Bar& b : panel.bars())
    for (size_t d = 0; d < f.dims.size(); ++d)
      if (f.dims[d].name == b.dimension) EXPECT_EQ(b.now, f.derivative[d].y()) << b.dimension;
  EXPECT_TRUE(panel.summary().startsWith("The gear bears ")) << panel.summary();
  shot(&panel, "gear_reaction_sensitivity");
}

TEST(SensitivityPanel, WhatCannotBeDifferentiatedYetIsSaid) {
  Document doc;
  ASSERT_TRUE(doc.open(QString::fromStdString(*resolveModel("cam-translating-roller")), nullptr));
  SensitivityPanel panel(&doc);
  panel.resize(900, 400);
  panel.show();
  settle(panel);
  // A cam's follower is differentiated: its rises, base and roller among the bars.
  int cams = 0;
  for (const SensitivityPanel::Bar& b : panel.bars()) cams += b.dimension.rfind("cam:", 0) == 0;
  EXPECT_EQ(cams, 4) << panel.summary().toStdString();
  // A dyad with an arc slot's centre: its transmission angle listed and differentiated.
  ASSERT_TRUE(doc.open(QString::fromStdString(*resolveModel("curved-guide")), nullptr));
  settle(panel);
  ASSERT_TRUE(choose(panel, "transmission angle 0: mu:rod.B"));
  EXPECT_FALSE(panel.bars().empty());
  EXPECT_TRUE(panel.summary().startsWith("mu:rod.B is ")) << panel.summary();
}

}  // namespace
}  // namespace linkage::ui
