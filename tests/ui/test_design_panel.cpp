// The design-checks dock (issue 13): its numbers are the solver API's (fourBarLoops,
// sweepTransmission with the band set in it, findLimits along the direction set in it), they
// follow edits only while the dock is shown, a crank that stops is reported, and a double-click
// on an extreme turns the crank there.
#include <gtest/gtest.h>

#include "ui_test.h"

#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QTableWidget>
#include <QTest>

#include "canvas/canvas_view.h"
#include "centres/centres_panel.h"
#include "design/checks_panel.h"
#include "design/design_choices.h"
#include "document/commands.h"
#include "document/document.h"
#include "linkage/grashof.h"
#include "window/features.h"

namespace linkage::ui {
namespace {

// Lets the window lay its docks out and report their visibility (queued signals).
void settle() {
  for (int i = 0; i < 4; ++i) QApplication::processEvents();
}

double exact(const QTableWidget* t, int row, int column, int role = Qt::UserRole) {
  const QTableWidgetItem* i = t->item(row, column);
  return i ? i->data(role).toDouble() : NAN;
}

struct PanelWindow {
  MainWindow w;
  ChecksPanel* panel;
  explicit PanelWindow(const char* example) {
    EXPECT_TRUE(w.openExample(example));
    panel = w.designChecks().panel();
    w.resize(1200, 800);
    w.show();
    w.designChecks().show->trigger();
    settle();
  }
  Document* doc() { return w.document(); }
};

void expectGrashof(const ChecksPanel& p, const Mechanism& m) {
  const std::vector<FourBarLoop> loops = fourBarLoops(m);
  const QTableWidget* t = p.grashofTable();
  ASSERT_EQ(t->rowCount(), static_cast<int>(loops.size()));
  for (int r = 0; r < t->rowCount(); ++r) {
    const QVariantList lengths = t->item(r, 2)->data(Qt::UserRole).toList();
    ASSERT_EQ(lengths.size(), 4);
    for (int i = 0; i < 4; ++i) EXPECT_EQ(lengths[i].toDouble(), loops[r].lengths[i]);
    EXPECT_EQ(t->item(r, 1)->text(), QString::fromUtf8(toString(loops[r].kind)));
    EXPECT_EQ(exact(t, r, 3), loops[r].margin);
    EXPECT_TRUE(
        t->item(r, 0)->text().startsWith(QString::fromStdString(m.body(loops[r].bodies[0])->name)));
  }
}

void expectTransmission(const ChecksPanel& p, const Kinematics& k, TransmissionBand band) {
  TransmissionOptions opt;
  opt.band = band;
  const TransmissionSweep s = sweepTransmission(k, opt);
  ASSERT_TRUE(s.status.ok());
  const QTableWidget* t = p.transmissionTable();
  ASSERT_EQ(t->rowCount(), static_cast<int>(s.joints.size()));
  for (int r = 0; r < t->rowCount(); ++r) {
    const TransmissionSummary& x = s.summaries[r];
    EXPECT_EQ(t->item(r, 0)->data(Qt::UserRole).toString().toStdString(), s.joints[r].label);
    EXPECT_EQ(exact(t, r, 1), x.min);
    EXPECT_EQ(exact(t, r, 1, ChecksPanel::CrankRole), x.minDeg);
    EXPECT_EQ(exact(t, r, 2), x.max);
    EXPECT_EQ(exact(t, r, 2, ChecksPanel::CrankRole), x.maxDeg);
    const QVariantList out = t->item(r, 3)->data(Qt::UserRole).toList();
    ASSERT_EQ(out.size(), static_cast<int>(x.outside.size())) << s.joints[r].label;
    for (size_t i = 0; i < x.outside.size(); ++i) {
      const QVariantList o = out[i].toList();
      EXPECT_EQ(o[0].toDouble(), x.outside[i].fromDeg);
      EXPECT_EQ(o[1].toDouble(), x.outside[i].toDeg);
      EXPECT_EQ(o[2].toBool(), x.outside[i].below);
    }
    EXPECT_EQ(t->item(r, 3)->text() == QStringLiteral("none"), x.inBand());
  }
}

void expectLimits(const ChecksPanel& p, const Kinematics& k, const LimitMeasure& what) {
  const Limits l = findLimits(k, what);
  ASSERT_TRUE(l.status.ok());
  const QTableWidget* t = p.limitsTable();
  ASSERT_EQ(t->rowCount(), static_cast<int>(l.extremes.size()) + 1);
  for (size_t i = 0; i < l.extremes.size(); ++i) {
    const int r = static_cast<int>(i);
    EXPECT_EQ(t->item(r, 0)->text(), l.extremes[i].max ? QStringLiteral("max") : "min");
    EXPECT_EQ(exact(t, r, 1), l.extremes[i].crankDeg);
    EXPECT_EQ(exact(t, r, 2), l.extremes[i].value);
  }
  EXPECT_EQ(t->item(t->rowCount() - 1, 0)->text(), QStringLiteral("stroke"));
  EXPECT_EQ(exact(t, t->rowCount() - 1, 2), l.stroke);
}

TEST(DesignPanel, TheNumbersAreTheSolverAPIs) {
  PanelWindow pw("needle-876-alpha-35");
  ChecksPanel* p = pw.panel;
  const Mechanism& m = pw.doc()->design();
  const Kinematics& k = pw.doc()->kinematics();
  ASSERT_TRUE(p->isVisible());
  expectGrashof(*p, m);
  EXPECT_EQ(p->grashofTable()->rowCount(), 2);
  expectTransmission(*p, k, {30, 150});
  EXPECT_EQ(p->transmissionTable()->rowCount(), 3);
  const PointId g = m.outputs.front();
  expectLimits(*p, k, LimitMeasure::along(g, defaultDirection(m, g)));
  EXPECT_EQ(p->subjectBox()->currentText(), QStringLiteral("needlebar.G"));
  shot(&pw.w, "design-panel");

  // A band that mu_2 leaves (its minimum is about 32.7 degrees at alpha = 35): set in the panel.
  p->bandLo()->setValue(40);
  EXPECT_EQ(pw.w.designChecks().choices()->band().lo, 40);
  expectTransmission(*p, k, {40, 150});
  EXPECT_NE(p->transmissionTable()->item(1, 3)->text(), QStringLiteral("none"));
  p->bandLo()->setValue(30);

  // A direction of the user's, then a body's angle.
  p->directionEdit()->setText(QStringLiteral("1, 2"));
  emit p->directionEdit()->editingFinished();
  expectLimits(*p, k, LimitMeasure::along(g, Vec2(1, 2)));
  p->subjectBox()->setCurrentIndex(p->subjectBox()->findText(QStringLiteral("lever (angle)")));
  emit p->subjectBox()->activated(p->subjectBox()->currentIndex());
  expectLimits(*p, k, LimitMeasure::angleOf(m.bodyNamed("lever")->id));
  EXPECT_FALSE(p->directionEdit()->isEnabled());
  // A direction that is no direction is refused with a reason.
  p->subjectBox()->setCurrentIndex(p->subjectBox()->findText(QStringLiteral("rod.E")));
  p->directionEdit()->setText(QStringLiteral("0, 0"));
  emit p->directionEdit()->editingFinished();
  EXPECT_TRUE(p->limitsStatus().contains(QStringLiteral("not both 0")));
}

TEST(DesignPanel, ShiftDShowsTheDockAndATabBehindAnotherComputesNothing) {
  MainWindow w;
  ASSERT_TRUE(w.openExample("needle-876-alpha-35"));
  w.resize(1200, 800);
  w.show();
  QApplication::processEvents();
  ChecksPanel* p = w.designChecks().panel();
  ASSERT_FALSE(w.designChecks().dock->isVisible());
  EXPECT_EQ(p->computations(), 0);
  QTest::keyClick(w.canvas(), Qt::Key_D, Qt::ShiftModifier);
  settle();
  EXPECT_TRUE(w.designChecks().dock->isVisible());
  EXPECT_TRUE(p->shown());
  EXPECT_EQ(p->computations(), 1);
  EXPECT_EQ(p->transmissionTable()->rowCount(), 3);
  // A tab beside the instant centres, in front: the centres behind it compute nothing (their
  // dock is moved off the window but stays "visible").
  EXPECT_TRUE(w.tabifiedDockWidgets(w.centres().dock).contains(w.designChecks().dock));
  ASSERT_TRUE(w.document()->setCrankDeg(10).ok());
  QApplication::processEvents();
  EXPECT_FALSE(w.centres().panel()->chain().has_value());
  // Behind the instant centres: the dock's visibility says it is not seen.
  w.centres().dock->raise();
  settle();
  ASSERT_FALSE(p->shown());
  ASSERT_TRUE(w.document()->setCrankDeg(20).ok());
  EXPECT_TRUE(w.centres().panel()->chain().has_value());  // the centres are seen again
  Mechanism m = w.document()->design();
  m.point(*m.findPoint("ground.C"))->pos.y() += 0.5;
  m.point(*m.findPoint("lever.C"))->pos.y() += 0.5;
  editDesign(w.document(), "Move C", m);
  EXPECT_EQ(p->computations(), 1);
  w.designChecks().dock->raise();
  settle();
  EXPECT_TRUE(p->shown());
  EXPECT_EQ(p->computations(), 2);
  expectGrashof(*p, w.document()->design());
}

TEST(DesignPanel, EditsAreFollowedOnlyWhileShown) {
  PanelWindow pw("needle-876-alpha-0");
  ChecksPanel* p = pw.panel;
  Document* d = pw.doc();
  const int shown = p->computations();
  EXPECT_GE(shown, 1);
  Mechanism m = d->design();
  m.point(*m.findPoint("ground.C"))->pos.y() += 0.5;
  m.point(*m.findPoint("lever.C"))->pos.y() += 0.5;
  editDesign(d, "Move C", m);
  ASSERT_TRUE(d->solved());
  EXPECT_EQ(p->computations(), shown + 1);
  expectGrashof(*p, d->design());
  expectTransmission(*p, d->kinematics(), pw.w.designChecks().choices()->band());
  const PointId g = d->design().outputs.front();
  expectLimits(*p, d->kinematics(), LimitMeasure::along(g, defaultDirection(d->design(), g)));
  // Hidden: edits and poses compute nothing; shown again, the numbers are the design's now.
  pw.w.designChecks().show->trigger();
  settle();
  const int hidden = p->computations();
  m.point(*m.findPoint("ground.C"))->pos.y() += 0.5;
  m.point(*m.findPoint("lever.C"))->pos.y() += 0.5;
  editDesign(d, "Move C", m);
  pw.w.designChecks().choices()->setBand({35, 145});
  ASSERT_TRUE(d->setCrankDeg(80).ok());
  EXPECT_EQ(p->computations(), hidden);
  pw.w.designChecks().show->trigger();
  settle();
  EXPECT_EQ(p->computations(), hidden + 1);
  expectGrashof(*p, d->design());
  expectTransmission(*p, d->kinematics(), {35, 145});
  pw.w.designChecks().choices()->setBand({30, 150});
}

TEST(DesignPanel, ACrankThatStopsIsReported) {
  PanelWindow pw("four-bar-crank-rocker");
  ChecksPanel* p = pw.panel;
  Document* d = pw.doc();
  // The rocker's pivot moved up towards B: the rocker becomes the shortest link and the
  // crank can no longer turn fully (tests/test_study.cpp finds the same).
  Mechanism m = d->design();
  m.point(*m.findPoint("ground.O4"))->pos.y() += 40;
  m.point(*m.findPoint("rocker.O4"))->pos.y() += 40;
  editDesign(d, "Move O4", m);
  ASSERT_TRUE(d->solved()) << d->solveStatus().message;
  const TransmissionSweep s = sweepTransmission(d->kinematics());
  ASSERT_FALSE(s.status.ok());
  EXPECT_EQ(p->transmissionStatus().toStdString(), s.status.message);
  EXPECT_EQ(p->transmissionTable()->rowCount(), 0);
  const PointId pt = d->design().outputs.front();
  const Limits l =
      findLimits(d->kinematics(), LimitMeasure::along(pt, defaultDirection(d->design(), pt)));
  ASSERT_FALSE(l.status.ok());
  EXPECT_EQ(p->limitsStatus().toStdString(), l.status.message);
  EXPECT_EQ(p->limitsTable()->rowCount(), 0);
  // Grashof says why: the loop is no longer a crank-rocker.
  ASSERT_EQ(p->grashofTable()->rowCount(), 1);
  EXPECT_NE(p->grashofTable()->item(0, 1)->text(), QStringLiteral("crank-rocker"));
}

TEST(DesignPanel, DoubleClickingAnExtremeTurnsTheCrankThere) {
  PanelWindow pw("wanzer-inversion-2");
  ChecksPanel* p = pw.panel;
  Document* d = pw.doc();
  ASSERT_TRUE(d->setCrankDeg(400).ok());  // in the second turn
  QTableWidget* t = p->limitsTable();
  ASSERT_EQ(t->rowCount(), 5);  // the needle's dwell: four extremes, then the stroke
  for (int r = 0; r < 4; ++r) {
    const double at = exact(t, r, 1), was = d->crankDeg();
    const QRect cell = t->visualItemRect(t->item(r, 2));
    QTest::mouseClick(t->viewport(), Qt::LeftButton, {}, cell.center());
    QTest::mouseDClick(t->viewport(), Qt::LeftButton, {}, cell.center());
    // The nearest crank angle where it happens: the mechanism moves the short way.
    const double turns = (d->crankDeg() - at) / 360;
    EXPECT_NEAR(turns, std::round(turns), 1e-12) << r;
    EXPECT_LE(std::abs(d->crankDeg() - was), 180 + 1e-9) << r;
    EXPECT_GE(d->crankDeg(), 180) << r;
  }
}

}  // namespace
}  // namespace linkage::ui
