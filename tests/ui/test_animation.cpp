// The animation: time follows the wall clock; a crank that cannot turn fully swings between the
// limit positions (the closed form's, for a triple-rocker four-bar); at a change point it stops
// there and says why; paused, nothing is solved or drawn.
#include <gtest/gtest.h>

#include "ui_test.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>

#include "animation/animator.h"
#include "canvas/canvas_scene.h"
#include "document/document.h"
#include "mechanisms.h"
#include "window/features.h"

namespace linkage::ui {
namespace {

TEST(Animation, TimeFollowsTheWallClockAtTheSlowMotionFactor) {
  Document d;
  d.setContents(test::fourBar(60, 20, 70, 50, 0, true, 0, 0, Direction::Ccw, 240).m, "");
  Animator a;
  a.setDocument(&d);
  a.setSlowMotion(0.1);
  EXPECT_DOUBLE_EQ(a.degreesPerSecond(), 240 * 6 * 0.1);
  a.advance(0.25);
  EXPECT_NEAR(d.crankDeg(), 36, 1e-9);
  a.setSlowMotion(1);
  a.advance(0.05);
  EXPECT_NEAR(d.crankDeg(), 36 + 72, 1e-9);
  a.step(-1);
  EXPECT_NEAR(d.crankDeg(), 107, 1e-9);
}

TEST(Animation, PlaysOnItsTimerAndDoesNothingWhilePaused) {
  Document d;
  d.setContents(test::fourBar(60, 20, 70, 50, 0).m, "");
  Animator a;
  a.setDocument(&d);
  QSignalSpy poses(&d, &Document::poseChanged);
  QTest::qWait(60);
  EXPECT_EQ(poses.count(), 0);  // paused: nothing solved
  a.setPlaying(true);
  QElapsedTimer t;  // a loaded machine runs the timer late: wait for frames, up to seconds
  t.start();
  while (poses.count() <= 2 && t.elapsed() < 10000) QTest::qWait(20);
  a.setPlaying(false);
  EXPECT_GT(poses.count(), 2);
  EXPECT_GT(d.crankDeg(), 0);
  const int n = poses.count();
  QTest::qWait(60);
  EXPECT_EQ(poses.count(), n);
}

// Links 60 (ground), 50 (driven), 40, 45: not Grashof, a triple rocker. The driven link stops
// where the other two are in line: |A O4| = 40 + 45, cos(theta) = (50^2 + 60^2 - 85^2) / 6000.
TEST(Animation, TripleRockerSwingsBetweenTheClosedFormLimits) {
  const double start = 30;
  Document d;
  d.setContents(test::fourBar(60, 50, 40, 45, start).m, "");
  ASSERT_TRUE(d.solved()) << d.solveStatus().message;
  const double limit = std::acos((50.0 * 50 + 60 * 60 - 85 * 85) / (2 * 50 * 60)) * 180 / M_PI;
  Animator a;
  a.setDocument(&d);
  a.setSlowMotion(0.05);  // 18 degrees a second at 60 rpm
  int reversals = 0, lastSweep = a.sweep();
  for (int f = 0; f < 2000 && reversals < 3; ++f) {
    a.advance(1.0 / 60);
    ASSERT_TRUE(d.solved());
    EXPECT_LE(d.crankDeg(), limit - start + 1e-6);
    EXPECT_GE(d.crankDeg(), -limit - start - 1e-6);
    if (a.sweep() != lastSweep) {
      ++reversals;
      lastSweep = a.sweep();
    }
  }
  EXPECT_EQ(reversals, 3);
  ASSERT_TRUE(a.upperLimit() && a.lowerLimit());
  EXPECT_NEAR(*a.upperLimit(), limit - start, 1e-5);
  EXPECT_NEAR(*a.lowerLimit(), -limit - start, 1e-5);
}

// A parallelogram (25 on 60, coupler 60) passes a change point with everything in line at
// theta = 180 degrees: the motion stops just before it, says why and names the place.
TEST(Animation, ChangePointStopsThereAndSaysWhy) {
  MainWindow w;
  w.document()->setContents(test::fourBar(60, 25, 60, 25, 30).m, "", "parallelogram");
  Document* d = w.document();
  ASSERT_TRUE(d->solved()) << d->solveStatus().message;
  Animator* a = w.animator();
  QSignalSpy messages(a, &Animator::message);
  a->setSlowMotion(0.1);
  a->setPlaying(true);
  for (int f = 0; f < 1000 && a->playing(); ++f) a->advance(1.0 / 60);
  EXPECT_FALSE(a->playing());
  EXPECT_NEAR(d->crankDeg(), 150, 1e-3);
  ASSERT_FALSE(messages.isEmpty());
  const QString text = messages.last().at(0).toString();
  EXPECT_TRUE(messages.last().at(1).toBool());  // a warning
  EXPECT_NE(text.indexOf("Stopped at crank"), -1) << text.toStdString();
  EXPECT_FALSE(d->poseStatus().ok());
  EXPECT_FALSE(d->poseStatus().joints.empty() && d->poseStatus().bodies.empty());
  // The joints it names are drawn flagged.
  int flagged = 0;
  for (PinItem* p : w.scene()->pinItems()) flagged += p->flagged();
  EXPECT_GT(flagged + int(d->poseStatus().bodies.size()), 0);
}

}  // namespace
}  // namespace linkage::ui
