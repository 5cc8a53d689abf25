// Find Dimensions (issue 29): a stroke target met by the crank's length, found on a thread of
// its own, shown before and after, applied as one undo step that an undo takes back; what is
// not a search is said. The slider-crank of example 22-A (crank 15, rod 50, no offset) has the
// stroke 2 r: a stroke of 34 mm is a crank of 17 mm.
#include <gtest/gtest.h>

#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTest>

#include "design/optimize_dialog.h"
#include "document/document.h"
#include "linkage/io/model_lookup.h"
#include "linkage/limits.h"
#include "linkage/sensitivity.h"
#include "ui_test.h"

namespace linkage::ui {
namespace {

double crank(const Mechanism& m) {
  for (const Dimension& d : dimensions(m))
    if (d.name == "crank.O-A") return d.value;
  return NAN;
}

TEST(OptimizeDialog, AStrokeMetByTheCrankIsOneUndoStep) {
  Document doc;
  ASSERT_TRUE(
      doc.open(QString::fromStdString(*resolveModel("slider-crank-22a-lambda-0.3")), nullptr));
  OptimizeDialog dialog(&doc);
  dialog.show();
  ASSERT_TRUE(dialog.vary("crank.O-A", 10, 20));
  ASSERT_TRUE(dialog.addStrokeTarget("needlebar.B", 34));
  QSignalSpy done(&dialog, &OptimizeDialog::finished);
  dialog.find();
  EXPECT_TRUE(dialog.busy());  // on its own thread: the window answers meanwhile
  ASSERT_TRUE(done.wait(20000));
  ASSERT_TRUE(dialog.result() && dialog.result()->status.ok()) << dialog.summary();
  EXPECT_NEAR(dialog.result()->after.at(0), 17, 1e-6);
  EXPECT_EQ(dialog.result()->before.at(0), 15);
  auto* table = dialog.findChild<QTableWidget*>("optResult");
  ASSERT_GE(table->rowCount(), 3);  // the crank, the stroke, the objective
  EXPECT_EQ(table->item(0, 0)->text(), "crank.O-A");
  shot(&dialog, "optimize_dialog");
  const int steps = doc.undoStack()->count();
  ASSERT_TRUE(dialog.apply());
  EXPECT_EQ(doc.undoStack()->count(), steps + 1);
  ASSERT_TRUE(doc.solved());
  EXPECT_NEAR(crank(doc.design()), 17, 1e-6);
  const PointId B = *doc.design().findPoint("needlebar.B");
  EXPECT_NEAR(findLimits(doc.kinematics(), LimitMeasure::along(B, Vec2(0, 1))).stroke, 34, 1e-6);
  EXPECT_FALSE(dialog.result());  // the design changed: the result was of the one before
  doc.undoStack()->undo();
  EXPECT_EQ(crank(doc.design()), 15);
}

TEST(OptimizeDialog, WhatIsNotASearchIsSaid) {
  Document doc;
  ASSERT_TRUE(
      doc.open(QString::fromStdString(*resolveModel("slider-crank-22a-lambda-0.3")), nullptr));
  OptimizeDialog dialog(&doc);
  dialog.find();
  EXPECT_FALSE(dialog.busy());
  EXPECT_TRUE(dialog.summary().contains("Tick a dimension")) << dialog.summary();
  // Add Target: the first output's stroke as it is (30 mm), ready to be typed over.
  dialog.findChild<QPushButton*>("optAddTarget")->click();
  auto* targets = dialog.findChild<QTableWidget*>("optTargets");
  ASSERT_EQ(targets->rowCount(), 1);
  EXPECT_EQ(targets->item(0, 2)->text(), "30");
  targets->removeRow(0);
  EXPECT_FALSE(dialog.addStrokeTarget("nothing.X", 3));
  ASSERT_TRUE(dialog.vary("crank.O-A", 20, 10));  // low above high
  ASSERT_TRUE(dialog.addStrokeTarget("needlebar.B", 34));
  dialog.find();
  EXPECT_FALSE(dialog.busy());
  EXPECT_TRUE(dialog.summary().contains("low below high")) << dialog.summary();
}

}  // namespace
}  // namespace linkage::ui
