// Dragging with the Select tool, as a hand pushing the mechanism: the crank turns so that the
// dragged point follows the mouse; at the end of its travel it stays there; a fast drag never
// jumps to the other assembly; with Ctrl the design changes instead, as one undo step.
#include <gtest/gtest.h>

#include "ui_test.h"

#include "document/document.h"
#include "drawing.h"
#include "linkage/io/model_file.h"
#include "tools/selection.h"

namespace linkage::ui {
namespace {

// The example four-bar: ground 60, crank 20, coupler 70, rocker 50.
struct FourBarWindow {
  MainWindow w;
  test::Draw d{w};
  Document* doc;
  FourBarWindow() {
    EXPECT_TRUE(test::showExample(w, "four-bar-crank-rocker"));
    w.canvas()->setZoom(5);
    w.canvas()->centerOn(30, 30);
    doc = w.document();
    d.key("S");
  }
  Vec2 at(const char* point) const {
    return doc->kinematics().position(*doc->design().findPoint(point));
  }
};

TEST(Drag, TheCrankTurnsSoThatThePointFollowsTheMouse) {
  FourBarWindow f;
  const std::string file = serializeMechanism(f.doc->design());
  const Vec2 a = f.at("crank.A");
  const Vec2 target = 20 * Vec2(std::cos(150 * M_PI / 180), std::sin(150 * M_PI / 180));
  f.d.drag(a.x(), a.y(), target.x(), target.y());
  // The mouse is where the pixel nearest the target is; A is the point of its circle nearest
  // to that.
  const QPointF m = f.w.canvas()->mapToScene(f.d.at(target.x(), target.y()));
  const Vec2 mouse(m.x(), m.y());
  EXPECT_LT((f.at("crank.A") - 20 * mouse.normalized()).norm(), 1e-6);
  EXPECT_NEAR(f.doc->crankDeg(), std::atan2(mouse.y(), mouse.x()) * 180 / M_PI - 60, 1e-5);
  // The design is what it was, and turning the crank is no edit.
  EXPECT_EQ(serializeMechanism(f.doc->design()), file);
  EXPECT_EQ(f.doc->undoStack()->count(), 0);
}

// The rocker's end of travel: crank and coupler in line (|O2 B| = 20 + 70). Dragging B beyond
// it leaves B there.
TEST(Drag, APointStaysAtItsEndOfTravel) {
  FourBarWindow f;
  const double d = 60, r = 50, s = 20 + 70;
  // B on circle (O2, s) and circle (O4, r), above the ground line.
  const double x = (s * s - r * r + d * d) / (2 * d);
  const Vec2 limit(x, std::sqrt(s * s - x * x));
  const Vec2 b = f.at("rocker.B");
  f.d.drag(b.x(), b.y(), limit.x() + 40, limit.y() - 25, {}, 20);
  EXPECT_LT((f.at("rocker.B") - limit).norm(), 1e-5);
}

// However fast the mouse moves, the coupler stays on its assembly (B on the same side of the
// line from A to the rocker's pivot): every step is tracked along the motion.
TEST(Drag, AFastDragNeverTunnelsToTheOtherAssembly) {
  FourBarWindow f;
  auto side = [&] {
    const Vec2 a = f.at("crank.A"), b = f.at("rocker.B"), o4(60, 0);
    return cross(b - a, o4 - a) > 0;
  };
  const bool before = side();
  const Vec2 p = f.at("coupler.P");
  for (const Vec2& to : {Vec2(-60, -40), Vec2(120, 100), Vec2(-30, 90), Vec2(80, -60)}) {
    f.d.drag(p.x(), p.y(), to.x(), to.y(), {}, 1);  // one move: as fast as a mouse goes
    EXPECT_EQ(side(), before) << to.x() << "," << to.y();
    EXPECT_TRUE(f.doc->solved());
  }
}

TEST(Drag, WithCtrlTheDesignChangesAsOneUndoStep) {
  FourBarWindow f;
  const std::string before = serializeMechanism(f.doc->design());
  f.d.drag(60, 0, 70, 0, Qt::ControlModifier);
  const Mechanism& m = f.doc->design();
  // The ground pivot and the rocker's end pinned to it moved together.
  EXPECT_EQ(m.point(*m.findPoint("ground.O4"))->pos, Vec2(70, 0));
  EXPECT_EQ(m.point(*m.findPoint("rocker.O4"))->pos, Vec2(70, 0));
  EXPECT_TRUE(f.doc->solved());
  EXPECT_EQ(f.doc->undoStack()->count(), 1);
  const std::string after = serializeMechanism(m);
  f.w.edit().undo->trigger();
  EXPECT_EQ(serializeMechanism(f.doc->design()), before);
  f.w.edit().redo->trigger();
  EXPECT_EQ(serializeMechanism(f.doc->design()), after);
}

// A drag that starts turns nothing for a move of a pixel or two: a click stays a click.
TEST(Drag, StartsOnlyAfterAFewPixels) {
  FourBarWindow f;
  const double deg = f.doc->crankDeg();
  const Vec2 a = f.at("crank.A");
  const double px = 1 / f.w.canvas()->zoom();
  f.d.drag(a.x(), a.y(), a.x() + 2 * px, a.y(), {}, 2);
  EXPECT_EQ(f.doc->crankDeg(), deg);
  EXPECT_EQ(f.w.tools().selection()->joints.size(), 1u);  // the pin at A, selected by the click
}

}  // namespace
}  // namespace linkage::ui

namespace linkage::ui {
namespace {

// Flip Assembly (X) on the coupler: the four-bar takes its crossed assembly, the mirror of B
// in the line from A to the rocker's pivot; the file keeps it; undo puts the open one back.
TEST(Drag, FlipPutsTheDyadOnItsOtherAssemblyAndUndoBringsItBack) {
  FourBarWindow f;
  const std::string before = serializeMechanism(f.doc->design());
  const Vec2 a = f.at("crank.A"), b = f.at("rocker.B"), o4(60, 0);
  // B mirrored in the line A-O4: the other intersection of the circles about A and O4.
  const Vec2 u = (o4 - a).normalized();
  const Vec2 mirrored = a + 2 * (b - a).dot(u) * u - (b - a);
  f.d.click(40, 40);  // the coupler plate
  ASSERT_EQ(f.w.tools().selection()->bodies.size(), 1u);
  f.d.key("X");
  EXPECT_LT((f.at("rocker.B") - mirrored).norm(), 1e-9);
  EXPECT_EQ(f.doc->undoStack()->count(), 1);
  // The file holds the flipped drawing: opened afresh, it moves on the new branch.
  Kinematics fresh;
  ASSERT_TRUE(fresh.load(f.doc->design()).ok());
  ASSERT_TRUE(fresh.moveTo(f.doc->crankDeg()).ok());
  EXPECT_LT((fresh.position(*f.doc->design().findPoint("rocker.B")) - mirrored).norm(), 1e-9);
  f.w.edit().undo->trigger();
  EXPECT_EQ(serializeMechanism(f.doc->design()), before);
  EXPECT_LT((f.at("rocker.B") - b).norm(), 1e-12);
}

}  // namespace
}  // namespace linkage::ui
