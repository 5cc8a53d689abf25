// Parameter studies (linkage/study.h): which points a move carries, rows equal to separate
// design checks of the moved mechanisms, a crank that stops where the closed form says, the
// paper's adjustment of the 876 needle mechanism, and the same rows on any number of threads.
#include <gtest/gtest.h>

#include <atomic>

#include <algorithm>
#include <cmath>
#include <string>

#include "examples.h"
#include "linkage/io/model_file.h"
#include "linkage/study.h"
#include "mechanisms.h"
#include "reference/needle876.h"

namespace linkage {
namespace {

using test::example;

std::vector<std::string> labels(const Mechanism& m, const std::vector<PointId>& ps) {
  std::vector<std::string> out;
  for (PointId p : ps) out.push_back(m.pointLabel(p));
  return out;
}

TEST(Study, AMoveCarriesThePointsPinnedWhereItIs) {
  const Mechanism m = example("needle-876-alpha-0");
  EXPECT_EQ(labels(m, movedTogether(m, *m.findPoint("ground.F"))),
            (std::vector<std::string>{"ground.F", "rocker.F"}));
  // E is where three bodies are pinned, two joints deep from the rod's point.
  EXPECT_EQ(labels(m, movedTogether(m, *m.findPoint("rod.E"))),
            (std::vector<std::string>{"link.E", "rocker.E", "rod.E"}));
  // The needle bar's G is pinned to the rod, and runs in a slot: the slot is not carried.
  EXPECT_EQ(labels(m, movedTogether(m, *m.findPoint("needlebar.G"))),
            (std::vector<std::string>{"rod.G", "needlebar.G"}));
  // A point pinned where it is not drawn (a hand-drawn sketch) is not carried.
  test::FourBar f = test::fourBar(60, 20, 70, 50, 60);
  for (Point& p : f.m.points)
    if (p.body == f.rocker && p.name == "O4") p.pos += Vec2(1e-3, 0);
  EXPECT_EQ(movedTogether(f.m, *f.m.findPoint("ground.O4")).size(), 1u);
  // Formula (8) as an arc about E: alpha = 35 is the example file, to rounding.
  Mechanism moved = m;
  PointMove arc;
  arc.point = *m.findPoint("ground.F");
  arc.kind = PointMove::Kind::Arc;
  arc.centre = m.point(*m.findPoint("rocker.E"))->pos;
  arc.angleDeg = -1;
  ASSERT_TRUE(movePoint(moved, arc, 35).ok());
  const Mechanism at35 = example("needle-876-alpha-35");
  for (const char* p : {"ground.F", "rocker.F"})
    EXPECT_LT((moved.point(*moved.findPoint(p))->pos - at35.point(*at35.findPoint(p))->pos).norm(),
              1e-13);
  EXPECT_EQ(moved.point(*moved.findPoint("rocker.E"))->pos, m.point(*m.findPoint("rocker.E"))->pos);
  PointMove stranger;
  stranger.point = *at35.findPoint("ground.F");  // another mechanism's id
  EXPECT_EQ(movePoint(moved, stranger, 1).code, StatusCode::BadModel);
}

TEST(Study, RowsAreTheDesignChecksOfTheMovedMechanisms) {
  // The four-bar's rocker pivot moved along x: each row is findLimits, sweepTransmission and
  // the motion's peaks of the moved mechanism, loaded on its own.
  const test::FourBar f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  StudySpec spec;
  spec.move.point = f.O4;
  spec.move.by = Vec2(1, 0.5);
  spec.from = -3;
  spec.to = 3;
  spec.values = 7;
  spec.point = f.P;
  spec.direction = Vec2(0, 1);
  spec.bodies = {f.rocker, f.coupler};
  spec.keepPaths = true;
  const Study s = runStudy(f.m, spec);
  ASSERT_TRUE(s.status.ok()) << s.status.message;
  ASSERT_EQ(s.rows.size(), 7u);
  ASSERT_EQ(s.joints.size(), 1u);
  for (int i = 0; i < 7; ++i) {
    const StudyRow& r = s.rows[i];
    EXPECT_EQ(r.t, -3 + i);
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    ASSERT_TRUE(r.turns);
    Mechanism moved = f.m;
    for (Point& p : moved.points)
      if (p.name == "O4") p.pos += r.t * Vec2(1, 0.5);
    Kinematics k;
    ASSERT_TRUE(k.load(moved).ok());
    const Limits point = findLimits(k, LimitMeasure::along(f.P, Vec2(0, 1)));
    EXPECT_EQ(r.point.min, point.min);
    EXPECT_EQ(r.point.max, point.max);
    EXPECT_EQ(r.point.stroke, point.stroke);
    ASSERT_EQ(r.point.extremes.size(), point.extremes.size());
    EXPECT_EQ(r.bodies[0].stroke, findLimits(k, LimitMeasure::angleOf(f.rocker)).stroke);
    EXPECT_EQ(r.bodies[1].stroke, findLimits(k, LimitMeasure::angleOf(f.coupler)).stroke);
    const TransmissionSweep tr = sweepTransmission(k);
    EXPECT_EQ(r.transmission[0].min, tr.summaries[0].min);
    EXPECT_EQ(r.transmission[0].max, tr.summaries[0].max);
    double speed = 0, accel = 0;
    ASSERT_EQ(r.path.size(), 361u);
    for (int deg = 0; deg <= 360; ++deg) {
      ASSERT_TRUE(k.moveTo(deg).ok());
      EXPECT_EQ(r.path[deg], k.position(f.P));
      speed = std::max(speed, std::hypot(k.velocity(f.P).x(), k.velocity(f.P).y()));
      accel = std::max(accel, std::hypot(k.acceleration(f.P).x(), k.acceleration(f.P).y()));
    }
    EXPECT_EQ(r.peakSpeed, speed);
    EXPECT_EQ(r.peakAccel, accel);
  }
  // Moving O4 changes the rocker's length and so its swing.
  EXPECT_NE(s.rows[0].bodies[0].stroke, s.rows[6].bodies[0].stroke);
}

TEST(Study, AStudyThatPassesTheGrashofLimitReportsWhereTheCrankStops) {
  // Crank 20, coupler 70, ground 60, the rocker pivot O4 moved up towards B by t: the rocker
  // r4(t) = |B - O4(t)| shortens until it is the shortest link and the crank rocks.
  const double r2 = 20, r3 = 70, drawn = 60;
  const test::FourBar f = test::fourBar(60, r2, r3, 50, drawn);
  const Vec2 B = f.m.point(f.B)->pos;
  StudySpec spec;
  spec.move.point = f.O4;
  spec.move.by = Vec2(0, 1);
  spec.from = 0;
  spec.to = 40;
  spec.values = 9;
  spec.point = f.B;
  const Study s = runStudy(f.m, spec);
  ASSERT_TRUE(s.status.ok());
  int locked = 0;
  for (const StudyRow& r : s.rows) {
    const Vec2 O4(60, r.t);
    const double r4 = (B - O4).norm(), g = O4.norm();
    // The crank turns fully when the loop is Grashof with the crank or the ground shortest.
    double len[4] = {r2, r3, r4, g};
    std::sort(len, len + 4);
    const bool full = len[0] + len[3] < len[1] + len[2] && (len[0] == r2 || len[0] == g);
    EXPECT_EQ(r.turns, full) << r.t;
    if (r.turns) {
      EXPECT_TRUE(r.status.ok());
      EXPECT_FALSE(r.lockDeg.has_value());
      continue;
    }
    ++locked;
    EXPECT_EQ(r.status.code, StatusCode::Unreachable) << r.status.message;
    ASSERT_TRUE(r.lockDeg.has_value());
    EXPECT_TRUE(r.point.extremes.empty());
    EXPECT_TRUE(r.path.empty());  // not asked for
    // Turning on from the drawing, the first crank angle where coupler and rocker no longer
    // reach: |A O4| leaves [|r3 - r4|, r3 + r4] (marched by 0.01 degree, then bisected).
    auto reach = [&](double deg) {
      const double th = (drawn + deg) * M_PI / 180;
      const double a = (Vec2(r2 * std::cos(th), r2 * std::sin(th)) - O4).norm();
      return std::min(r3 + r4 - a, a - std::abs(r3 - r4));
    };
    double lo = 0, hi = 0;
    while (reach(hi) > 0 && hi < 360) lo = hi, hi += 0.01;
    ASSERT_LT(hi, 360);
    for (int i = 0; i < 100; ++i) (reach(0.5 * (lo + hi)) > 0 ? lo : hi) = 0.5 * (lo + hi);
    EXPECT_NEAR(*r.lockDeg, lo, 1e-6) << r.t;
  }
  EXPECT_GT(locked, 0);
  EXPECT_LT(locked, 9);
}

TEST(Study, ThePapersAdjustmentOfTheNeedleStroke) {
  // Seed 001: F on its arc about E, alpha 0 to 35: the needle's lowest position stays, its
  // stroke grows (the paper: 18 to 23 mm) and mu_2's minimum falls by alpha.
  const Mechanism m = example("needle-876-alpha-0");
  StudySpec spec;
  spec.move.point = *m.findPoint("ground.F");
  spec.move.kind = PointMove::Kind::Arc;
  spec.move.centre = m.point(*m.findPoint("rocker.E"))->pos;
  spec.move.angleDeg = -1;
  spec.from = 0;
  spec.to = 35;
  spec.values = 36;
  spec.point = *m.findPoint("needlebar.G");
  const Study s = runStudy(m, spec);
  ASSERT_TRUE(s.status.ok());
  double last = 0;
  for (const StudyRow& r : s.rows) {
    ASSERT_TRUE(r.turns) << r.t;
    EXPECT_NEAR(r.point.min, 107.4750004009442, 1e-12) << r.t;
    EXPECT_NEAR(r.point.minDeg, 0, 1e-9);
    EXPECT_GT(r.point.stroke, last);
    last = r.point.stroke;
    EXPECT_NEAR(r.transmission[1].min, 67.677483779484959 - r.t, 1e-9) << r.t;
    // The top against the paper's formulas, at the other stretched position of crank and
    // coupler (where D stands still again).
    const linkref::Needle876<__float128> ref(r.t);
    EXPECT_NEAR(r.point.max, static_cast<double>(ref.at(r.point.maxDeg).G.y), 1e-9);
  }
  EXPECT_NEAR(s.rows.front().point.stroke, 18, 0.5);
  EXPECT_NEAR(s.rows.back().point.stroke, 23, 0.5);
}

TEST(Study, SameRowsOnAnyNumberOfThreadsAndBadSpecs) {
  const Mechanism m = example("needle-876-alpha-0");
  StudySpec spec;
  spec.move.point = *m.findPoint("ground.C");
  spec.move.by = Vec2(0.5, -0.25);
  spec.from = -4;
  spec.to = 4;
  spec.values = 17;
  spec.point = *m.findPoint("needlebar.G");
  spec.bodies = {m.bodyNamed("lever")->id};
  spec.threads = 1;
  const Study one = runStudy(m, spec);
  spec.threads = 5;
  const Study five = runStudy(m, spec);
  ASSERT_EQ(five.threads, 5);
  ASSERT_EQ(one.rows.size(), five.rows.size());
  for (size_t i = 0; i < one.rows.size(); ++i) {
    EXPECT_EQ(one.rows[i].t, five.rows[i].t);
    EXPECT_EQ(one.rows[i].turns, five.rows[i].turns);
    EXPECT_EQ(one.rows[i].point.stroke, five.rows[i].point.stroke);
    EXPECT_EQ(one.rows[i].bodies[0].stroke, five.rows[i].bodies[0].stroke);
    EXPECT_EQ(one.rows[i].transmission[2].max, five.rows[i].transmission[2].max);
  }
  StudySpec bad = spec;
  bad.values = 0;
  EXPECT_EQ(runStudy(m, bad).status.code, StatusCode::BadModel);
  bad = spec;
  bad.steps = 3;
  EXPECT_EQ(runStudy(m, bad).status.code, StatusCode::BadModel);
  bad = spec;
  bad.move.by = Vec2(NAN, 0);
  EXPECT_EQ(runStudy(m, bad).status.code, StatusCode::BadModel);
  bad = spec;
  bad.direction = Vec2(0, 0);
  EXPECT_EQ(runStudy(m, bad).status.code, StatusCode::BadModel);
  bad = spec;
  bad.point = PointId{};
  EXPECT_EQ(runStudy(m, bad).status.code, StatusCode::BadModel);
  EXPECT_TRUE(runStudy(m, bad).rows.empty());
}

// The one pool of threads for studies, watched and stopped from outside (what the editor's
// study runner does from its thread): progress after every variant, and a cancel keeps the
// rows computed, the first values of t, each the same as a whole run's.
TEST(Study, ProgressAfterEveryVariantAndACancelKeepsTheFirstRows) {
  const Mechanism m = example("needle-876-alpha-0");
  StudySpec spec;
  spec.move.point = *m.findPoint("ground.C");
  spec.move.by = Vec2(0.5, -0.25);
  spec.from = -4;
  spec.to = 4;
  spec.values = 17;
  spec.point = *m.findPoint("needlebar.G");
  spec.threads = 2;
  std::atomic<int> calls{0}, last{0};
  StudyControl watch;
  watch.progress = [&](int done, int total) {
    ++calls;
    EXPECT_EQ(total, 17);
    last = std::max(last.load(), done);
  };
  const Study whole = runStudy(m, spec, watch);
  EXPECT_EQ(calls, 17);
  EXPECT_EQ(last, 17);
  EXPECT_FALSE(whole.cancelled);
  std::atomic<bool> cancel{false};
  StudyControl stop;
  stop.cancel = &cancel;
  stop.progress = [&](int done, int) {
    if (done >= 5) cancel = true;
  };
  const Study part = runStudy(m, spec, stop);
  EXPECT_TRUE(part.cancelled);
  ASSERT_GE(part.rows.size(), 5u);
  ASSERT_LT(part.rows.size(), 17u);
  for (size_t i = 0; i < part.rows.size(); ++i) {
    EXPECT_EQ(part.rows[i].t, whole.rows[i].t);
    EXPECT_EQ(part.rows[i].point.stroke, whole.rows[i].point.stroke);
  }
}

}  // namespace
}  // namespace linkage
