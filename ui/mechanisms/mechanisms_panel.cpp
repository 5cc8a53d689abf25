#include "mechanisms/mechanisms_panel.h"

#include <QAction>
#include <QColorDialog>
#include <QHeaderView>
#include <QPainter>
#include <QStyleOptionViewItem>
#include <QToolBar>
#include <QTreeWidget>
#include <QVBoxLayout>

#include "document/commands.h"
#include "document/document.h"
#include "linkage/mechanisms.h"
#include "tools/selection.h"

namespace linkage::ui {

namespace {

enum Column { NameColumn, ColourColumn, BodiesColumn };

QIcon swatch(const QColor& c) {
  QPixmap pm(16, 16);
  pm.fill(Qt::transparent);
  QPainter p(&pm);
  p.setPen(QColor(120, 120, 120));
  if (c.isValid()) {
    p.setBrush(c);
    p.drawRect(1, 1, 13, 13);
  } else {
    // No colour of its own: each body its own (a diagonal, as "none" is drawn).
    p.setBrush(Qt::NoBrush);
    p.drawRect(1, 1, 13, 13);
    p.drawLine(2, 13, 13, 2);
  }
  return QIcon(pm);
}

}  // namespace

MechanismsPanel::MechanismsPanel(QWidget* parent) : QWidget(parent) {
  list_ = new QTreeWidget;
  list_->setObjectName("mechanismList");
  list_->setColumnCount(3);
  list_->setHeaderLabels({tr("Mechanism"), tr("Colour"), tr("Bodies")});
  list_->setRootIsDecorated(false);
  list_->setSelectionMode(QAbstractItemView::SingleSelection);
  list_->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
  list_->header()->setSectionResizeMode(NameColumn, QHeaderView::ResizeToContents);
  list_->header()->setSectionResizeMode(ColourColumn, QHeaderView::ResizeToContents);
  list_->setContextMenuPolicy(Qt::ActionsContextMenu);
  colour_ = new QAction(tr("&Colour..."), this);
  colour_->setObjectName("mechanismColour");
  colour_->setStatusTip(tr("Draw the selected mechanism's links in a colour of your choice"));
  noColour_ = new QAction(tr("&Own Colours"), this);
  noColour_->setObjectName("mechanismOwnColours");
  noColour_->setStatusTip(tr("Draw the selected mechanism's links each in its own colour again"));
  list_->addAction(colour_);
  list_->addAction(noColour_);
  auto* bar = new QToolBar;
  bar->setIconSize(QSize(16, 16));
  bar->addAction(colour_);
  bar->addAction(noColour_);
  // Wide enough for a name, its swatch and the start of its bodies beside the canvas.
  setMinimumWidth(220);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(list_);
  layout->addWidget(bar);
  connect(colour_, &QAction::triggered, this, &MechanismsPanel::chooseColour);
  connect(noColour_, &QAction::triggered, this,
          [this] { setColour(list_->indexOfTopLevelItem(list_->currentItem()), QColor()); });
  connect(list_, &QTreeWidget::itemChanged, this, &MechanismsPanel::itemChanged);
  connect(list_, &QTreeWidget::itemSelectionChanged, this, &MechanismsPanel::selectBodies);
  // The swatch is a button: a click on it asks for the colour.
  connect(list_, &QTreeWidget::itemClicked, this, [this](QTreeWidgetItem*, int column) {
    if (column == ColourColumn) chooseColour();
  });
}

void MechanismsPanel::setDocument(Document* doc, Selection* selection) {
  if (doc_) disconnect(doc_, nullptr, this, nullptr);
  doc_ = doc;
  selection_ = selection;
  if (doc_) connect(doc_, &Document::designChanged, this, &MechanismsPanel::refill);
  refill();
}

void MechanismsPanel::refill() {
  // The row that was current stays current (an edit of it refills the list).
  const int row = list_->indexOfTopLevelItem(list_->currentItem());
  filling_ = true;
  list_->clear();
  if (doc_) {
    const Mechanism& m = doc_->design();
    for (const SubMechanism& s : subMechanisms(m)) {
      auto* item = new QTreeWidgetItem(list_);
      item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsEditable |
                     Qt::ItemIsUserCheckable);
      item->setText(NameColumn, QString::fromStdString(s.name));
      item->setCheckState(NameColumn, s.hidden ? Qt::Unchecked : Qt::Checked);
      item->setToolTip(NameColumn, s.shaft ? tr("A shaft that drives several mechanisms, or none")
                                           : tr("Bodies that move together"));
      const QColor c = s.colour.empty() ? QColor() : QColor(QString::fromStdString(s.colour));
      item->setIcon(ColourColumn, swatch(c));
      item->setToolTip(ColourColumn, c.isValid() ? c.name() : tr("each body its own colour"));
      QStringList bodies;
      for (BodyId id : s.bodies) bodies << QString::fromStdString(m.body(id)->name);
      item->setText(BodiesColumn, bodies.join(QStringLiteral(", ")));
    }
  }
  if (row >= 0 && row < list_->topLevelItemCount()) {
    const QSignalBlocker block(list_);
    list_->setCurrentItem(list_->topLevelItem(row));
  }
  filling_ = false;
}

void MechanismsPanel::itemChanged(QTreeWidgetItem* item, int column) {
  if (filling_ || column != NameColumn || !doc_) return;
  const int row = list_->indexOfTopLevelItem(item);
  const std::vector<SubMechanism> all = subMechanisms(doc_->design());
  if (row < 0 || row >= int(all.size())) return;
  const bool hidden = item->checkState(NameColumn) != Qt::Checked;
  // Queued: the edit refills the list, which must not happen inside the list's own signal.
  if (hidden != all[row].hidden)
    QMetaObject::invokeMethod(
        this, [this, row, hidden] { setHidden(row, hidden); }, Qt::QueuedConnection);
  else if (item->text(NameColumn).toStdString() != all[row].name)
    QMetaObject::invokeMethod(
        this, [this, row, name = item->text(NameColumn)] { rename(row, name); },
        Qt::QueuedConnection);
}

void MechanismsPanel::selectBodies() {
  if (filling_ || !doc_ || !selection_) return;
  const int row = list_->indexOfTopLevelItem(list_->currentItem());
  const std::vector<SubMechanism> all = subMechanisms(doc_->design());
  if (row < 0 || row >= int(all.size())) return;
  // One change for the canvas and the panels, not one per body.
  {
    const QSignalBlocker block(selection_);
    selection_->clear();
    for (BodyId b : all[row].bodies) selection_->add(b);
  }
  emit selection_->changed();
}

std::vector<SubMechanism> MechanismsPanel::current() const {
  return doc_ ? subMechanisms(doc_->design()) : std::vector<SubMechanism>{};
}

bool MechanismsPanel::edit(int row, const QString& text, const QString& name, const QString& colour,
                           bool hidden) {
  if (!doc_) return false;
  Mechanism next = doc_->design();
  const std::vector<SubMechanism> all = subMechanisms(next);
  if (row < 0 || row >= int(all.size())) return false;
  const SubMechanism& s = all[row];
  if (name.toStdString() == s.name && colour.toStdString() == s.colour && hidden == s.hidden)
    return false;
  setSubMechanismLook(next, s, name.toStdString(), colour.toStdString(), hidden);
  commitEdit(doc_, text.arg(QString::fromStdString(s.name)), std::move(next));
  return true;
}

bool MechanismsPanel::rename(int row, const QString& name) {
  const QString n = name.trimmed();
  const std::vector<SubMechanism> all = current();
  if (n.isEmpty() || row < 0 || row >= int(all.size())) {
    refill();  // an empty name is not taken: the old one comes back
    return false;
  }
  const SubMechanism& s = all[row];
  return edit(row, tr("Rename mechanism %1"), n, QString::fromStdString(s.colour), s.hidden);
}

bool MechanismsPanel::setColour(int row, const QColor& colour) {
  const std::vector<SubMechanism> all = current();
  if (row < 0 || row >= int(all.size())) return false;
  const SubMechanism& s = all[row];
  return edit(row, tr("Colour mechanism %1"), QString::fromStdString(s.name),
              colour.isValid() ? colour.name() : QString(), s.hidden);
}

bool MechanismsPanel::setHidden(int row, bool hidden) {
  const std::vector<SubMechanism> all = current();
  if (row < 0 || row >= int(all.size())) return false;
  const SubMechanism& s = all[row];
  return edit(row, hidden ? tr("Hide mechanism %1") : tr("Show mechanism %1"),
              QString::fromStdString(s.name), QString::fromStdString(s.colour), hidden);
}

QStringList MechanismsPanel::probeLines() const {
  QStringList out;
  for (int i = 0; i < list_->topLevelItemCount(); ++i) {
    QTreeWidgetItem* item = list_->topLevelItem(i);
    const QRect r = list_->visualItemRect(item);
    const QPoint c = list_->viewport()->mapToGlobal(
        QPoint(r.left() + list_->columnWidth(NameColumn) / 2, r.center().y()));
    // The check box: the style's indicator at the left of the name cell.
    QStyleOptionViewItem opt;
    opt.initFrom(list_);
    opt.rect = r;
    opt.features = QStyleOptionViewItem::HasCheckIndicator | QStyleOptionViewItem::HasDisplay;
    const QPoint box = list_->viewport()->mapToGlobal(
        list_->style()
            ->subElementRect(QStyle::SE_ItemViewItemCheckIndicator, &opt, list_)
            .center());
    out << QStringLiteral("mechanism %1: %2 %3 %4 check %5 %6")
               .arg(item->text(NameColumn))
               .arg(item->checkState(NameColumn) == Qt::Checked ? "shown" : "hidden")
               .arg(c.x())
               .arg(c.y())
               .arg(box.x())
               .arg(box.y());
  }
  return out;
}

void MechanismsPanel::chooseColour() {
  const int row = list_->indexOfTopLevelItem(list_->currentItem());
  const std::vector<SubMechanism> all = current();
  if (row < 0 || row >= int(all.size())) return;
  const QColor old =
      all[row].colour.empty() ? QColor(Qt::gray) : QColor(QString::fromStdString(all[row].colour));
  const QColor c = QColorDialog::getColor(
      old, this, tr("Colour of %1").arg(QString::fromStdString(all[row].name)));
  if (c.isValid()) setColour(row, c);
}

}  // namespace linkage::ui
