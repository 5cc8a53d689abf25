#include "design/checks_panel.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QScrollArea>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>

#include "design/design_choices.h"
#include "document/document.h"
#include "linkage/grashof.h"

namespace linkage::ui {

namespace {

QString deg(double v) {
  return QString::number(v, 'f', 2);
}

QTableWidget* makeTable(const QStringList& headers) {
  auto* t = new QTableWidget(0, headers.size());
  t->setHorizontalHeaderLabels(headers);
  t->verticalHeader()->hide();
  t->setEditTriggers(QAbstractItemView::NoEditTriggers);
  t->setSelectionBehavior(QAbstractItemView::SelectRows);
  t->setWordWrap(false);
  t->horizontalHeader()->setStretchLastSection(true);
  t->verticalHeader()->setDefaultSectionSize(t->fontMetrics().height() + 6);
  // As tall as its rows: the dock scrolls, not each table.
  t->setSizeAdjustPolicy(QAbstractScrollArea::AdjustToContents);
  t->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  t->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
  return t;
}

// A cell showing `text`, with the exact value behind it (and the crank angle it is at).
QTableWidgetItem* cell(const QString& text, const QVariant& exact = {},
                       const QVariant& crank = {}) {
  auto* i = new QTableWidgetItem(text);
  if (exact.isValid()) i->setData(Qt::UserRole, exact);
  if (crank.isValid()) i->setData(ChecksPanel::CrankRole, crank);
  return i;
}

QGroupBox* section(const QString& title, QLayout* layout) {
  auto* box = new QGroupBox(title);
  box->setLayout(layout);
  layout->setContentsMargins(4, 4, 4, 4);
  return box;
}

QLabel* note() {
  auto* l = new QLabel;
  l->setWordWrap(true);
  l->setTextInteractionFlags(Qt::TextSelectableByMouse);
  return l;
}

}  // namespace

ChecksPanel::ChecksPanel(DesignChoices* choices, QWidget* parent)
    : DockPanel(Redraw::Now, Behind::Rests, parent), choices_(choices) {
  buildWidgets();
  connect(choices_, &DesignChoices::bandChanged, this, [this] {
    QSignalBlocker a(lo_), b(hi_);
    lo_->setValue(choices_->band().lo);
    hi_->setValue(choices_->band().hi);
    markStale();
  });
  connect(choices_, &DesignChoices::subjectChanged, this, &ChecksPanel::markStale);
}

void ChecksPanel::buildWidgets() {
  createResults();
  QHBoxLayout* band = bandRow();
  QFormLayout* form = subjectForm();
  layOut(band, form);
}

void ChecksPanel::createResults() {
  grashof_ = makeTable({tr("Loop"), tr("Class"), tr("Links [mm]"), tr("Margin [mm]")});
  grashof_->setToolTip(
      tr("Each ring of four bodies joined by four pins: frame, input, coupler, "
         "output, with the links between their pins. Grashof: s + l < p + q, "
         "the shortest link turns fully; margin (p + q) - (s + l)"));
  transmission_ = makeTable(
      {tr("Joint"), tr("Min (crank)"), tr("Max (crank)"), tr("Outside the band (crank)")});
  transmission_->setToolTip(tr("Over a turn of the crank; double-click a value to turn there"));
  limits_ = makeTable({tr("Extreme"), tr("Crank [\u00b0]"), tr("Value")});
  limits_->setToolTip(
      tr("Every extreme over a turn of the crank; double-click one to turn "
         "there"));
  for (QTableWidget* t : {transmission_, limits_})
    connect(t, &QTableWidget::cellDoubleClicked, this, [this, t](int row, int column) {
      if (QTableWidgetItem* i = t->item(row, column); i && i->data(CrankRole).isValid())
        turnTo(i->data(CrankRole).toDouble());
    });
  transmissionNote_ = note();
  limitsNote_ = note();
}

QHBoxLayout* ChecksPanel::bandRow() {
  lo_ = new QDoubleSpinBox;
  hi_ = new QDoubleSpinBox;
  for (QDoubleSpinBox* s : {lo_, hi_}) {
    s->setRange(0, 180);
    s->setDecimals(1);
    s->setSuffix(QStringLiteral("\u00b0"));
    s->setKeyboardTracking(false);
  }
  lo_->setValue(choices_->band().lo);
  hi_->setValue(choices_->band().hi);
  for (QDoubleSpinBox* s : {lo_, hi_})
    connect(s, &QDoubleSpinBox::valueChanged, this, [this] {
      if (!choices_->setBand({lo_->value(), hi_->value()}))
        transmissionNote_->setText(tr("The band needs its low end below its high end."));
    });
  lo_->setToolTip(tr("Transmission angles below this are flagged (remembered)"));
  hi_->setToolTip(tr("Transmission angles above this are flagged (remembered)"));
  auto* band = new QHBoxLayout;
  band->addWidget(new QLabel(tr("Band")));
  band->addWidget(lo_);
  band->addWidget(new QLabel(QStringLiteral("\u2013")));
  band->addWidget(hi_);
  band->addStretch();
  return band;
}

QFormLayout* ChecksPanel::subjectForm() {
  subject_ = new QComboBox;
  subject_->setToolTip(tr("The point whose extreme positions are found, or a body's angle"));
  direction_ = new QLineEdit;
  direction_->setPlaceholderText(tr("default: its slot, else +y"));
  direction_->setToolTip(tr("The direction DX, DY the point's position is measured along"));
  connect(subject_, &QComboBox::activated, this, &ChecksPanel::subjectEdited);
  connect(direction_, &QLineEdit::editingFinished, this, &ChecksPanel::subjectEdited);
  auto* form = new QFormLayout;
  form->addRow(tr("Of"), subject_);
  form->addRow(tr("Along"), direction_);
  return form;
}

void ChecksPanel::layOut(QHBoxLayout* band, QFormLayout* form) {
  auto* g = new QVBoxLayout;
  g->addWidget(grashof_);
  auto* t = new QVBoxLayout;
  t->addLayout(band);
  t->addWidget(transmission_);
  t->addWidget(transmissionNote_);
  auto* l = new QVBoxLayout;
  l->addLayout(form);
  l->addWidget(limits_);
  l->addWidget(limitsNote_);
  auto* content = new QWidget;
  auto* sections = new QVBoxLayout(content);
  sections->setContentsMargins(2, 2, 2, 2);
  sections->addWidget(section(tr("Four-bar loops (Grashof)"), g));
  sections->addWidget(section(tr("Transmission angles"), t));
  sections->addWidget(section(tr("Limit positions and stroke"), l));
  sections->addStretch();
  auto* scroll = new QScrollArea;
  scroll->setWidget(content);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(scroll);
}

void ChecksPanel::setDocument(Document* doc) {
  delete docContext_;
  docContext_ = nullptr;
  doc_ = doc;
  if (doc_) {
    docContext_ = new QObject(this);
    connect(doc_, &Document::designChanged, docContext_, [this] { markStale(); });
  }
  markStale();
}

QString ChecksPanel::transmissionStatus() const {
  return transmissionNote_->text();
}

QString ChecksPanel::limitsStatus() const {
  return limitsNote_->text();
}

void ChecksPanel::compute() {
  ++computations_;
  offerSubjects();
  fillGrashof();
  fillTransmission();
  fillLimits();
}

void ChecksPanel::offerSubjects() {
  QSignalBlocker block(subject_);
  subject_->clear();
  if (!doc_) return;
  const Mechanism& m = doc_->design();
  const Body* ground = m.ground();
  auto addPoint = [&](PointId id) {
    subject_->addItem(
        QString::fromStdString(m.pointLabel(id)),
        QStringList{QStringLiteral("point"), QString::fromStdString(m.pointLabel(id))});
  };
  for (PointId p : m.outputs) addPoint(p);
  for (const Point& p : m.points)
    if ((!ground || p.body != ground->id) &&
        std::find(m.outputs.begin(), m.outputs.end(), p.id) == m.outputs.end())
      addPoint(p.id);
  for (const Body& b : m.bodies)
    if (!b.ground)
      subject_->addItem(tr("%1 (angle)").arg(QString::fromStdString(b.name)),
                        QStringList{QStringLiteral("body"), QString::fromStdString(b.name)});
  // What the checks follow: the subject, or the first output in its place.
  const std::optional<LimitMeasure> what = choices_->measure(m);
  QStringList key;
  if (what && what->body)
    key = {QStringLiteral("body"), QString::fromStdString(m.body(what->body)->name)};
  else if (what)
    key = {QStringLiteral("point"), QString::fromStdString(m.pointLabel(what->point))};
  subject_->setCurrentIndex(subject_->findData(key));
  const std::optional<Vec2>& d = choices_->subject().direction;
  direction_->setText(d ? QStringLiteral("%1, %2").arg(d->x()).arg(d->y()) : QString());
  direction_->setEnabled(!what || !what->body);
}

void ChecksPanel::subjectEdited() {
  const QStringList key = subject_->currentData().toStringList();
  if (key.size() != 2) return;
  LimitSubject s;
  (key[0] == QStringLiteral("body") ? s.body : s.point) = key[1];
  const QStringList xy = direction_->text().split(',');
  bool okX = false, okY = false;
  const double x = xy.value(0).trimmed().toDouble(&okX), y = xy.value(1).trimmed().toDouble(&okY);
  if (s.point.isEmpty() || direction_->text().trimmed().isEmpty()) {
    s.direction.reset();
  } else if (xy.size() == 2 && okX && okY && std::isfinite(x) && std::isfinite(y) &&
             (x != 0 || y != 0)) {
    s.direction = Vec2(x, y);
  } else {
    limitsNote_->setText(tr("The direction is two numbers DX, DY, not both 0."));
    return;
  }
  choices_->setSubject(s);
}

void ChecksPanel::fillGrashof() {
  grashof_->setRowCount(0);
  if (!doc_) return;
  const Mechanism& m = doc_->design();
  const std::vector<FourBarLoop> loops = fourBarLoops(m);
  grashof_->setRowCount(static_cast<int>(loops.size()));
  for (int r = 0; r < grashof_->rowCount(); ++r) {
    const FourBarLoop& l = loops[r];
    QStringList names, lengths;
    QVariantList exact;
    for (int i = 0; i < 4; ++i) {
      names << QString::fromStdString(m.body(l.bodies[i])->name);
      lengths << QString::number(l.lengths[i], 'g', 6);
      exact << l.lengths[i];
    }
    grashof_->setItem(r, 0, cell(names.join(QStringLiteral("\u2013"))));
    grashof_->setItem(r, 1, cell(QString::fromUtf8(toString(l.kind)), static_cast<int>(l.kind)));
    grashof_->setItem(r, 2, cell(lengths.join(QStringLiteral(", ")), exact));
    grashof_->setItem(r, 3, cell(QString::number(l.margin, 'g', 6), l.margin));
  }
  grashof_->resizeColumnsToContents();
}

bool ChecksPanel::clearSection(QTableWidget* table, QLabel* note) const {
  table->setRowCount(0);
  note->clear();
  if (doc_ && doc_->solved()) return true;
  note->setText(tr("No motion: the design is not solved."));
  return false;
}

void ChecksPanel::fillTransmission() {
  if (!clearSection(transmission_, transmissionNote_)) return;
  TransmissionOptions opt;
  opt.band = choices_->band();
  const TransmissionSweep s = sweepTransmission(doc_->kinematics(), opt);
  if (!s.status.ok()) {
    transmissionNote_->setText(QString::fromStdString(s.status.message));
    return;
  }
  if (s.joints.empty())
    transmissionNote_->setText(tr("No joint where a link drives another through a pin or a slot."));
  transmission_->setRowCount(static_cast<int>(s.joints.size()));
  for (int r = 0; r < transmission_->rowCount(); ++r) {
    const TransmissionSummary& t = s.summaries[r];
    auto* name = cell(QStringLiteral("\u03bc%1 %2")
                          .arg(r + 1)
                          .arg(QString::fromStdString(s.joints[r].label.substr(3))),
                      QString::fromStdString(s.joints[r].label));
    name->setToolTip(QString::fromUtf8(toString(s.joints[r].kind)));
    transmission_->setItem(r, 0, name);
    auto at = [](double v, double crank) {
      return QStringLiteral("%1\u00b0 (%2\u00b0)").arg(deg(v), QString::number(crank, 'f', 1));
    };
    transmission_->setItem(r, 1, cell(at(t.min, t.minDeg), t.min, t.minDeg));
    transmission_->setItem(r, 2, cell(at(t.max, t.maxDeg), t.max, t.maxDeg));
    QStringList stretches;
    QVariantList exact;
    for (const TransmissionStretch& o : t.outside) {
      stretches << QStringLiteral("%1 %2\u2013%3\u00b0")
                       .arg(o.below ? QStringLiteral("below") : QStringLiteral("above"),
                            QString::number(o.fromDeg, 'f', 1), QString::number(o.toDeg, 'f', 1));
      exact.append(QVariant(QVariantList{o.fromDeg, o.toDeg, o.below}));
    }
    auto* out = cell(stretches.isEmpty() ? tr("none") : stretches.join(QStringLiteral(", ")), exact,
                     t.outside.empty() ? QVariant() : QVariant(t.outside.front().fromDeg));
    if (!stretches.isEmpty()) {
      const QColor warning = palette().color(QPalette::Base).lightnessF() < 0.5
                                 ? QColor(255, 90, 80)
                                 : QColor(210, 30, 20);
      if (t.min < s.band.lo) transmission_->item(r, 1)->setForeground(warning);
      if (t.max > s.band.hi) transmission_->item(r, 2)->setForeground(warning);
      out->setForeground(warning);
    }
    transmission_->setItem(r, 3, out);
  }
  transmission_->resizeColumnsToContents();
}

void ChecksPanel::fillLimits() {
  if (!clearSection(limits_, limitsNote_)) return;
  const std::optional<LimitMeasure> what = choices_->measure(doc_->design());
  if (!what) {
    limitsNote_->setText(tr("Choose a point or a body (the design has no output point)."));
    return;
  }
  const Limits l = findLimits(doc_->kinematics(), *what);
  if (!l.status.ok()) {
    limitsNote_->setText(QString::fromStdString(l.status.message));
    return;
  }
  const QString unit = what->body ? QStringLiteral("\u00b0") : QStringLiteral(" mm");
  // As `linkage-cli limits` lists them: every extreme in crank order, then the stroke.
  const int n = static_cast<int>(l.extremes.size());
  limits_->setRowCount(n + 1);
  for (int r = 0; r < n; ++r) {
    const LocalExtreme& e = l.extremes[r];
    limits_->setItem(r, 0, cell(e.max ? tr("max") : tr("min"), e.max, e.crankDeg));
    limits_->setItem(r, 1, cell(deg(e.crankDeg), e.crankDeg, e.crankDeg));
    limits_->setItem(r, 2, cell(QString::number(e.value, 'f', 3) + unit, e.value, e.crankDeg));
  }
  limits_->setItem(n, 0, cell(tr("stroke")));
  limits_->setItem(n, 2, cell(QString::number(l.stroke, 'f', 3) + unit, l.stroke));
  limits_->resizeColumnsToContents();
  QString text = !l.moves ? tr("It does not move with the crank.")
                          : tr("From %1 to %2%3: %4")
                                .arg(QString::number(l.min, 'f', 3), QString::number(l.max, 'f', 3),
                                     unit, choices_->describe(doc_->design()));
  if (!l.periodic) text += tr("; the motion does not repeat after a turn");
  limitsNote_->setText(text);
}

void ChecksPanel::turnTo(double crankDeg) {
  if (!doc_ || !doc_->solved()) return;
  // The same position in the turn the crank is in, so that the mechanism moves the short way.
  const double now = doc_->crankDeg();
  doc_->setCrankDeg(crankDeg + 360 * std::round((now - crankDeg) / 360));
}

}  // namespace linkage::ui
