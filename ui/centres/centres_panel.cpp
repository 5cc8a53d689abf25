#include "centres/centres_panel.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHeaderView>
#include <QLineEdit>
#include <QScrollBar>
#include <QSplitter>
#include <QTableWidget>
#include <QTextBrowser>
#include <QVBoxLayout>
#include <cmath>

#include "document/document.h"
#include "document/shown_numbers.h"

namespace linkage::ui {

namespace {

QString num(double v, int decimals = 3) {
  return fixedText(v, decimals);
}

QString pt(const Vec2& v) {
  return QStringLiteral("(%1, %2)").arg(num(v.x()), num(v.y()));
}

QString ic(int i, int j) {
  return QStringLiteral("IC(%1,%2)").arg(std::min(i, j)).arg(std::max(i, j));
}

QString bodyName(const Document& d, const InstantCentres& ics, int n) {
  const Body* b = d.kinematics().mechanism().body(ics.bodyNumbered(n));
  return b ? QString::fromStdString(b->name) : QStringLiteral("?");
}

}  // namespace

CentresPanel::CentresPanel(QWidget* parent) : DockPanel(Redraw::NextTurn, Behind::Rests, parent) {
  table_ = new QTableWidget(0, 6);
  table_->setHorizontalHeaderLabels(
      {tr("i,j"), tr("bodies"), tr("x [mm]"), tr("y [mm]"), tr("at \u221e"), tr("found by")});
  table_->verticalHeader()->hide();
  // Only the rows in view are written at each pose: the others when they come into it.
  connect(table_->verticalScrollBar(), &QScrollBar::valueChanged, this,
          &CentresPanel::fillScrolledTo);
  connect(table_->verticalScrollBar(), &QScrollBar::rangeChanged, this,
          &CentresPanel::fillScrolledTo);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setSelectionMode(QAbstractItemView::SingleSelection);
  // Columns sized once per design, not per frame: sizing to contents measures every cell's
  // text, which cost more than the whole solve and paint of a frame.
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
  table_->horizontalHeader()->setStretchLastSection(true);
  connect(table_, &QTableWidget::itemSelectionChanged, this, [this] {
    const auto rows = table_->selectionModel()->selectedRows();
    if (rows.isEmpty()) {
      emit centreChosen(0, 0);
      return;
    }
    const QStringList ij = table_->item(rows[0].row(), 0)->text().split(',');
    emit centreChosen(ij.value(0).toInt(), ij.value(1).toInt());
  });

  textTimer_.setSingleShot(true);
  connect(&textTimer_, &QTimer::timeout, this, [this] {
    if (chain_) {
      steps_->setHtml(chainText());
      lastText_.start();
    }
  });
  point_ = new QComboBox;
  point_->setToolTip(tr("The point whose velocity the chain of centres finds"));
  via_ = new QLineEdit;
  via_->setPlaceholderText(tr("e.g. 3,4 (optional)"));
  via_->setToolTip(
      tr("Textbook numbers of the bodies to go through, from the crank to the point's body"));
  steps_ = new QTextBrowser;
  steps_->setOpenLinks(false);
  connect(point_, &QComboBox::currentIndexChanged, this, &CentresPanel::refresh);
  connect(point_, &QComboBox::activated, this, [this](int i) { choseNone_ = i == 0; });
  connect(via_, &QLineEdit::editingFinished, this, &CentresPanel::refresh);

  auto* chainBox = new QWidget;
  auto* form = new QFormLayout;
  form->addRow(tr("Velocity of"), point_);
  form->addRow(tr("Through bodies"), via_);
  auto* chainLayout = new QVBoxLayout(chainBox);
  chainLayout->setContentsMargins(0, 0, 0, 0);
  chainLayout->addLayout(form);
  chainLayout->addWidget(steps_);

  auto* split = new QSplitter(Qt::Vertical);
  split->addWidget(table_);
  split->addWidget(chainBox);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  layout->addWidget(split);
}

void CentresPanel::setDocument(Document* doc) {
  if (doc_) disconnect(doc_, nullptr, this, nullptr);
  doc_ = doc;
  if (doc_) connect(doc_, &Document::designChanged, this, &CentresPanel::rebuildPoints);
  rebuildPoints();
}

void CentresPanel::rebuildPoints() {
  QStringList labels{tr("(none)")};
  if (doc_) {
    const Mechanism& m = doc_->kinematics().mechanism();
    // Output points first: the ones a user checks.
    for (PointId p : m.outputs) labels << QString::fromStdString(m.pointLabel(p));
    for (const Point& p : m.points)
      if (std::find(m.outputs.begin(), m.outputs.end(), p.id) == m.outputs.end())
        labels << QString::fromStdString(m.pointLabel(p.id));
  }
  // A design dragged with Ctrl changes many times a second and keeps its points: the choice
  // stays as it is (refilling the box cost a frame a millisecond).
  if (labels == pointLabels_) {
    refresh();
    return;
  }
  pointLabels_ = labels;
  const QString was = point_->currentText();
  QSignalBlocker block(point_);
  point_->clear();
  point_->addItems(labels);
  // The same point again after an edit; otherwise the first output point, unless the user
  // chose none.
  int i = point_->findText(was);
  if ((i < 0 || (i == 0 && !choseNone_)) && point_->count() > 1 && doc_ &&
      !doc_->kinematics().mechanism().outputs.empty())
    i = 1;
  point_->setCurrentIndex(std::max(i, 0));
  refresh();
}

void CentresPanel::refresh() {
  markStale();
}

void CentresPanel::dropChain() {
  if (!chain_) return;
  chain_.reset();
  emit chainChanged();
}

void CentresPanel::leftView() {
  // The canvas draws the chain's distances only while the panel is seen.
  dropChain();
  markStale();
}

void CentresPanel::compute() {
  // Nothing of a design the solver has not taken: the last good state is another design, or
  // another document's (a file that cannot be solved).
  if (!doc_ || !doc_->solved()) {
    dropChain();
    if (doc_) {
      table_->setRowCount(0);
      textTimer_.stop();
      steps_->setHtml(
          tr("<p><b>Not solved:</b> %1</p>")
              .arg(QString::fromStdString(doc_->solveStatus().message).toHtmlEscaped()));
    }
    return;
  }
  const InstantCentres& ics = doc_->instantCentres();
  fillTable(ics);
  fillChain(ics);
}

// The rows a user can see (and a few around them): a machine's 465 centres written every
// frame were a sixth of the frame; the others are written when they are scrolled to.
std::pair<int, int> CentresPanel::shownRows() const {
  const int n = table_->rowCount();
  if (n == 0) return {0, 0};
  int first = table_->rowAt(0), last = table_->rowAt(table_->viewport()->height() - 1);
  if (first < 0) first = 0;
  if (last < 0) last = n - 1;
  return {std::max(0, first - 2), std::min(n, last + 3)};
}

void CentresPanel::fillTable(const InstantCentres& ics) {
  if (!ics.status.ok()) {
    table_->setRowCount(0);
    return;
  }
  const int n = static_cast<int>(ics.centres.size());
  bool all = false;
  if (table_->rowCount() != n) {
    table_->setRowCount(n);
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < 6; ++c) table_->setItem(r, c, new QTableWidgetItem);
    all = true;
  }
  // Every row when the centres are others (a new design): the columns are sized on them.
  all = all || ics.revision != tableRevision_;
  tableRevision_ = ics.revision;
  fresh_.assign(n, false);
  const auto [from, to] = all ? std::pair{0, n} : shownRows();
  fillRows(ics, from, to);
}

void CentresPanel::fillRows(const InstantCentres& ics, int from, int to) {
  // Sized again when the rows name other centres or bodies (the first two columns change), not
  // on every edit: a design dragged with Ctrl is an edit a frame.
  bool relabelled = false;
  // A body free with the crank held has no centre the driver determines.
  const std::vector<BodyId> free = doc_->kinematics().structure().freeBodies;
  auto isFree = [&](int n) {
    return std::find(free.begin(), free.end(), ics.bodyNumbered(n)) != free.end();
  };
  for (int r = from; r < to && r < static_cast<int>(ics.centres.size()); ++r) {
    InstantCentre c = ics.centres[r];
    const bool held = isFree(c.i) || isFree(c.j);
    if (held) c.determined = false;
    const QString cells[6] = {
        QStringLiteral("%1,%2").arg(c.i).arg(c.j),
        bodyName(*doc_, ics, c.i) + QStringLiteral(" \u2013 ") + bodyName(*doc_, ics, c.j),
        coordinate(c, c.h.x()),
        coordinate(c, c.h.y()),
        c.atInfinity() ? tr("yes (direction)") : QString(),
        statusText(c, held) + planeText(ics, c)};
    for (int k = 0; k < 6; ++k)
      if (table_->item(r, k)->text() != cells[k]) {
        table_->item(r, k)->setText(cells[k]);
        relabelled = relabelled || k < 2;
      }
    fresh_[r] = true;
  }
  if (relabelled) {
    table_->resizeColumnsToContents();
    // Room for coordinates that grow while the mechanism moves (a centre far away).
    const int wide = table_->fontMetrics().horizontalAdvance(QStringLiteral("-00000.000  "));
    for (int c : {2, 3}) table_->setColumnWidth(c, std::max(table_->columnWidth(c), wide));
  }
}

QString CentresPanel::coordinate(const InstantCentre& c, double v) {
  if (!c.determined) return QStringLiteral("\u2013");
  return c.atInfinity() ? num(v, 4) : num(v);
}

// A machine in space: which plane's coordinates the centre is in (its class's first plane).
QString CentresPanel::planeText(const InstantCentres& ics, const InstantCentre& c) const {
  if (c.across || !c.determined || ics.classes.frames.size() < 2) return {};
  return tr(", in plane %1").arg(QString::fromStdString(ics.classes.frames[c.planeClass].name));
}

QString CentresPanel::statusText(const InstantCentre& c, bool held) const {
  if (c.across) return tr("none: their planes are not parallel");
  if (held) return tr("not determined (a body free with the crank held)");
  if (!c.determined) return tr("none (no relative motion)");
  if (c.status == CentreStatus::Kennedy)
    return tr("Kennedy, round %1 (via %2)")
        .arg(c.round)
        .arg(c.lines[0].k ? QString::number(c.lines[0].k) : tr("slot"));
  return QString::fromUtf8(toString(c.status));
}

// Rows scrolled to are written before they are painted: never a number of another pose.
void CentresPanel::fillScrolledTo() {
  if (!doc_ || !doc_->solved() || fresh_.size() != static_cast<size_t>(table_->rowCount())) return;
  const auto [from, to] = shownRows();
  for (int r = from; r < to; ++r)
    if (!fresh_[r]) {
      fillRows(doc_->instantCentres(), from, to);
      return;
    }
}

void CentresPanel::fillChain(const InstantCentres& ics) {
  const Mechanism& m = doc_->kinematics().mechanism();
  std::optional<PointId> p = m.findPoint(point_->currentText().toStdString());
  if (point_->currentIndex() <= 0 || !p || !ics.status.ok()) {
    steps_->clear();
    if (chain_) {
      chain_.reset();
      emit chainChanged();
    }
    return;
  }
  // A point the driver does not move has no velocity to find: the reason instead.
  if (const Status d = doc_->kinematics().checkDetermined({*p}); !d.ok()) {
    textTimer_.stop();
    steps_->setHtml(
        tr("<p><b>No chain:</b> %1</p>").arg(QString::fromStdString(d.message).toHtmlEscaped()));
    if (chain_) {
      chain_.reset();
      emit chainChanged();
    }
    return;
  }
  std::vector<int> via;
  for (const QString& s : via_->text().split(',', Qt::SkipEmptyParts)) via.push_back(s.toInt());
  chain_ = velocityChain(doc_->kinematics(), ics, *p, via);
  emit chainChanged();
  constexpr int kTextMs = 100;
  if (!lastText_.isValid() || lastText_.elapsed() >= kTextMs) {
    textTimer_.stop();
    steps_->setHtml(chainText());
    lastText_.start();
  } else if (!textTimer_.isActive()) {
    textTimer_.start(kTextMs - int(lastText_.elapsed()));
  }
}

QString CentresPanel::stepsText() const {
  return steps_->toPlainText();
}

QString CentresPanel::chainText() const {
  if (!chain_ || !doc_) return QString();
  const VelocityChain& ch = *chain_;
  const InstantCentres& ics = doc_->instantCentres();
  const Mechanism& m = doc_->kinematics().mechanism();
  const QString label = QString::fromStdString(m.pointLabel(ch.point));
  if (!ch.status.ok())
    return tr("<p><b>No chain:</b> %1</p>").arg(QString::fromStdString(ch.status.message));
  QString s = tr("<p><b>v of %1</b> (body %2) at crank %3&deg;</p><ol>")
                  .arg(label)
                  .arg(ch.body)
                  .arg(num(ics.crankDeg));
  s += crankText(ch, ics);
  for (const ChainStep& st : ch.steps) s += stepText(st);
  s += pointText(ch, label);
  s += QStringLiteral("</ol>");
  return s + comparisonText(ch);
}

QString CentresPanel::crankText(const VelocityChain& ch, const InstantCentres& ics) const {
  const BodyMotion& c = ch.crankMotion;
  return tr("<li>Crank %1 (%2) turns about %3 = %4 mm: &omega;%1 = %5 rad/s (%6 rpm %7)</li>")
      .arg(ch.crank)
      .arg(bodyName(*doc_, ics, ch.crank))
      .arg(ic(1, ch.crank))
      .arg(pt(c.pivot))
      .arg(num(c.omega, 4))
      .arg(doc_->kinematics().rpm())
      .arg(c.omega < 0 ? tr("cw") : tr("ccw"));
}

QString CentresPanel::stepText(const ChainStep& st) const {
  const QString P = ic(st.from, st.to);
  if (st.centreAtInfinity)
    return tr("<li>%1 is at infinity: bodies %2 and %3 turn alike, &omega;%3 = &omega;%2 = %4 "
              "rad/s</li>")
        .arg(P)
        .arg(st.from)
        .arg(st.to)
        .arg(num(st.toMotion.omega, 4));
  QString s = tr("<li>P = %1 = %2 mm").arg(P, pt(st.centre));
  if (st.fromMotion.kind == BodyMotion::Kind::Turns)
    s += tr("<br>|%1 P| = %2 mm; v<sub>P</sub> = &omega;%3 &middot; |%1 P| = %4 &times; %2 = "
            "<b>%5 mm/s</b>")
             .arg(ic(1, st.from))
             .arg(num(st.fromArm))
             .arg(st.from)
             .arg(num(std::abs(st.fromMotion.omega), 4))
             .arg(num(st.vP.norm()));
  else
    s += tr("<br>v<sub>P</sub> = v%1 = %2 mm/s").arg(st.from).arg(num(st.vP.norm()));
  s += tr("<br>P is also on body %1 (P = %2): v<sub>P</sub> is the same on both").arg(st.to).arg(P);
  return s + stepMotionText(st) + QStringLiteral("</li>");
}

QString CentresPanel::stepMotionText(const ChainStep& st) const {
  switch (st.toMotion.kind) {
    case BodyMotion::Kind::Turns:
      return tr("<br>body %1 turns about %2 = %3 mm; |%2 P| = %4 mm; &omega;%1 = v<sub>P</sub> / "
                "|%2 P| = %5 rad/s")
          .arg(st.to)
          .arg(ic(1, st.to))
          .arg(pt(st.toMotion.pivot))
          .arg(num(st.toArm))
          .arg(num(st.toMotion.omega, 4));
    case BodyMotion::Kind::Translates:
      return tr("<br>%1 is at infinity: body %2 translates with v<sub>P</sub>")
          .arg(ic(1, st.to))
          .arg(st.to);
    case BodyMotion::Kind::AtRest:
      return tr("<br>body %1 is at rest at this instant").arg(st.to);
  }
  return QString();
}

QString CentresPanel::pointText(const VelocityChain& ch, const QString& label) const {
  if (ch.bodyMotion.kind == BodyMotion::Kind::Turns)
    return tr("<li>%1 = %2 mm: |%3 %1| = %4 mm; v = &omega;%5 &middot; %4</li>")
        .arg(label, pt(ch.position), ic(1, ch.body), num(ch.arm))
        .arg(ch.body);
  if (ch.bodyMotion.kind == BodyMotion::Kind::Translates)
    return tr("<li>%1 moves with body %2: v = v%2</li>").arg(label).arg(ch.body);
  return QString();
}

QString CentresPanel::comparisonText(const VelocityChain& ch) const {
  const double diff = (ch.velocity - ch.solverVelocity).norm();
  return tr("<table><tr><td>by the chain</td><td><b>%1 mm/s</b></td><td>%2</td></tr>"
            "<tr><td>exact (solver)</td><td><b>%3 mm/s</b></td><td>%4</td></tr>"
            "<tr><td>difference</td><td>%5 mm/s</td><td></td></tr></table>")
      .arg(num(ch.velocity.norm()), pt(ch.velocity), num(ch.solverVelocity.norm()),
           pt(ch.solverVelocity))
      .arg(diff, 0, 'g', 3);
}

}  // namespace linkage::ui
