#include "cycle/cycle_panel.h"

#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QSaveFile>
#include <QScrollArea>
#include <QSplitter>
#include <QStackedWidget>
#include <QStyledItemDelegate>
#include <QTreeWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "cycle/clearance_selection.h"
#include "cycle/clearance_text.h"
#include "cycle/window_form.h"
#include "document/commands.h"
#include "document/document.h"
#include "document/file_folder.h"
#include "figures/qcp.h"
#include "figures/units.h"
#include "linkage/tables/timing_table.h"
#include "linkage/timing_text.h"
#include "tools/selection.h"

namespace linkage::ui {

namespace {

constexpr int kKindRole = Qt::UserRole, kIndexRole = Qt::UserRole + 1;

QString deg(double d) {
  return QString::number(d, 'f', 2) + QStringLiteral("°");
}

QString intervalText(const AngleInterval& i) {
  return deg(i.fromDeg) + QStringLiteral("–") + deg(i.toDeg);
}

QString mm(double v) {
  return QString::number(v, 'g', 4) + QStringLiteral(" mm");
}

// Whether crank angle c (in [0, 360)) is inside an interval that may run past 360.
bool inside(const AngleInterval& i, double c) {
  return (c >= i.fromDeg && c <= i.toDeg) || (c + 360 >= i.fromDeg && c + 360 <= i.toDeg);
}

}  // namespace

CyclePanel::CyclePanel(Document* doc, QWidget* parent)
    : DockPanel(Redraw::Throttled, Behind::Works, parent), doc_(doc) {
  buildWidgets();
  if (doc) {
    connect(doc, &Document::designChanged, this, [this] {
      markStale();  // the results are of the entries before: none is shown until recomputed
      // A threshold's drag ends: its preview is of the design before.
      preview_.reset();
      levelDrag_ = -1;
      fillList();
      formFollowsDesign();
    });
    connect(doc, &Document::poseChanged, this, &CyclePanel::updateCursor);
    connect(doc, &QObject::destroyed, this, [this] { markStale(); });
  }
  fillList();
  formFollowsDesign();
}

CyclePanel::~CyclePanel() = default;

QWidget* CyclePanel::buildAddRow() {
  auto* row = new QWidget;
  auto* h = new QHBoxLayout(row);
  h->setContentsMargins(0, 0, 0, 0);
  kind_ = new QComboBox;
  for (EntryKind k : kEntryKinds) kind_->addItem(kindName(k), static_cast<int>(k));
  kind_->setToolTip(
      tr("What to add: a row of the diagram, a window (where an output is below "
         "or above a level), a conflict (two windows that must not overlap) or "
         "a clearance between two moving parts"));
  line_ = new QLineEdit;
  auto* add = new QPushButton(tr("&Add"));
  h->addWidget(new QLabel(tr("Add")));
  h->addWidget(kind_);
  h->addWidget(line_, 1);
  h->addWidget(add);
  auto hint = [this] {
    line_->setPlaceholderText(kindHint(static_cast<EntryKind>(kind_->currentData().toInt())));
  };
  hint();
  connect(kind_, &QComboBox::currentIndexChanged, this, hint);
  auto submit = [this] {
    QString why;
    if (addEntry(static_cast<EntryKind>(kind_->currentData().toInt()), line_->text(), &why)) {
      line_->clear();
      setError({});
    } else {
      setError(why);
    }
  };
  connect(line_, &QLineEdit::returnPressed, this, submit);
  connect(add, &QPushButton::clicked, this, submit);
  return row;
}

namespace {

// A column whose rows are as tall as their text wrapped at the column's width (a view's rows
// are one line unless their delegate says otherwise).
class WrappedColumn : public QStyledItemDelegate {
 public:
  explicit WrappedColumn(QTreeWidget* list) : QStyledItemDelegate(list), list_(list) {}
  QSize sizeHint(const QStyleOptionViewItem& o, const QModelIndex& index) const override {
    QStyleOptionViewItem opt = o;
    initStyleOption(&opt, index);
    const int width = std::max(20, list_->columnWidth(index.column()) - 8);
    const QRect text =
        opt.fontMetrics.boundingRect(QRect(0, 0, width, 100000), Qt::TextWordWrap, opt.text);
    return {width, std::max(text.height() + 4, QStyledItemDelegate::sizeHint(o, index).height())};
  }

 private:
  QTreeWidget* list_;
};

}  // namespace

void CyclePanel::buildList() {
  list_ = new QTreeWidget;
  list_->setColumnCount(3);
  list_->setHeaderLabels({tr("Kind"), tr("Entry"), tr("Result")});
  list_->setRootIsDecorated(false);
  list_->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
  list_->setContextMenuPolicy(Qt::CustomContextMenu);
  // The result is what is read: the entry's column is held to part of the list, the result
  // takes the rest and wraps to be read whole (it was cut off at the list's edge).
  list_->header()->setStretchLastSection(true);
  list_->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
  list_->setWordWrap(true);
  list_->setTextElideMode(Qt::ElideMiddle);
  list_->setItemDelegateForColumn(2, new WrappedColumn(list_));
  // The rows' heights follow the result's column as it narrows or widens (the view lays its
  // rows out only when asked).
  connect(list_->header(), &QHeaderView::sectionResized, list_, [this] {
    QMetaObject::invokeMethod(list_, &QTreeWidget::doItemsLayout, Qt::QueuedConnection);
  });
  list_->setMinimumWidth(200);
  connect(list_, &QTreeWidget::itemChanged, this, [this](QTreeWidgetItem* i) { itemEdited(i); });
  connect(list_, &QWidget::customContextMenuRequested, this, [this](const QPoint& at) {
    QTreeWidgetItem* item = list_->itemAt(at);
    if (!item) return;
    QMenu menu;
    menu.addAction(tr("Edit"), [this, item] { list_->editItem(item, 1); });
    menu.addAction(tr("Remove"), [this, item] {
      removeEntry(static_cast<EntryKind>(item->data(0, kKindRole).toInt()),
                  item->data(0, kIndexRole).toInt());
    });
    menu.exec(list_->viewport()->mapToGlobal(at));
  });
  // Delete in the list removes its entry (a key, not an action: the window's Delete is Edit >
  // Delete, and each shortcut is one action's).
  list_->installEventFilter(this);
}

void CyclePanel::buildWidgets() {
  auto* top = new QVBoxLayout(this);
  top->setContentsMargins(4, 4, 4, 4);
  top->setSpacing(3);
  top->addWidget(buildAddRow());
  form_ = new WindowForm;
  top->addWidget(form_);
  error_ = new QLabel;
  error_->setWordWrap(true);
  error_->setStyleSheet("color: #962020");
  error_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
  error_->hide();  // shown with a sentence only: the diagram keeps the height meanwhile
  top->addWidget(error_);
  auto* split = new QSplitter(Qt::Horizontal);
  buildList();
  stack_ = new QStackedWidget;
  plot_ = new QCustomPlot;
  plot_->setMinimumSize(240, 120);
  plot_->setCursor(Qt::CrossCursor);
  plot_->setInteractions({});     // a drag turns the crank, not the axes
  plot_->setMouseTracking(true);  // the cursor says where a threshold can be grabbed
  figure_ = std::make_unique<CycleFigure>(plot_);
  levels_ = std::make_unique<LevelLines>(plot_, *figure_);
  sentence_ = new QLabel;
  sentence_->setWordWrap(true);
  sentence_->setAlignment(Qt::AlignCenter);
  sentence_->setMargin(16);
  // A dock too low for the rows scrolls rather than print their labels over each other.
  scroll_ = new QScrollArea;
  scroll_->setWidget(plot_);
  scroll_->setWidgetResizable(true);
  scroll_->setFrameShape(QFrame::NoFrame);
  scroll_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  stack_->addWidget(scroll_);
  stack_->addWidget(sentence_);
  split->addWidget(list_);
  split->addWidget(stack_);
  split->setStretchFactor(1, 2);
  split->setSizes({380, 760});
  top->addWidget(split, 1);
  values_ = new QLabel;
  values_->setWordWrap(true);
  values_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
  values_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  top->addWidget(values_);
  connect(plot_, &QCustomPlot::mousePress, this, [this](QMouseEvent* e) { mouseOnPlot(e, true); });
  connect(plot_, &QCustomPlot::mouseMove, this, [this](QMouseEvent* e) { mouseOnPlot(e, false); });
  connect(plot_, &QCustomPlot::mouseRelease, this, [this](QMouseEvent*) {
    figure_->endDrag();
    if (levelDrag_ >= 0) endLevelDrag();
  });
  connectForm();
}

bool CyclePanel::eventFilter(QObject* watched, QEvent* e) {
  if (watched == list_ && e->type() == QEvent::KeyPress &&
      static_cast<QKeyEvent*>(e)->key() == Qt::Key_Delete && list_->currentItem()) {
    const QTreeWidgetItem* i = list_->currentItem();
    removeEntry(static_cast<EntryKind>(i->data(0, kKindRole).toInt()),
                i->data(0, kIndexRole).toInt());
    return true;
  }
  if (watched == list_ && e->type() == QEvent::Resize) fitEntryColumn();
  return QWidget::eventFilter(watched, e);
}

// --- the entries ----------------------------------------------------------------------------

void CyclePanel::fillList() {
  filling_ = true;
  list_->clear();
  if (doc_) {
    const Mechanism& m = doc_->design();
    for (EntryKind k : kEntryKinds)
      for (int i = 0; i < entryCount(m.timing, k); ++i) {
        auto* item = new QTreeWidgetItem(list_, {kindName(k), entryText(m, k, i), QString()});
        item->setToolTip(1, item->text(1));  // whole where its column elides it
        item->setData(0, kKindRole, static_cast<int>(k));
        item->setData(0, kIndexRole, i);
        item->setFlags(item->flags() | Qt::ItemIsEditable);
        if (k == EntryKind::Clearance)
          item->setToolTip(1, clearanceDescription(m, m.timing.clearances[i]));
      }
  }
  fitEntryColumn();
  filling_ = false;
  showResults();
}

void CyclePanel::fitEntryColumn() {
  // The entry as wide as its longest, but no more than half of what the kind leaves: the
  // result's column, which wraps, keeps the rest (it was cut off at the list's edge).
  list_->resizeColumnToContents(0);
  list_->resizeColumnToContents(1);
  const int half = std::max(80, (list_->viewport()->width() - list_->columnWidth(0)) / 2);
  if (list_->columnWidth(1) > half) list_->setColumnWidth(1, half);
}

void CyclePanel::itemEdited(QTreeWidgetItem* item) {
  if (filling_ || !doc_) return;
  const auto kind = static_cast<EntryKind>(item->data(0, kKindRole).toInt());
  const int index = item->data(0, kIndexRole).toInt();
  QString why;
  const QString text = item->text(1);
  if (text == entryText(doc_->design(), kind, index)) return;
  if (!editEntry(kind, index, text, &why)) {
    setError(why);
    // Back to what the document holds: the typed text stays in the error's sentence.
    filling_ = true;
    item->setText(1, entryText(doc_->design(), kind, index));
    filling_ = false;
  }
}

bool CyclePanel::change(const QString& title, const std::function<bool(Mechanism&, QString*)>& edit,
                        QString* why) {
  if (!doc_) return false;
  Mechanism next = doc_->design();
  QString bad;
  if (!edit(next, &bad)) {
    if (why) *why = bad;
    return false;
  }
  setError({});
  editDesign(doc_, title, std::move(next));
  return true;
}

bool CyclePanel::addEntry(EntryKind kind, const QString& text, QString* why) {
  return change(
      tr("Add %1").arg(kindName(kind).toLower()),
      [&](Mechanism& m, QString* bad) { return setEntry(m, kind, -1, text, bad); }, why);
}

bool CyclePanel::editEntry(EntryKind kind, int index, const QString& text, QString* why) {
  if (!doc_ || index < 0 || index >= entryCount(doc_->design().timing, kind)) return false;
  return change(
      tr("Edit %1").arg(entryTitle(doc_->design(), kind, index)),
      [&](Mechanism& m, QString* bad) { return setEntry(m, kind, index, text, bad); }, why);
}

void CyclePanel::removeEntry(EntryKind kind, int index) {
  if (!doc_ || index < 0 || index >= entryCount(doc_->design().timing, kind)) return;
  change(
      tr("Remove %1").arg(entryTitle(doc_->design(), kind, index)),
      [&](Mechanism& m, QString*) {
        linkage::ui::removeEntry(m, kind, index);
        return true;
      },
      nullptr);
}

bool CyclePanel::watchSelection(const Selection& s, QString* why) {
  if (!doc_) return false;
  const QString text = clearanceOfSelection(doc_->design(), s);
  if (text.isEmpty()) {
    if (why)
      *why =
          tr("Select two points, a point and a slot of another body, or a point and two "
             "points of one other body (the segment between them: a needle, a blade); "
             "Shift+click adds to the selection. Then watch their clearance.");
    return false;
  }
  return addEntry(EntryKind::Clearance, text, why);
}

void CyclePanel::setError(const QString& why) {
  error_->setText(why);
  error_->setVisible(!why.isEmpty());
}

QString CyclePanel::entryError() const {
  return error_->text();
}

// --- work -----------------------------------------------------------------------------------

void CyclePanel::cameIntoView() {
  updateCursor();
  emitMarks();
}

void CyclePanel::leftView() {
  // The canvas shows what this dock watches only while the dock is seen.
  Q_EMIT marksChanged({});
}

QString CyclePanel::whyNoDiagram() const {
  if (!doc_) return tr("No document.");
  if (!doc_->solved())
    return tr("The design is not solved (%1): no cycle is shown.")
        .arg(QString::fromStdString(doc_->solveStatus().message));
  if (Status s = doc_->motionStatus(); !s.ok())
    return tr("No cycle: %1; a cycle is that of a motion the driver determines.")
        .arg(QString::fromStdString(s.message));
  if (!doc_->design().driver) return tr("No cycle: the mechanism has no driver to turn.");
  const Timing& t = doc_->design().timing;
  if (t.outputs.empty() && t.windows.empty() && t.clearances.empty())
    return tr(
        "The machine's cycle diagram: add a row (needlebar.N:y), a window "
        "(needle=needlebar.N:y<-150), a conflict between two windows, or the clearance "
        "between two moving parts (select two points on the canvas, or a point and two "
        "points of another body for the segment between them, then Analysis > Watch "
        "Clearance).");
  return {};
}

void CyclePanel::compute() {
  diagram_ = CycleDiagram{};
  windows_.clear();
  clearances_.clear();
  clearanceWhy_.clear();
  why_ = whyNoDiagram();
  if (why_.isEmpty()) {
    const Kinematics& k = doc_->kinematics();  // the document's pose and branch; not moved
    const Mechanism& m = k.mechanism();
    const Timing& t = preview_ ? *preview_ : m.timing;
    for (const TimingWindow& w : t.windows)
      windows_.push_back({w.name, {measureText(m, w.output), w.output}, w.below, w.level});
    diagram_ = cycleDiagram(k, t);
    ++computations_;
    if (!diagram_.status.ok())
      why_ = tr("No cycle: %1.").arg(QString::fromStdString(diagram_.status.message));
    else
      computeClearances(k);
  }
  rebuildFigure();
  showResults();
  emitMarks();
}

void CyclePanel::computeClearances(const Kinematics& k) {
  const Mechanism& m = k.mechanism();
  for (const ClearanceWatch& w : m.timing.clearances) {
    Clearance c = findClearance(k, ClearancePart::of(w.point), w.other);
    if (!c.status.ok()) {
      clearanceWhy_.push_back(QString::fromStdString(c.status.message));
      continue;
    }
    clearanceWhy_.push_back({});
    clearances_.push_back({clearanceLabel(m, w), std::move(c), w.minMm, w});
  }
}

const CycleClearanceRow* CyclePanel::clearanceRow(int i) const {
  if (i < 0 || i >= static_cast<int>(clearanceWhy_.size()) || !clearanceWhy_[i].isEmpty())
    return nullptr;
  // Those measured are in clearances_, in the entries' order.
  return &clearances_[std::count(clearanceWhy_.begin(), clearanceWhy_.begin() + i, QString())];
}

const CycleDiagram* CyclePanel::diagram() const {
  return why_.isEmpty() ? &diagram_ : nullptr;
}

void CyclePanel::rebuildFigure() {
  if (!diagram()) {
    figure_->clear();
    plot_->replot();
    sentence_->setText(why_);
    stack_->setCurrentWidget(sentence_);
    values_->clear();
    return;
  }
  stack_->setCurrentWidget(scroll_);
  figure_->build(diagram_, windows_, clearances_, QString(), crankAxisLabel(doc_->design()));
  plot_->setMinimumHeight(CycleFigure::leastHeightFor(figure_->rowCount()));
  levels_->draw(diagram_, windows_, form_->target());
  plot_->replot(QCustomPlot::rpQueuedReplot);
  updateCursor();
}

QString CyclePanel::resultText(EntryKind kind, int i) const {
  if (stale() || !diagram() || !doc_ || i < 0 || i >= entryCount(doc_->design().timing, kind))
    return {};
  const Mechanism& m = doc_->design();
  switch (kind) {
    case EntryKind::Row: {
      const std::string name = measureText(m, m.timing.outputs[i]);
      for (const CycleRow& r : diagram_.rows)
        if (r.output.name == name) {
          QStringList dead;
          for (const LocalExtreme& e : r.extremes) dead << deg(e.crankDeg);
          const QString unit = r.output.measure.body ? QStringLiteral("°") : QStringLiteral(" mm");
          return tr("stroke %1%2; dead centres %3")
              .arg(QString::number(r.max - r.min, 'g', 5), unit,
                   dead.isEmpty() ? tr("none") : dead.join(", "));
        }
      return {};
    }
    case EntryKind::Window: {
      const std::vector<AngleInterval>& v = diagram_.windows[i].intervals;
      if (v.empty()) return tr("never");
      if (v.size() == 1 && v[0].fromDeg == 0 && v[0].toDeg == 360) return tr("always");
      QStringList parts;
      for (const AngleInterval& x : v) parts << intervalText(x);
      return parts.join("; ");
    }
    case EntryKind::Conflict: {
      const std::vector<AngleInterval>& v = diagram_.conflicts[i].overlaps;
      if (v.empty()) return tr("no overlap");
      QStringList parts;
      for (const AngleInterval& x : v) parts << intervalText(x);
      return tr("overlap %1").arg(parts.join("; "));
    }
    case EntryKind::Clearance: {
      if (i >= static_cast<int>(clearanceWhy_.size())) return {};
      if (!clearanceWhy_[i].isEmpty()) return clearanceWhy_[i];
      const CycleClearanceRow& c = *clearanceRow(i);
      const ClearanceWatch& w = m.timing.clearances[i];
      // What it measured to, then what it found: a 0 says that they meet or how.
      QString t = partName(m, w.other) + QStringLiteral(": ") + clearanceFigures(m, w, c.clearance);
      if (c.minMm && c.clearance.closest.distance < *c.minMm)
        t += tr(": under the minimum, %1").arg(mm(*c.minMm));
      return t;
    }
  }
  return {};
}

// Each entry's result in its row, red where something is wrong (an overlap, too close, an
// entry that cannot be measured).
void CyclePanel::showResults() {
  filling_ = true;
  for (int r = 0; r < list_->topLevelItemCount(); ++r) {
    QTreeWidgetItem* item = list_->topLevelItem(r);
    const auto kind = static_cast<EntryKind>(item->data(0, kKindRole).toInt());
    const int i = item->data(0, kIndexRole).toInt();
    const QString text = resultText(kind, i);
    bool bad = false;
    if (!stale() && diagram() && kind == EntryKind::Conflict)
      bad = !diagram_.conflicts[i].overlaps.empty();
    if (!stale() && diagram() && kind == EntryKind::Clearance)
      bad = text.contains(tr("under the minimum")) ||
            (i < static_cast<int>(clearanceWhy_.size()) && !clearanceWhy_[i].isEmpty());
    item->setText(2, text);
    item->setToolTip(2, text);
    // A clearance's tooltip: every crossing of the part's line, where along it.
    if (kind == EntryKind::Clearance && !text.isEmpty() && doc_)
      if (const CycleClearanceRow* c = clearanceRow(i))
        if (const QString x = clearanceCrossings(doc_->design(),
                                                 doc_->design().timing.clearances[i], c->clearance);
            !x.isEmpty())
          item->setToolTip(2, text + QLatin1Char('\n') + x);
    item->setForeground(2, bad ? QBrush(QColor(150, 32, 32)) : palette().text());
    // A threshold being dragged: the window's text follows it with its ends.
    if (preview_ && doc_ && kind == EntryKind::Window &&
        i < static_cast<int>(preview_->windows.size()))
      item->setText(1, QString::fromStdString(windowText(doc_->design(), preview_->windows[i])));
  }
  filling_ = false;
  if (form_->target() >= 0) form_->setResult(resultText(EntryKind::Window, form_->target()));
}

void CyclePanel::emitMarks() {
  if (!shown() || !doc_) return;
  std::vector<ClearanceMark> marks;
  if (diagram())
    for (const CycleClearanceRow& c : clearances_) {
      const Clearance& k = c.clearance;
      const bool close = c.minMm && k.closest.distance < *c.minMm;
      // Brief on the canvas: the part drawn there shows where along it they meet.
      const Mechanism& m = doc_->kinematics().mechanism();
      const ClearancePart& other = c.watch.other;
      const Point* a = m.point(c.watch.point);
      const Point* b = m.point(other.point);
      const Slot* slot = m.slot(other.slot);
      marks.push_back({k.closestPoint, k.closestOther,
                       c.label + QStringLiteral(": ") + clearanceNote(k, 2), close, k.closestPart,
                       a ? a->body : BodyId{},
                       b      ? b->body
                       : slot ? slot->body
                              : BodyId{}});
    }
  Q_EMIT marksChanged(marks);
}

// --- the cursor -----------------------------------------------------------------------------

void CyclePanel::updateCursor() {
  if (!shown() || !doc_ || !diagram()) return;
  const double at = crankInPeriod(doc_->crankDeg(), 360);
  figure_->setCursor(at);
  QStringList parts;
  for (const WindowIntervals& w : diagram_.windows) {
    const bool holds = std::any_of(w.intervals.begin(), w.intervals.end(),
                                   [&](const AngleInterval& i) { return inside(i, at); });
    parts << (holds ? tr("%1 holds") : tr("%1 does not")).arg(QString::fromStdString(w.name));
  }
  const Kinematics& k = doc_->kinematics();
  for (const ClearanceWatch& w : doc_->design().timing.clearances) {
    const double d = clearanceAt(k, ClearancePart::of(w.point), w.other);
    if (std::isfinite(d)) parts << tr("%1 %2").arg(clearanceLabel(k.mechanism(), w), mm(d));
  }
  values_->setText(tr("At %1: %2").arg(deg(at), parts.join(", ")));
}

QString CyclePanel::cursorText() const {
  return values_->text();
}

void CyclePanel::mouseOnPlot(QMouseEvent* e, bool press) {
  if (!diagram()) return;
  if (!(e->buttons() & Qt::LeftButton)) {  // hovering: a threshold can be grabbed here
    plot_->setCursor(levels_->windowAt(e->position()) >= 0 ? Qt::SizeVerCursor : Qt::CrossCursor);
    return;
  }
  if (press && !figure_->dragging() && levelDrag_ < 0)
    if (const int w = levels_->windowAt(e->position()); w >= 0) beginLevelDrag(w);
  if (levelDrag_ >= 0) {
    if (!press) dragLevel(e->position().y());
    return;
  }
  const double d = figure_->crankDragged(e->position(), press);
  if (std::isnan(d)) return;
  Q_EMIT crankAngleRequested(
      crankNear(std::clamp(d, 0.0, 360.0), doc_ ? doc_->crankDeg() : 0.0, 360));
}

// --- export ---------------------------------------------------------------------------------

bool CyclePanel::exportFigure(const QString& path, QSize size, QString* error) {
  ensureComputed();
  if (!diagram()) {
    if (error) *error = why_;
    return false;
  }
  const QString name = QString::fromStdString(doc_->design().name);
  figure_->build(diagram_, windows_, clearances_,
                 (name.isEmpty() ? QString() : name + ": ") + tr("cycle diagram"),
                 crankAxisLabel(doc_->design()));
  const bool ok = figure_->exportFigure(path, size, error);
  rebuildFigure();
  return ok;
}

bool CyclePanel::exportTable(const QString& path, QString* error) {
  ensureComputed();
  if (!diagram()) {
    if (error) *error = why_;
    return false;
  }
  QSaveFile f(path);
  const std::string text = timingTable(diagram_);
  if (!f.open(QIODevice::WriteOnly) || f.write(text.data(), qint64(text.size())) < 0 ||
      !f.commit()) {
    if (error) *error = tr("%1: %2").arg(path, f.errorString());
    return false;
  }
  return true;
}

void CyclePanel::saveFigureAs() {
  const QString path = QFileDialog::getSaveFileName(
      this, tr("Export Cycle Diagram"), suggestedFile(doc_, QStringLiteral("-cycle.svg")),
      tr("SVG (*.svg);;PDF (*.pdf);;PNG (*.png)"));
  if (path.isEmpty()) return;
  QString why;
  const int rows = figure_->rowCount();
  if (!exportFigure(path, QSize(1200, CycleFigure::heightFor(rows) + 40), &why))
    QMessageBox::warning(this, tr("Export Cycle Diagram"), why);
}

void CyclePanel::saveTableAs() {
  const QString path = QFileDialog::getSaveFileName(
      this, tr("Export Timing Table"), suggestedFile(doc_, QStringLiteral("-cycle.csv")),
      tr("CSV tables (*.csv)"));
  if (path.isEmpty()) return;
  QString why;
  if (!exportTable(path, &why)) QMessageBox::warning(this, tr("Export Timing Table"), why);
}

QStringList CyclePanel::probeLines() const {
  QStringList out;
  out << QStringLiteral("cycle: ") + (diagram() ? QStringLiteral("%1 rows").arg(figure_->rowCount())
                                                : QString(why_).replace('\n', ' '));
  for (int r = 0; r < list_->topLevelItemCount(); ++r) {
    const QTreeWidgetItem* item = list_->topLevelItem(r);
    out << QStringLiteral("cycle entry %1 %2: %3 => %4")
               .arg(item->text(0))
               .arg(item->data(0, kIndexRole).toInt())
               .arg(item->text(1), item->text(2));
  }
  out << QStringLiteral("cycle values: ") + values_->text();
  auto at = [&](const char* name, const QWidget* w) {
    const QPoint c = w->mapToGlobal(w->rect().center());
    out << QStringLiteral("at cycle %1: %2 %3").arg(QLatin1String(name)).arg(c.x()).arg(c.y());
  };
  out << QStringLiteral("cycle kind: ") + kind_->currentText();
  at("kind", kind_);
  at("line", line_);
  out << form_->probeLines();
  // Each window's threshold line, at crank 345 (clear of the names at the middle of windows).
  if (diagram() && doc_)
    for (size_t w = 0; w < windows_.size(); ++w)
      if (const std::optional<QPointF> p = levelPixel(static_cast<int>(w), 345)) {
        const QPoint c = plot_->mapToGlobal(p->toPoint());
        out << QStringLiteral("at cycle threshold %1: %2 %3")
                   .arg(QString::fromStdString(windows_[w].name))
                   .arg(c.x())
                   .arg(c.y());
      }
  if (diagram() && figure_->rowCount() > 0)
    for (int deg : {90, 250}) {
      const QPoint c = plot_->mapToGlobal(figure_->pixelAt(deg, 0.5, 0).toPoint());
      out << QStringLiteral("at cycle %1: %2 %3").arg(deg).arg(c.x()).arg(c.y());
    }
  return out;
}

}  // namespace linkage::ui
