#include "properties/properties_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>
#include <cmath>

#include "document/commands.h"
#include "document/document.h"
#include "document/shown_numbers.h"
#include "linkage/edits.h"
#include "linkage/io/numbers.h"
#include "properties/forms.h"
#include "properties/number_keys.h"
#include "tools/selection.h"

namespace linkage::ui {

namespace {

void markBad(QWidget* w, bool bad) {
  w->setStyleSheet(bad ? QStringLiteral("background: rgba(220, 40, 30, 60);") : QString());
}

// Ctrl+Z in a field that shows the document's value (committed, or not typed in since) undoes
// the document's last edit, as anywhere else in the window: the field's own undo would take
// back only its text, which leaving the field then committed again as a new edit. While a value
// is being typed, the field undoes its typing first.
class FieldUndo : public QObject {
 public:
  using QObject::QObject;
  bool eventFilter(QObject* watched, QEvent* e) override {
    auto* field = qobject_cast<QLineEdit*>(watched);
    if (!field || e->type() != QEvent::ShortcutOverride) return QObject::eventFilter(watched, e);
    auto* k = static_cast<QKeyEvent*>(e);
    const bool undo = k->matches(QKeySequence::Undo);
    const bool redo = k->matches(QKeySequence::Redo);
    if (!undo && !redo) return QObject::eventFilter(watched, e);
    const bool typing =
        field->isModified() && (undo ? field->isUndoAvailable() : field->isRedoAvailable());
    if (typing) return QObject::eventFilter(watched, e);
    e->ignore();  // the window's Undo or Redo acts
    return true;
  }
};

}  // namespace

PropertiesPanel::PropertiesPanel(QWidget* parent) : QWidget(parent) {
  title_ = new QLabel;
  title_->setTextFormat(Qt::RichText);
  title_->setWordWrap(true);  // a long name on lines, not the panel stretched
  form_ = new QFormLayout;
  form_->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
  auto* l = new QVBoxLayout(this);
  l->setContentsMargins(4, 4, 4, 4);
  l->addWidget(title_);
  l->addLayout(form_);
}

void PropertiesPanel::setDocument(Document* doc, Selection* selection) {
  if (doc_) disconnect(doc_, nullptr, this, nullptr);
  if (selection_) disconnect(selection_, nullptr, this, nullptr);
  doc_ = doc;
  selection_ = selection;
  shape_.clear();  // the rows read the document they were made for
  if (doc_) connect(doc_, &Document::designChanged, this, &PropertiesPanel::rebuild);
  if (selection_) connect(selection_, &Selection::changed, this, &PropertiesPanel::rebuild);
  rebuild();
}

QWidget* PropertiesPanel::field(const QString& label) const {
  for (const Row& r : rows_)
    if (r.label == label) return r.editor;
  return nullptr;
}

QString PropertiesPanel::labelOf(const QWidget* editor) const {
  for (const Row& r : rows_)
    if (r.editor == editor) return r.label;
  return QString();
}

QString PropertiesPanel::title() const {
  return title_->text();
}

void PropertiesPanel::clearRows() {
  // The rows' widgets go at the event loop's next turn, not now: the edit that rebuilds the form
  // may come from a row's own signal (a choice that changes the form's shape), and Qt reads its
  // sender again after the slot returns (QComboBox emits textActivated after activated). Until
  // then they say nothing: hiding one moves the focus, and a field left would commit to what
  // its row read (a load removed).
  while (form_->rowCount() > 0) {
    const QFormLayout::TakeRowResult row = form_->takeRow(0);
    for (QLayoutItem* item : {row.labelItem, row.fieldItem}) {
      if (!item) continue;
      if (QWidget* w = item->widget()) {
        w->blockSignals(true);
        w->hide();
        w->deleteLater();
      }
      delete item;
    }
  }
  rows_.clear();
}

void PropertiesPanel::refresh() {
  for (const Row& r : rows_) r.refresh();
}

void PropertiesPanel::addSection(const FormSection& section) {
  sections_.push_back(section);
  shape_.clear();
  rebuild();
}

FormTarget PropertiesPanel::target() const {
  FormTarget t;
  if (selection_->size() != 1) return t;
  if (!selection_->bodies.empty()) t.body = selection_->bodies[0];
  if (!selection_->points.empty()) t.point = selection_->points[0];
  if (!selection_->joints.empty()) t.joint = selection_->joints[0];
  if (!selection_->slots_.empty()) t.slot = selection_->slots_[0];
  return t;
}

void PropertiesPanel::rebuild() {
  if (!doc_ || !selection_) return;
  const Mechanism& m = doc_->design();
  // One thing selected is edited; several or none: the mechanism. The rows are made for a
  // shape, the form's and its sections', and only refreshed while it stays (forms.h).
  const FormTarget t = target();
  const FormDescriptor* form = nullptr;
  for (const FormDescriptor* d : formDescriptors())
    if (d->takes(m, t)) {
      form = d;
      break;
    }
  if (!form) return;
  auto joins = [form](const FormSection& s) { return qstrcmp(s.form, form->name) == 0; };
  QString shape = QString::fromLatin1(form->name) + QLatin1Char(' ') + form->shape(m, t);
  for (const FormSection& s : sections_)
    if (joins(s)) shape += QLatin1Char(';') + s.shape(m, t);
  if (shape == shape_) {
    refresh();
    return;
  }
  shape_ = shape;
  clearRows();
  form->fill(*this, t);
  for (const FormSection& s : sections_)
    if (joins(s)) s.fill(*this, t);
  emit rebuilt();
}

void PropertiesPanel::setTitle(const QString& html) {
  title_->setText(html);
}

void PropertiesPanel::setTip(const QString& label, const QString& tip) {
  if (QWidget* f = field(label)) f->setToolTip(tip);
}

bool PropertiesPanel::change(const QString& text,
                             const std::function<bool(Mechanism&, QString*)>& edit, QString* why) {
  Mechanism m = doc_->design();
  if (!edit(m, why)) return false;
  // Solved from the pose shown and kept assembled: a typed dimension that no longer fits moves
  // the bodies it must, and the file closes (it kept the typed drawing, open by 20 mm).
  commitEdit(doc_, text, std::move(m));
  if (!doc_->solveStatus().ok())
    emit message(QString::fromStdString(doc_->solveStatus().message), true);
  return true;
}

void PropertiesPanel::addInfo(const QString& label, std::function<QString()> value) {
  auto* l = new QLabel(value());
  l->setTextInteractionFlags(Qt::TextSelectableByMouse);
  form_->addRow(label, l);
  rows_.push_back({label, l, [l, value] { l->setText(value()); }});
}

void PropertiesPanel::addChoice(const QString& label, const QStringList& items,
                                std::function<int()> current, std::function<void(int)> chosen) {
  auto* box = new QComboBox;
  box->addItems(items);
  box->setCurrentIndex(current());
  form_->addRow(label, box);
  rows_.push_back({label, box, [box, current] {
                     QSignalBlocker b(box);
                     box->setCurrentIndex(current());
                   }});
  // The box shows what the document holds after the choice: a refused one is taken back (the
  // edit may have rebuilt the form, the box with it).
  const QPointer<QComboBox> held(box);
  connect(box, &QComboBox::activated, this, [held, current, chosen = std::move(chosen)](int i) {
    chosen(i);
    if (!held) return;
    QSignalBlocker b(held);
    held->setCurrentIndex(current());
  });
}

std::function<int()> PropertiesPanel::addSelector(const QString& label, const QStringList& items) {
  auto* box = new QComboBox;
  box->addItems(items);
  form_->addRow(label, box);
  rows_.push_back({label, box, [] {}});
  connect(box, &QComboBox::currentIndexChanged, this, [this] { refresh(); });
  const QPointer<QComboBox> held(box);
  return [held] { return held ? held->currentIndex() : 0; };
}

void PropertiesPanel::addButton(const QString& label, const QString& text,
                                std::function<void()> clicked) {
  auto* button = new QPushButton(text);
  form_->addRow(label, button);
  rows_.push_back({label, button, [] {}});
  connect(button, &QPushButton::clicked, this, std::move(clicked));
}

void PropertiesPanel::addCheck(const QString& label, const QString& text,
                               std::function<bool()> checked, std::function<bool()> enabled,
                               std::function<void(bool)> clicked) {
  auto* box = new QCheckBox(text);
  box->setChecked(checked());
  box->setEnabled(enabled());
  form_->addRow(label, box);
  rows_.push_back({label, box, [box, checked, enabled] {
                     QSignalBlocker b(box);
                     box->setChecked(checked());
                     box->setEnabled(enabled());
                   }});
  connect(box, &QCheckBox::clicked, this, std::move(clicked));
}

void PropertiesPanel::addText(const QString& label, std::function<QString()> value,
                              std::function<bool(const QString&, QString*)> commit) {
  auto* e = new QLineEdit(value());
  e->installEventFilter(new FieldUndo(e));
  form_->addRow(label, e);
  // A field being typed in keeps what is typed; any other shows the document's value (an undo
  // while the field has the keyboard shows the value undone).
  rows_.push_back({label, e, [e, value] {
                     const QString v = value();
                     if ((!e->hasFocus() || !e->isModified()) && e->text() != v) e->setText(v);
                   }});
  connect(e, &QLineEdit::editingFinished, this, [this, e, value, commit, label] {
    const QString text = e->text().trimmed();
    if (text == value()) return;
    QString why;
    // The edit may make the rows anew, this field with them.
    const QPointer<QLineEdit> field(e);
    if (!commit(text, &why)) {
      if (refused_ && refused_ != e) markBad(refused_, false);
      markBad(e, true);
      refusal_ = tr("%1: %2").arg(label, why);
      refused_ = e;
      emit message(refusal_, true);
      e->setText(value());
      return;
    }
    if (!field) return;
    markBad(field, false);
    // Committed: the field shows the document's value, its typing no longer to be undone
    // (setText clears the field's own undo history).
    field->setText(value());
  });
}

void PropertiesPanel::messageShown(const QString& text) {
  // A field stays red while the message that says why its value was refused is shown.
  if (text == refusal_ || !refused_) return;
  markBad(refused_, false);
  refused_ = nullptr;
  refusal_.clear();
}

void PropertiesPanel::addNumber(const QString& label, std::function<double()> value,
                                std::function<bool(double, QString*)> commit, const QString& unit) {
  const QString full = unit.isEmpty() ? label : QStringLiteral("%1 [%2]").arg(label, unit);
  addText(
      // Out of double's range (a distance between points dragged to 1e300): no number to show.
      // A field shows the value rounded for people; left as shown, it commits nothing (addText),
      // so the model keeps every digit.
      full,
      [value] {
        const double v = value();
        return std::isfinite(v) ? shownText(v) : QStringLiteral("\u2014");
      },
      [commit](const QString& text, QString* why) {
        const std::optional<double> v = parseNumber(text.toStdString());
        if (!v) {
          *why = tr("\"%1\" is not a number").arg(text);
          return false;
        }
        return commit(*v, why);
      });
  new NumberKeys(qobject_cast<QLineEdit*>(field(full)), [this, full](const QString& key) {
    emit message(tr("%1 takes a number (digits, \".\", \"+\", \"-\", \"e\"): \"%2\" was not typed")
                     .arg(full, key),
                 true);
  });
}

}  // namespace linkage::ui
