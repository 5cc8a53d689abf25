#include "cam/cam_panel.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>

#include "cam/cam_figure.h"
#include "cam/cam_table.h"
#include "document/commands.h"
#include "figures/qcp.h"
#include "linkage/cam_edits.h"
#include "linkage/cam_joint.h"
#include "linkage/elements.h"

namespace linkage::ui {

namespace {

QDoubleSpinBox* spin(const char* name, double max, const QString& suffix, const QString& tip) {
  auto* s = new QDoubleSpinBox;
  s->setObjectName(QString::fromLatin1(name));
  s->setRange(0, max);
  s->setDecimals(3);
  s->setSuffix(suffix);
  s->setKeyboardTracking(false);
  s->setStatusTip(tip);
  s->setToolTip(tip);
  return s;
}

bool isFlat(const cam::CamGeometry& g) {
  return g.face == cam::FollowerFace::Flat;
}
bool isOscillating(const cam::CamGeometry& g) {
  return g.motion == cam::FollowerMotion::Oscillating;
}

}  // namespace

CamPanel::CamPanel(Document* doc, QWidget* parent)
    : DockPanel(Redraw::Throttled, Behind::Rests, parent), doc_(doc) {
  setObjectName(QStringLiteral("camPanel"));
  buildControls();
  connect(doc_, &Document::designChanged, this, [this] { markStale(); });
  connect(doc_, &Document::poseChanged, this, [this] {
    if (shown() && !stale()) followPose();
  });
}

CamPanel::~CamPanel() = default;

void CamPanel::buildControls() {
  choice_ = new QComboBox;
  choice_->setObjectName(QStringLiteral("camChoice"));
  choice_->setStatusTip(tr("The cam shown: a cam joint of the mechanism"));
  connect(choice_, &QComboBox::activated, this, [this](int i) {
    if (i >= 0 && i < static_cast<int>(cams_.size())) showCam(cams_[i]);
  });
  follower_ = new QLabel;
  follower_->setObjectName(QStringLiteral("camFollower"));
  auto* top = new QHBoxLayout;
  top->addWidget(new QLabel(tr("Cam:")));
  top->addWidget(choice_, 1);
  top->addWidget(follower_, 2);
  table_ = new CamTable;
  connect(table_, &CamTable::edited, this,
          [this](const std::vector<cam::Segment>& s, const QString& what) {
            edit(what, [this, s](Mechanism& m, std::string& why) {
              return setCamMotion(m, shown_, s, &why);
            });
          });
  connect(table_, &CamTable::refused, this, &CamPanel::say);
  checksText_ = new QLabel;
  checksText_->setObjectName(QStringLiteral("camChecks"));
  checksText_->setWordWrap(true);
  checksText_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  message_ = new QLabel;
  message_->setObjectName(QStringLiteral("camMessage"));
  message_->setWordWrap(true);
  message_->setStyleSheet(QStringLiteral("color: #b00000"));
  auto* left = new QWidget;
  auto* leftLayout = new QVBoxLayout(left);
  leftLayout->setContentsMargins(0, 0, 0, 0);
  leftLayout->addWidget(buildSizes());
  leftLayout->addWidget(table_, 1);
  leftLayout->addWidget(checksText_);
  leftLayout->addWidget(message_);
  plot_ = new QCustomPlot;
  plot_->setObjectName(QStringLiteral("camPlot"));
  plot_->setMinimumSize(320, 260);
  figure_ = std::make_unique<CamFigure>(plot_);
  connect(figure_.get(), &CamFigure::endDragged, this, &CamPanel::endDragged);
  auto* split = new QSplitter(Qt::Horizontal);
  split->addWidget(left);
  split->addWidget(plot_);
  split->setStretchFactor(1, 1);
  split->setSizes({380, 620});
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(top);
  layout->addWidget(split, 1);
}

QWidget* CamPanel::buildSizes() {
  base_ = spin("camBase", 1e5, tr(" mm"),
               tr("The base circle's radius: the follower moves to its new lowest position"));
  roller_ = spin("camRoller", 1e5, tr(" mm"),
                 tr("The roller's radius (0: a knife edge), the pitch curve kept"));
  limit_ = spin("camLimit", 89, tr("°"),
                tr("The pressure angle's limit: drawn on the check, and kept by Find Base"));
  findBase_ = new QPushButton(tr("Find &Base"));
  findBase_->setObjectName(QStringLiteral("camFindBase"));
  findBase_->setStatusTip(
      tr("The smallest base circle (rounded up to 0.01 mm) whose largest "
         "pressure angle is within the limit"));
  findRoller_ = new QPushButton(tr("Find &Roller"));
  findRoller_->setObjectName(QStringLiteral("camFindRoller"));
  findRoller_->setStatusTip(
      tr("The largest roller (rounded down to 0.01 mm) that does not "
         "undercut: the pitch curve's least convex radius"));
  connect(base_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
    if (geometry_ && std::abs(v - geometry_->baseMm) > 1e-9)
      edit(tr("Cam Base Circle"),
           [this, v](Mechanism& m, std::string& why) { return setCamBase(m, shown_, v, &why); });
  });
  connect(roller_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
    if (geometry_ && std::abs(v - geometry_->rollerMm) > 1e-9)
      edit(tr("Cam Roller"),
           [this, v](Mechanism& m, std::string& why) { return setCamRoller(m, shown_, v, &why); });
  });
  connect(limit_, &QDoubleSpinBox::valueChanged, this, [this] { markStale(); });
  auto say = [this](bool ok, const QString& why) {
    if (!ok) this->say(why);
  };
  connect(findBase_, &QPushButton::clicked, this, [this, say] {
    QString why;
    say(findBase(&why), why);
  });
  connect(findRoller_, &QPushButton::clicked, this, [this, say] {
    QString why;
    say(findRoller(&why), why);
  });
  auto* box = new QWidget;
  auto* form = new QFormLayout(box);
  form->setContentsMargins(0, 0, 0, 0);
  auto* baseRow = new QHBoxLayout;
  baseRow->addWidget(base_, 1);
  baseRow->addWidget(findBase_);
  auto* rollerRow = new QHBoxLayout;
  rollerRow->addWidget(roller_, 1);
  rollerRow->addWidget(findRoller_);
  form->addRow(tr("Base circle"), baseRow);
  form->addRow(tr("Roller"), rollerRow);
  form->addRow(tr("Pressure limit"), limit_);
  return box;
}

double CamPanel::limitDeg() const {
  return limit_->value();
}

void CamPanel::showCam(JointId j) {
  if (j == shown_) return;
  shown_ = j;
  geometry_.reset();
  markStale();
  ensureComputed();
}

void CamPanel::refreshCams() {
  const Mechanism& m = doc_->design();
  const JointType camType = elementKindNamed("cam")->type;
  cams_.clear();
  QSignalBlocker block(choice_);
  choice_->clear();
  for (const Joint& j : m.joints) {
    if (j.type != camType) continue;
    cams_.push_back(j.id);
    choice_->addItem(QStringLiteral("%1 → %2").arg(QString::fromStdString(m.pointLabel(j.a)),
                                                   QString::fromStdString(m.pointLabel(j.b))));
  }
  const auto at = std::find(cams_.begin(), cams_.end(), shown_);
  if (at == cams_.end()) {
    const bool had = static_cast<bool>(shown_);
    shown_ = cams_.empty() ? JointId{} : cams_.front();
    if (had || shown_) geometry_.reset();
  }
  choice_->setCurrentIndex(
      shown_ ? static_cast<int>(std::find(cams_.begin(), cams_.end(), shown_) - cams_.begin())
             : -1);
}

void CamPanel::compute() {
  refreshCams();
  const Mechanism& m = doc_->design();
  const Joint* j = shown_ ? m.joint(shown_) : nullptr;
  std::string why, where;
  const std::optional<CamJoint> c = j ? camJoint(m, *j, &why, &where) : std::nullopt;
  for (QWidget* w :
       std::initializer_list<QWidget*>{base_, roller_, limit_, findBase_, findRoller_, table_})
    w->setEnabled(static_cast<bool>(c));
  if (!c) {
    geometry_.reset();
    checks_.reset();
    marks_.clear();
    Q_EMIT marksChanged(marks_);
    table_->setSegments({}, false);
    follower_->clear();
    checksText_->clear();
    figure_->showNothing(
        j ? tr("This cam is not one yet: %1: %2")
                .arg(QString::fromStdString(where), QString::fromStdString(why))
          : tr("No cam in this mechanism: right-click a follower's point (a block in a "
               "straight slot, or a body pinned to its pivot) and choose Drive by a Cam"));
    return;
  }
  const bool first = !geometry_ || limitFor_ != shown_;
  geometry_ = cam::geometryOf(*c);
  const cam::CamGeometry& g = *geometry_;
  const cam::CamChecks checks = cam::camChecks(g);
  {
    const QSignalBlocker b1(base_), b2(roller_), b3(limit_);
    base_->setValue(g.baseMm);
    roller_->setValue(g.rollerMm);
    if (first) limit_->setValue(isOscillating(g) ? 35 : 30);
  }
  limitFor_ = shown_;
  roller_->setEnabled(!isFlat(g));
  findRoller_->setEnabled(!isFlat(g));
  findBase_->setEnabled(!isFlat(g));
  limit_->setEnabled(!isFlat(g));
  follower_->setText(tr("%1 %2, on %3")
                         .arg(isOscillating(g) ? tr("oscillating") : tr("translating"))
                         .arg(isFlat(g)        ? tr("flat face")
                              : g.rollerMm > 0 ? tr("roller")
                                               : tr("knife edge"))
                         .arg(QString::fromStdString(m.body(c->cam)->name)));
  camBody_ = c->cam;
  guideBody_ = c->guide;
  table_->setSegments(g.program.segments(), isOscillating(g));
  figure_->build(g, checks, limitDeg());
  showChecks(g, checks);
  checks_ = checks;
  centre_ = c->drawn.centre;
  followPose();
}

void CamPanel::cameIntoView() {
  followPose();
}

void CamPanel::leftView() {
  marks_.clear();
  Q_EMIT marksChanged(marks_);
}

void CamPanel::followPose() {
  if (!geometry_ || !checks_ || !doc_->solved()) return;
  const Kinematics& k = doc_->kinematics();
  const Transform cam = k.bodyTransform(camBody_);
  const double theta = camAngle(cam.R, k.bodyTransform(guideBody_).R) * 180 / M_PI;
  figure_->setCursor(crankInPeriod(theta, 360));
  // Each extreme on the cam's surface where the follower touches it then: in the cam's frame
  // about its centre as drawn, carried by the cam's motion.
  marks_.clear();
  auto mark = [&](const cam::CamExtreme& e, const QString& text, bool warn) {
    if (!e.found) return;
    const Vec2 at = cam * (centre_ + cam::camPointAt(*geometry_, e.atDeg * M_PI / 180).surface);
    marks_.push_back({at,
                      at,
                      text.arg(e.value, 0, 'f', 2).arg(e.atDeg, 0, 'f', 1),
                      warn,
                      {},
                      camBody_,
                      camBody_});
  };
  const cam::CamChecks& c = *checks_;
  mark(c.pressureMax, tr("largest pressure angle %1° (cam at %2°)"),
       c.pressureMax.value > limitDeg());
  mark(c.pitchRadiusMin, tr("least pitch radius %1 mm (cam at %2°)"), c.undercut);
  mark(c.surfaceRadiusMin, tr("least surface radius %1 mm (cam at %2°)"), c.undercut);
  Q_EMIT marksChanged(marks_);
}

void CamPanel::showChecks(const cam::CamGeometry& g, const cam::CamChecks& c) {
  QStringList lines;
  auto at = [](const cam::CamExtreme& e) { return QString::number(e.atDeg, 'f', 2); };
  if (c.pressureMax.found)
    lines << tr("Largest pressure angle %1° at %2° (limit %3°)%4")
                 .arg(c.pressureMax.value, 0, 'f', 2)
                 .arg(at(c.pressureMax))
                 .arg(limitDeg(), 0, 'g', 4)
                 .arg(c.pressureMax.value > limitDeg() ? tr(": over") : QString());
  if (c.pitchRadiusMin.found)
    lines << tr("Pitch curve's least convex radius %1 mm at %2°")
                 .arg(c.pitchRadiusMin.value, 0, 'f', 3)
                 .arg(at(c.pitchRadiusMin));
  if (c.surfaceRadiusMin.found)
    lines << tr("Surface's least radius %1 mm at %2°")
                 .arg(c.surfaceRadiusMin.value, 0, 'f', 3)
                 .arg(at(c.surfaceRadiusMin));
  lines << (c.undercut ? tr("Undercut: %1").arg(QString::fromStdString(c.undercutWhy))
                       : tr("No undercut"));
  (void)g;
  checksText_->setText(lines.join(QLatin1Char('\n')));
}

QString CamPanel::checksText() const {
  return checksText_->text();
}

void CamPanel::say(const QString& message) {
  message_->setText(message);
}

bool CamPanel::edit(const QString& text,
                    const std::function<bool(Mechanism&, std::string&)>& change, QString* why) {
  Mechanism next = doc_->design();
  std::string reason;
  if (!shown_ || !change(next, reason)) {
    const QString r = QString::fromStdString(reason);
    say(r);
    if (why) *why = r;
    markStale();  // the fields and the table back to the document's
    return false;
  }
  say(QString());
  commitEdit(doc_, text, std::move(next));
  return true;
}

bool CamPanel::findBase(QString* why) {
  if (!geometry_) return false;
  const std::optional<double> b = cam::smallestBaseFor(*geometry_, limitDeg());
  if (!b) {
    if (why) *why = tr("No base circle keeps the pressure angle within %1°").arg(limitDeg());
    return false;
  }
  const double base = std::ceil(*b * 100 - 1e-9) / 100;
  return edit(
      tr("Find Cam Base"),
      [this, base](Mechanism& m, std::string& w) { return setCamBase(m, shown_, base, &w); }, why);
}

bool CamPanel::findRoller(QString* why) {
  if (!geometry_) return false;
  const std::optional<double> r = cam::largestRoller(*geometry_);
  if (!r || !(*r > 0)) {
    if (why) *why = tr("No roller keeps the cam from undercutting: the pitch curve is not convex");
    return false;
  }
  const double roller = std::floor(*r * 100 + 1e-9) / 100;
  return edit(
      tr("Find Cam Roller"),
      [this, roller](Mechanism& m, std::string& w) { return setCamRoller(m, shown_, roller, &w); },
      why);
}

void CamPanel::endDragged(int k, double deg, bool done) {
  if (!geometry_) return;
  const std::vector<cam::Segment> s =
      CamTable::withEnd(geometry_->program.segments(), static_cast<size_t>(k), deg);
  Mechanism next = doc_->design();
  std::string why;
  if (!setCamMotion(next, shown_, s, &why)) {
    say(QString::fromStdString(why));
    return;
  }
  if (!dragBefore_) dragBefore_ = doc_->state();
  if (!done) {
    doc_->setDesign(next);  // live: the canvas and this panel follow, one undo step at the end
    return;
  }
  const DocumentState before = *dragBefore_;
  dragBefore_.reset();
  commitEdit(doc_, tr("Drag Cam Segment End"), std::move(next), before);
}

}  // namespace linkage::ui

namespace linkage::ui {

QStringList CamPanel::probeLines() const {
  QStringList out;
  auto at = [](const QWidget* w, QPoint local) {
    const QPoint g = w->mapToGlobal(local);
    return QStringLiteral("%1 %2").arg(g.x()).arg(g.y());
  };
  out << QStringLiteral("cam dock: ") + (isVisible() ? QStringLiteral("shown") : QString());
  out << QStringLiteral("cam: ") + choice_->currentText();
  QStringList segs;
  for (const cam::Segment& s : table_->segments())
    segs << QStringLiteral("%1 %2 %3")
                .arg(s.toDeg)
                .arg(s.law ? QString::fromLatin1(cam::lawName(*s.law)) : QStringLiteral("dwell"))
                .arg(s.rise);
  out << QStringLiteral("cam segments: ") + segs.join(QStringLiteral(" | "));
  out << QStringLiteral("cam base: %1 roller: %2").arg(base_->value()).arg(roller_->value());
  out << QStringLiteral("cam checks: ") + checksText_->text().replace(QLatin1Char('\n'), " | ");
  out << QStringLiteral("cam message: ") + message_->text();
  if (!isVisible()) return out;
  const QTableWidget* t = table_->table();
  for (int r = 0; r < t->rowCount(); ++r)
    for (int c = 1; c < t->columnCount(); ++c)
      out << QStringLiteral("at cam cell %1 %2: ").arg(r).arg(c) +
                 at(t->viewport(), t->visualRect(t->model()->index(r, c)).center());
  for (const QPushButton* b : {findBase_, findRoller_})
    out << QStringLiteral("at cam button %1: ").arg(b->objectName()) + at(b, b->rect().center());
  for (size_t k = 0; k < figure_->ends().size(); ++k)
    out << QStringLiteral("at cam end %1: ").arg(k) +
               at(plot_, figure_->pixelAt(1, figure_->ends()[k], 0).toPoint());
  return out;
}

}  // namespace linkage::ui
