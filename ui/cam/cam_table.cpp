#include "cam/cam_table.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>

namespace linkage::ui {

namespace {

enum Column { From, To, Law, Rise, Columns };

QString number(double v) {
  return QString::number(v, 'g', 10);
}

}  // namespace

CamTable::CamTable(QWidget* parent) : QWidget(parent) {
  table_ = new QTableWidget(0, Columns, this);
  table_->setObjectName(QStringLiteral("camSegments"));
  table_->setHorizontalHeaderLabels({tr("From (°)"), tr("To (°)"), tr("Law"), tr("Rise")});
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setSectionResizeMode(Law, QHeaderView::Stretch);
  // Room for a programme of five segments without scrolling.
  table_->setMinimumHeight(table_->horizontalHeader()->sizeHint().height() +
                           6 * table_->verticalHeader()->defaultSectionSize());
  table_->verticalHeader()->setVisible(false);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setSelectionMode(QAbstractItemView::SingleSelection);
  connect(table_, &QTableWidget::cellChanged, this, &CamTable::cellEdited);
  split_ = new QPushButton(tr("S&plit"), this);
  split_->setObjectName(QStringLiteral("camSplit"));
  split_->setStatusTip(tr("Split the selected segment at its middle into two halves of its rise"));
  join_ = new QPushButton(tr("&Join"), this);
  join_->setObjectName(QStringLiteral("camJoin"));
  join_->setStatusTip(tr("Join the selected segment to the one before it, their rises added"));
  connect(split_, &QPushButton::clicked, this, [this] {
    const int row = selectedRow();
    if (row >= 0) ask(split(segments_, row), tr("Split Cam Segment"));
  });
  connect(join_, &QPushButton::clicked, this, [this] {
    const int row = selectedRow();
    if (row >= 0 && segments_.size() > 1) ask(joined(segments_, row), tr("Join Cam Segments"));
  });
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(split_);
  buttons->addWidget(join_);
  buttons->addStretch();
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(table_);
  layout->addLayout(buttons);
}

void CamTable::ask(const std::vector<cam::Segment>& s, const QString& what) {
  asked_ = true;
  // After the cell's own signal has returned: the edit refills the table, and an item must not
  // be replaced while it tells of its change.
  QMetaObject::invokeMethod(
      this, [this, s, what] { Q_EMIT edited(s, what); }, Qt::QueuedConnection);
}

int CamTable::selectedRow() const {
  const int row = table_->currentRow();
  return row >= 0 && row < static_cast<int>(segments_.size()) ? row : -1;
}

void CamTable::setSegments(const std::vector<cam::Segment>& s, bool oscillating) {
  // The same programme shown again after an edit was asked for: the cells may hold the edit.
  if (!asked_ && s == segments_ && oscillating == oscillating_ &&
      table_->rowCount() == static_cast<int>(s.size()))
    return;
  asked_ = false;
  segments_ = s;
  oscillating_ = oscillating;
  fill();
}

void CamTable::fill() {
  filling_ = true;
  const int current = table_->currentRow();
  table_->setRowCount(static_cast<int>(segments_.size()));
  table_->horizontalHeaderItem(Rise)->setText(oscillating_ ? tr("Rise (°)") : tr("Rise (mm)"));
  double from = 0;
  for (int r = 0; r < table_->rowCount(); ++r) {
    const cam::Segment& s = segments_[r];
    auto* start = new QTableWidgetItem(number(from));
    start->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    table_->setItem(r, From, start);
    table_->setItem(r, To, new QTableWidgetItem(number(s.toDeg)));
    auto* rise = new QTableWidgetItem(s.law ? number(s.rise) : QString());
    if (!s.law) rise->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    table_->setItem(r, Rise, rise);
    auto* law = new QComboBox;
    law->addItem(tr("dwell"));
    for (cam::Law l : cam::allLaws()) law->addItem(QString::fromLatin1(cam::lawName(l)));
    law->setCurrentIndex(s.law ? static_cast<int>(*s.law) + 1 : 0);
    connect(law, &QComboBox::activated, this, [this, r](int index) {
      const std::optional<cam::Law> l =
          index == 0 ? std::nullopt : std::optional(cam::allLaws()[index - 1]);
      ask(withLaw(segments_, r, l), tr("Cam Segment Law"));
    });
    table_->setCellWidget(r, Law, law);
    from = s.toDeg;
  }
  if (current >= 0 && current < table_->rowCount()) table_->selectRow(current);
  filling_ = false;
}

void CamTable::cellEdited(int row, int column) {
  if (filling_ || row < 0 || row >= static_cast<int>(segments_.size())) return;
  bool ok = false;
  const double v = table_->item(row, column)->text().toDouble(&ok);
  if (!ok || !std::isfinite(v)) {
    Q_EMIT refused(tr("\"%1\" is not a number").arg(table_->item(row, column)->text()));
    QMetaObject::invokeMethod(this, &CamTable::fill, Qt::QueuedConnection);
    return;
  }
  if (column == To) {
    ask(withEnd(segments_, row, v), tr("Cam Segment End"));
    return;
  }
  std::vector<cam::Segment> next = segments_;
  if (!withRise(next, row, v)) {
    Q_EMIT refused(tr("No segment moves the other way to take the difference: add one"));
    QMetaObject::invokeMethod(this, &CamTable::fill, Qt::QueuedConnection);
    return;
  }
  ask(next, tr("Cam Segment Rise"));
}

std::vector<cam::Segment> CamTable::withEnd(std::vector<cam::Segment> s, size_t k, double deg) {
  if (k < s.size()) s[k].toDeg = deg;
  return s;
}

bool CamTable::withRise(std::vector<cam::Segment>& s, size_t k, double rise) {
  if (k >= s.size()) return false;
  const double delta = rise - s[k].rise, way = rise != 0 ? rise : s[k].rise;
  s[k].rise = rise;
  if (delta == 0) return true;
  for (size_t i = 1; i < s.size(); ++i) {
    cam::Segment& o = s[(k + i) % s.size()];
    if (o.law && o.rise * way < 0) {
      o.rise -= delta;
      return true;
    }
  }
  return false;
}

std::vector<cam::Segment> CamTable::withLaw(std::vector<cam::Segment> s, size_t k,
                                            std::optional<cam::Law> law) {
  if (k >= s.size()) return s;
  s[k].law = law;
  // A dwell rises by nothing: its rise goes to the next segment that moves, so the programme
  // stays closed where it can.
  if (!law && s[k].rise != 0) {
    const double rise = s[k].rise;
    s[k].rise = 0;
    for (size_t i = 1; i < s.size(); ++i)
      if (cam::Segment& o = s[(k + i) % s.size()]; o.law) {
        o.rise += rise;
        break;
      }
  }
  return s;
}

std::vector<cam::Segment> CamTable::split(std::vector<cam::Segment> s, size_t k) {
  if (k >= s.size()) return s;
  const double from = k > 0 ? s[k - 1].toDeg : 0;
  cam::Segment first = s[k];
  first.toDeg = (from + s[k].toDeg) / 2;
  first.rise = s[k].rise / 2;
  s[k].rise -= first.rise;
  s.insert(s.begin() + static_cast<std::ptrdiff_t>(k), first);
  return s;
}

std::vector<cam::Segment> CamTable::joined(std::vector<cam::Segment> s, size_t k) {
  if (k >= s.size() || s.size() < 2) return s;
  const size_t keep = k > 0 ? k - 1 : 0, gone = keep + 1;
  s[keep].rise += s[gone].rise;
  s[keep].toDeg = s[gone].toDeg;
  if (!s[keep].law) s[keep].law = s[gone].law;
  if (s[keep].rise == 0 && !s[gone].law) s[keep].law.reset();
  s.erase(s.begin() + static_cast<std::ptrdiff_t>(gone));
  return s;
}

}  // namespace linkage::ui
