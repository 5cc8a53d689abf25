#include "properties/inspector_panel.h"

#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

#include "document/document.h"
#include "document/shown_numbers.h"
#include "linkage/space.h"

namespace linkage::ui {

namespace {
const Vec2 kUnknown(NAN, NAN);
}  // namespace

InspectorPanel::InspectorPanel(QWidget* parent) : QWidget(parent) {
  summary_ = new QLabel;
  summary_->setWordWrap(true);
  summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  summary_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
  motion_ = new QTableWidget(0, 4);
  setHeaders(false);
  motion_->verticalHeader()->hide();
  motion_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  // Columns sized once per design, not per frame: sizing to contents measures every cell's
  // text, which cost more than the whole solve and paint of a frame.
  motion_->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
  auto* l = new QVBoxLayout(this);
  l->setContentsMargins(4, 4, 4, 4);
  l->addWidget(summary_);
  l->addWidget(new QLabel(tr("<b>Output points</b> (exact, at the current crank angle)")));
  l->addWidget(motion_, 1);
  note_ = new QLabel;
  note_->setWordWrap(true);
  note_->setTextFormat(Qt::PlainText);
  note_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  note_->hide();
  l->addWidget(note_);
}

void InspectorPanel::setHeaders(bool inSpace) {
  if (int(inSpace) == inSpace_) return;
  inSpace_ = inSpace;
  if (inSpace)
    motion_->setHorizontalHeaderLabels({tr("point"), tr("world x, y, z [mm]"),
                                        tr("world vx, vy, vz [mm/s]"),
                                        tr("world ax, ay, az [mm/s\u00b2]")});
  else
    motion_->setHorizontalHeaderLabels(
        {tr("point"), tr("position [mm]"), tr("velocity [mm/s]"), tr("acceleration [mm/s\u00b2]")});
}

QString InspectorPanel::noteText() const {
  return note_->isHidden() ? QString() : note_->text();
}

void InspectorPanel::setDocument(Document* doc) {
  if (doc_) disconnect(doc_, nullptr, this, nullptr);
  doc_ = doc;
  if (doc_) {
    connect(doc_, &Document::designChanged, this, &InspectorPanel::refreshSummary);
    connect(doc_, &Document::fileStateChanged, this, &InspectorPanel::refreshSummary);
  }
  refreshSummary();
}

void InspectorPanel::showEvent(QShowEvent* e) {
  QWidget::showEvent(e);
  refreshSummary();
}

QString InspectorPanel::summaryText() const {
  return summary_->text();
}

void InspectorPanel::refreshSummary() {
  if (!doc_) return;
  const Mechanism& m = doc_->design();
  const Kinematics& k = doc_->kinematics();
  QString s =
      tr("<b>%1</b><br>%2<br>")
          .arg(QString::fromStdString(m.name).toHtmlEscaped(),
               doc_->filePath().isEmpty() ? tr("not saved") : doc_->filePath().toHtmlEscaped());
  s += tr("%1 bodies, %2 joints").arg(m.bodies.size()).arg(m.joints.size());
  // The structure and the solve of the design only: a design the solver refused has none (what
  // it keeps is the last design it could solve, another one).
  if (doc_->solved()) {
    const StructureReport r = k.structure();
    s += tr("<br>Degrees of freedom: <b>%1</b> (Gruebler %2, rank %3 of %4 equations)")
             .arg(r.mobility)
             .arg(r.gruebler)
             .arg(r.rank)
             .arg(r.jointEquations);
    s += tr("<br>Solved %1")
             .arg(k.closedForm() ? tr("in closed form, group by group")
                                 : tr("by Newton on all coordinates"));
    for (const Note& n : k.notes())
      s += QStringLiteral("<br>\u2022 ") + QString::fromStdString(n.text).toHtmlEscaped();
  }
  if (!doc_->solveStatus().ok())
    s += tr("<br><font color='#d22'><b>Not solved:</b> %1</font>")
             .arg(QString::fromStdString(doc_->solveStatus().message).toHtmlEscaped());
  summary_->setText(s);
  refreshMotion();
}

void InspectorPanel::refreshMotion() {
  // Seen only: a dock in a tab behind another is moved off the window but stays "visible".
  if (!isVisible() || visibleRegion().isEmpty() || !doc_) return;
  const Kinematics& k = doc_->kinematics();
  const Mechanism& m = k.mechanism();
  // Only what the solver has determined: nothing of a design it has not solved (the last good
  // state is another design), nothing of a point the driver does not move.
  const bool solved = doc_->solved();
  const int n = solved ? static_cast<int>(m.outputs.size()) : 0;
  const bool resize = motion_->rowCount() != n;
  if (resize) {
    motion_->setRowCount(n);
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < 4; ++c) motion_->setItem(r, c, new QTableWidgetItem);
  }
  // In space the world's x, y, z (the solver's planar ones are in each plane class's frame).
  const bool inSpace = isSpatial(m);
  setHeaders(inSpace);
  QStringList why;
  if (!solved && !doc_->design().outputs.empty()) why << tr("Not solved: no motion to show.");
  for (int r = 0; r < n; ++r) {
    const PointId p = m.outputs[r];
    motion_->item(r, 0)->setText(QString::fromStdString(m.pointLabel(p)));
    const Status determined = k.checkDetermined({p});
    if (!determined.ok()) why << QString::fromStdString(determined.message);
    const Vec3 nan = Vec3::Constant(NAN);
    Kinematics::PointMotion3 pm{nan, nan, nan};
    if (determined.ok() && inSpace) pm = k.motionInSpace(p);
    if (determined.ok() && !inSpace) {
      const Kinematics::PointMotion flat = k.motion(p);
      auto lift = [](const Vec2& v) { return Vec3(v.x(), v.y(), 0); };
      pm = {lift(flat.position), lift(flat.velocity), lift(flat.acceleration)};
    }
    const Vec3* v[3] = {&pm.position, &pm.velocity, &pm.acceleration};
    for (int c = 0; c < 3; ++c) {
      const double scale = motionScale(k, c);
      QStringList xyz;
      for (int i = 0; i < (inSpace ? 3 : 2); ++i) xyz << fixedText(cleaned((*v[c])[i], scale), 3);
      motion_->item(r, c + 1)->setText(v[c]->allFinite() ? xyz.join(QStringLiteral(", "))
                                       : determined.ok() ? QStringLiteral("\u2013")
                                                         : tr("not determined"));
    }
  }
  note_->setText(why.join(QLatin1Char('\n')));
  note_->setVisible(!why.isEmpty());
  if (resize) motion_->resizeColumnsToContents();
}

}  // namespace linkage::ui
