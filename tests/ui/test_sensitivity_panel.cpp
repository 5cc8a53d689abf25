// The Sensitivity dock (issue 29): the dimensions ranked by how much they move the chosen
// output, against what must hold whatever the mechanism (moving the whole ground moves every
// point by as much: the ground points' x and y derivatives of a point's y add up to 0 and 1, the
// ground's slots moved with them where they move),
// the ranking by the turn's largest, and what cannot be differentiated yet said.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QTest>

#include "design/sensitivity_panel.h"
#include "document/document.h"
#include "linkage/io/model_lookup.h"
#include "ui_test.h"

namespace linkage::ui {
namespace {

void settle(SensitivityPanel& panel) {
  QTest::qWait(40);
  QElapsedTimer t;
  t.start();
  while (panel.redrawPending() && t.elapsed() < 10000) QTest::qWait(5);
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

TEST(SensitivityPanel, AFourBarsPointMovesWithItsGround) {
  Document doc;
  ASSERT_TRUE(doc.open(QString::fromStdString(*resolveModel("four-bar-crank-rocker")), nullptr));
  doc.setCrankDeg(100);
  SensitivityPanel panel(&doc);
  panel.resize(900, 400);
  panel.show();
  settle(panel);
  for (int component : {0, 1}) {
    panel.componentBox()->setCurrentIndex(component);
    Q_EMIT panel.componentBox()->activated(component);
    settle(panel);
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

TEST(SensitivityPanel, WhatCannotBeDifferentiatedYetIsSaid) {
  Document doc;
  ASSERT_TRUE(doc.open(QString::fromStdString(*resolveModel("cam-translating-roller")), nullptr));
  SensitivityPanel panel(&doc);
  panel.resize(900, 400);
  panel.show();
  settle(panel);
  EXPECT_TRUE(panel.bars().empty());
  EXPECT_TRUE(panel.summary().startsWith("Not yet")) << panel.summary();
}

}  // namespace
}  // namespace linkage::ui
