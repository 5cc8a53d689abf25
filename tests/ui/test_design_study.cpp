// The parameter-study dialog (issue 13): its table is runStudy's on the same spec, value for
// value, and its CSV is linkage-cli study's text; a study where the crank stops says so in the
// table; the run is off the GUI thread, reports progress and can be cancelled; a form that
// cannot run says which field is wrong.
#include <gtest/gtest.h>

#include "ui_test.h"

#include <QApplication>
#include <QComboBox>
#include <QFile>
#include <QLineEdit>
#include <QListWidget>
#include <QProcess>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTemporaryDir>

#include "design/study_dialog.h"
#include "design/study_plots.h"
#include "design/study_runner.h"
#include "design/study_table_model.h"
#include "document/document.h"
#include "figures/qcp.h"
#include "linkage/tables/study_table.h"
#include "window/features.h"

namespace linkage::ui {
namespace {

struct Form {
  const char* move;
  const char* by = nullptr;  // a line, or:
  const char* about = nullptr;
  const char* angle = nullptr;
  const char* from;
  const char* to;
  int values;
  const char* point;
  std::vector<const char*> bodies = {};
};

void fill(StudyDialog* d, const Form& f) {
  d->moveBox()->setCurrentIndex(d->moveBox()->findText(f.move));
  d->kindBox()->setCurrentIndex(f.by ? 0 : 1);
  if (f.by) d->byEdit()->setText(f.by);
  if (f.about) d->aboutEdit()->setText(f.about);
  if (f.angle) d->angleEdit()->setText(f.angle);
  d->fromEdit()->setText(f.from);
  d->toEdit()->setText(f.to);
  d->valuesBox()->setValue(f.values);
  d->pointBox()->setCurrentIndex(d->pointBox()->findText(f.point));
  for (const char* b : f.bodies)
    d->bodiesList()->findItems(b, Qt::MatchExactly).front()->setCheckState(Qt::Checked);
}

bool runAndWait(StudyDialog* d) {
  QSignalSpy ended(d, &StudyDialog::runEnded);
  if (!d->run()) return false;
  return ended.wait(60000);
}

// A study of 20,000 variants of the 876 (seconds of work) started in the window's dialog.
StudyDialog* startLongRun(MainWindow& w, const char* move, const char* point) {
  EXPECT_TRUE(w.openExample("needle-876-alpha-0"));
  StudyDialog* d = w.designChecks().studyDialog();
  d->show();
  fill(d, {move, "0.001, 0", nullptr, nullptr, "0", "1", 20000, point});
  EXPECT_TRUE(d->run());
  return d;
}

// The dialog's table, its rows and paths, are runStudy's on the same spec.
void expectTableIsRunStudy(StudyDialog* d, const Mechanism& m, const StudySpec& spec) {
  const Study s = runStudy(m, spec);
  ASSERT_TRUE(s.status.ok()) << s.status.message;
  const StudyTableModel* model = d->model();
  const std::vector<std::string> columns = studyColumns(m, spec, s);
  ASSERT_EQ(model->columnCount(), static_cast<int>(columns.size()));
  for (int c = 0; c < model->columnCount(); ++c)
    EXPECT_EQ(model->columns()[c].toStdString(), columns[c]);
  ASSERT_EQ(model->rowCount(), static_cast<int>(s.rows.size()));
  for (int r = 0; r < model->rowCount(); ++r) {
    const std::vector<std::optional<double>> v = studyValues(spec, s, s.rows[r]);
    for (int c = 0; c < model->columnCount(); ++c) {
      EXPECT_EQ(model->value(r, c), v[c]) << "row " << r << " " << columns[c];
      const QVariant shown = model->data(model->index(r, c), Qt::UserRole);
      EXPECT_EQ(shown.isValid(), v[c].has_value());
      if (v[c]) EXPECT_EQ(shown.toDouble(), *v[c]);
    }
    EXPECT_EQ(d->runner()->study().rows[r].path, s.rows[r].path) << r;
  }
  int paths = 0;
  for (const StudyRow& r : s.rows) paths += !r.path.empty();
  EXPECT_EQ(d->plots()->familyCurves(), paths);
}

TEST(DesignStudy, TheTableIsRunStudysAndTheCsvIsTheCommandLines) {
  MainWindow w;
  ASSERT_TRUE(w.openExample("needle-876-alpha-0"));
  w.designChecks().parameterStudy->trigger();
  StudyDialog* d = w.designChecks().studyDialog();
  ASSERT_TRUE(d->isVisible());
  // The paper's adjustment: F turned about E, alpha from 0 to 35 degrees.
  fill(d, {"ground.F",
           nullptr,
           "43, 137.05539931644228",
           "-1",
           "0",
           "35",
           8,
           "needlebar.G",
           {"lever"}});
  d->resize(1180, 760);
  ASSERT_TRUE(runAndWait(d)) << d->statusText().toStdString();
  const Mechanism& m = w.document()->design();
  StudySpec spec;
  spec.move.point = *m.findPoint("ground.F");
  spec.move.kind = PointMove::Kind::Arc;
  spec.move.centre = Vec2(43, 137.05539931644228);
  spec.move.angleDeg = -1;
  spec.from = 0;
  spec.to = 35;
  spec.values = 8;
  spec.point = *m.findPoint("needlebar.G");
  spec.bodies = {m.bodyNamed("lever")->id};
  spec.keepPaths = true;
  expectTableIsRunStudy(d, m, spec);
  EXPECT_FALSE(d->runner()->cancelled());
  EXPECT_EQ(d->progressBar()->value(), 8);
  EXPECT_EQ(d->plots()->measureBox()->currentText(), QStringLiteral("needlebar.G.stroke_mm"));
  // The needle bar runs in its guide: its family is drawn against the crank angle.
  EXPECT_EQ(d->plots()->familyBox()->currentData().toInt(),
            static_cast<int>(StudyPlots::Family::AgainstCrank));
  // Its axis says which way the crank turns, as every crank-angle axis does.
  EXPECT_TRUE(d->plots()->familyPlot()->xAxis->label().endsWith("angle [deg], counter-clockwise"))
      << d->plots()->familyPlot()->xAxis->label();
  QApplication::processEvents();
  shot(d, "design-study");

  // The CSV is what linkage-cli study writes for the same study.
  QTemporaryDir dir;
  const QString path = dir.filePath("study.csv");
  QString why;
  ASSERT_TRUE(d->exportCsv(path, &why)) << why.toStdString();
  QFile f(path);
  ASSERT_TRUE(f.open(QIODevice::ReadOnly));
  QProcess cli;
  cli.start(QStringLiteral(LINKAGE_CLI),
            {"study", "needle-876-alpha-0", "--move", "ground.F", "--about",
             "43,137.05539931644228", "--angle", "-1", "--from", "0", "--to", "35", "--steps", "8",
             "--point", "needlebar.G", "--body", "lever"});
  ASSERT_TRUE(cli.waitForFinished(60000));
  ASSERT_EQ(cli.exitCode(), 0) << cli.readAllStandardError().toStdString();
  EXPECT_EQ(f.readAll().toStdString(), cli.readAllStandardOutput().toStdString());
}

TEST(DesignStudy, AStudyWhereTheCrankStopsReportsItInTheTable) {
  MainWindow w;
  ASSERT_TRUE(w.openExample("four-bar-crank-rocker"));
  StudyDialog* d = w.designChecks().studyDialog();
  d->show();
  // The rocker's pivot moved up towards B: the rocker shortens until the crank rocks.
  fill(d, {"ground.O4", "0, 1", nullptr, nullptr, "0", "40", 9, "coupler.P"});
  ASSERT_TRUE(runAndWait(d)) << d->statusText().toStdString();
  const Mechanism& m = w.document()->design();
  StudySpec spec;
  spec.move.point = *m.findPoint("ground.O4");
  spec.move.by = Vec2(0, 1);
  spec.from = 0;
  spec.to = 40;
  spec.values = 9;
  spec.point = *m.findPoint("coupler.P");
  spec.keepPaths = true;
  expectTableIsRunStudy(d, m, spec);
  const StudyTableModel* model = d->model();
  int locked = 0;
  for (int r = 0; r < model->rowCount(); ++r) {
    if (*model->value(r, 1) == 1) continue;
    ++locked;
    EXPECT_TRUE(model->value(r, 2).has_value()) << r;   // lock_deg
    EXPECT_FALSE(model->value(r, 3).has_value()) << r;  // no stroke
    EXPECT_TRUE(model->data(model->index(r, 0), Qt::ToolTipRole).isValid()) << r;
  }
  EXPECT_GT(locked, 0);
  EXPECT_LT(locked, 9);
  EXPECT_TRUE(d->statusText().contains(QStringLiteral("does not turn fully")))
      << d->statusText().toStdString();
  EXPECT_EQ(d->plots()->familyBox()->currentData().toInt(),
            static_cast<int>(StudyPlots::Family::Paths));
  d->resize(1180, 760);
  QApplication::processEvents();
  shot(d, "design-study-locked");
}

TEST(DesignStudy, ARunReportsProgressKeepsTheWindowLiveAndCanBeCancelled) {
  MainWindow w;
  StudyDialog* d = startLongRun(w, "ground.C", "needlebar.G");
  QSignalSpy ended(d, &StudyDialog::runEnded);
  ASSERT_TRUE(d->runner()->running());
  EXPECT_FALSE(d->runButton()->isEnabled());
  EXPECT_TRUE(d->cancelButton()->isEnabled());
  EXPECT_FALSE(d->run());  // one run at a time
  // The event loop runs while the study does: the progress bar moves.
  int loops = 0;
  while (d->progressBar()->value() < 10 && d->runner()->running()) {
    QApplication::processEvents(QEventLoop::AllEvents, 10);
    ++loops;
  }
  EXPECT_GT(loops, 0);
  ASSERT_TRUE(d->runner()->running()) << "20,000 variants ran out before they could be cancelled";
  d->cancelButton()->click();
  ASSERT_TRUE(ended.wait(60000));
  EXPECT_TRUE(d->runner()->cancelled());
  const Study& s = d->runner()->study();
  ASSERT_GE(s.rows.size(), 10u);
  ASSERT_LT(s.rows.size(), 20000u);
  EXPECT_TRUE(d->statusText().startsWith(QStringLiteral("Cancelled")));
  EXPECT_EQ(d->model()->rowCount(), static_cast<int>(s.rows.size()));
  // The rows computed are the first values of t, each as runStudy computes it.
  StudySpec one = d->runner()->spec();
  for (size_t i = 0; i < s.rows.size(); ++i)
    EXPECT_EQ(s.rows[i].t, one.from + (one.to - one.from) * static_cast<double>(i) / (20000 - 1));
  one.values = static_cast<int>(s.rows.size());
  one.to = one.from + (one.to - one.from) * (one.values - 1) / (20000 - 1);
  const Study check = runStudy(w.document()->design(), one);
  for (size_t i : {size_t(0), s.rows.size() - 1}) {
    EXPECT_NEAR(check.rows[i].t, s.rows[i].t, 1e-15);
    EXPECT_NEAR(check.rows[i].point.stroke, s.rows[i].point.stroke, 1e-12);
  }
  EXPECT_TRUE(d->runButton()->isEnabled());
}

TEST(DesignStudy, AFormThatCannotRunSaysWhichField) {
  MainWindow w;
  ASSERT_TRUE(w.openExample("four-bar-crank-rocker"));
  StudyDialog* d = w.designChecks().studyDialog();
  fill(d, {"ground.O4", nullptr, "", "10", "0", "1", 3, "coupler.P"});
  EXPECT_FALSE(d->run());
  EXPECT_TRUE(d->statusText().startsWith(QStringLiteral("About"))) << d->statusText().toStdString();
  fill(d, {"ground.O4", "1", nullptr, nullptr, "0", "1", 3, "coupler.P"});
  EXPECT_FALSE(d->run());
  EXPECT_TRUE(d->statusText().startsWith(QStringLiteral("By"))) << d->statusText().toStdString();
  fill(d, {"ground.O4", "1, 0", nullptr, nullptr, "zero", "1", 3, "coupler.P"});
  EXPECT_FALSE(d->run());
  EXPECT_TRUE(d->statusText().startsWith(QStringLiteral("t from")));
  d->directionEdit()->setText(QStringLiteral("0, 0"));
  fill(d, {"ground.O4", "1, 0", nullptr, nullptr, "0", "1", 3, "coupler.P"});
  EXPECT_FALSE(d->run());
  EXPECT_TRUE(d->statusText().startsWith(QStringLiteral("Along")));
  EXPECT_FALSE(d->runner()->running());
}

TEST(DesignStudy, ClosingTheDialogCancelsItsRunAndEditsKeepTheChoices) {
  MainWindow w;
  StudyDialog* d = startLongRun(w, "ground.F", "rod.E");
  QSignalSpy ended(d, &StudyDialog::runEnded);
  ASSERT_TRUE(d->runner()->running());
  d->close();
  ASSERT_TRUE(ended.wait(60000));
  EXPECT_TRUE(d->runner()->cancelled());
  // An edit offers the new design's points and keeps the ones chosen.
  Mechanism m = w.document()->design();
  m.name = "renamed";
  w.document()->setDesign(m);
  EXPECT_EQ(d->moveBox()->currentText(), QStringLiteral("ground.F"));
  EXPECT_EQ(d->pointBox()->currentText(), QStringLiteral("rod.E"));
  EXPECT_EQ(w.designChecks().studyDialog(), d);  // one per window
}

}  // namespace
}  // namespace linkage::ui
