// The document: files in and out, edits kept when the solver refuses them, exact undo.
#include <gtest/gtest.h>

#include "ui_test.h"

#include <QTemporaryDir>

#include "document/document.h"
#include "linkage/io/model_file.h"
#include "linkage/io/model_lookup.h"

namespace linkage::ui {
namespace {

QString example(const char* name) {
  return QString::fromStdString(*resolveModel(name));
}

TEST(Document, BadFileLeavesTheOpenDocumentAsItWas) {
  Document d;
  QString err;
  ASSERT_TRUE(d.open(example("wanzer-inversion-2"), &err)) << err.toStdString();
  ASSERT_TRUE(d.solved());
  d.setCrankDeg(40);
  const std::string before = serializeMechanism(d.design());
  QTemporaryDir dir;
  const QString bad = dir.filePath("bad.linkage.json");
  {
    QFile f(bad);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(R"({"format": "linkage", "version": 1, "bodies": [{"name": "g", "ground": true,)"
            R"( "points": {"A": [0, "x"]}}], "joints": []})");
  }
  EXPECT_FALSE(d.open(bad, &err));
  EXPECT_NE(err.indexOf("bodies[0].points"), -1) << err.toStdString();
  EXPECT_EQ(serializeMechanism(d.design()), before);
  EXPECT_EQ(d.filePath(), example("wanzer-inversion-2"));
  EXPECT_NEAR(d.crankDeg(), 40, 1e-12);
}

TEST(Document, RefusedEditIsKeptAndTheLastGoodPoseStays) {
  Document d;
  ASSERT_TRUE(d.open(example("four-bar-crank-rocker"), nullptr));
  ASSERT_TRUE(d.setCrankDeg(30).ok());
  const DocumentState good = d.state();
  const PointId p = d.design().outputs.at(0);
  const Vec2 at = d.kinematics().position(p);
  // The rocker's ground pivot moved far away: the rocker cannot reach it.
  Mechanism broken = d.design();
  broken.point(*broken.findPoint("ground.O4"))->pos.x() += 500;
  d.setDesign(broken);
  EXPECT_FALSE(d.solved());
  EXPECT_FALSE(d.solveStatus().ok());
  EXPECT_EQ(serializeMechanism(d.design()), serializeMechanism(broken));
  EXPECT_TRUE(d.kinematics().valid());
  EXPECT_EQ(d.kinematics().position(p), at);
  d.restore(good);
  EXPECT_TRUE(d.solved());
  EXPECT_EQ(serializeMechanism(d.design()), serializeMechanism(good.design));
}

TEST(Document, SaveIsAtomicAndClearsTheModifiedMark) {
  Document d;
  ASSERT_TRUE(d.open(example("slider-crank-22a-lambda-0.3"), nullptr));
  EXPECT_FALSE(d.isModified());
  QTemporaryDir dir;
  const QString out = dir.filePath("copy.linkage.json");
  QString err;
  ASSERT_TRUE(d.save(out, &err)) << err.toStdString();
  EXPECT_EQ(d.filePath(), out);
  EXPECT_EQ(d.displayName(), "copy.linkage.json");
  LoadResult r = loadMechanismFile(out.toStdString());
  ASSERT_TRUE(r.mechanism) << r.error;
  EXPECT_EQ(mechanismDifference(*r.mechanism, d.design()), "");
  // A directory that does not exist: the reason, and nothing changed.
  EXPECT_FALSE(d.save(dir.filePath("no/such/dir/x.linkage.json"), &err));
  EXPECT_FALSE(err.isEmpty());
  EXPECT_EQ(d.filePath(), out);
}

}  // namespace
}  // namespace linkage::ui
