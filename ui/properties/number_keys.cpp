#include "properties/number_keys.h"

#include <QAction>
#include <QKeyEvent>
#include <QLineEdit>

#include "linkage/io/numbers.h"

namespace linkage::ui {

NumberKeys::NumberKeys(QLineEdit* field, std::function<void(const QString&)> refused)
    : QObject(field), field_(field), refused_(std::move(refused)) {
  field->installEventFilter(this);
}

bool NumberKeys::partOfNumber(QChar c) {
  return QStringLiteral("0123456789.+-eE").contains(c);
}

bool NumberKeys::numberTyped() const {
  return !slipped_ && field_->isModified() &&
         parseNumber(field_->text().trimmed().toStdString()).has_value();
}

bool NumberKeys::windowKey(const QKeyEvent* k) const {
  // As the window's shortcut map matches: the key as pressed, or without the Shift a symbol
  // needs ("#" is Shift+3 on many keyboards).
  const QKeySequence pressed(k->keyCombination());
  const QKeySequence bare(QKeyCombination(
      k->modifiers() & ~(Qt::ShiftModifier | Qt::KeypadModifier), Qt::Key(k->key())));
  for (const QAction* a : field_->window()->findChildren<QAction*>())
    if (a->isEnabled())
      for (const QKeySequence& s : a->shortcuts())
        if (s.matches(pressed) == QKeySequence::ExactMatch ||
            s.matches(bare) == QKeySequence::ExactMatch)
          return true;
  return false;
}

bool NumberKeys::eventFilter(QObject* watched, QEvent* e) {
  if (e->type() == QEvent::FocusIn) slipped_ = false;
  if (watched != field_ || (e->type() != QEvent::ShortcutOverride && e->type() != QEvent::KeyPress))
    return QObject::eventFilter(watched, e);
  auto* k = static_cast<QKeyEvent*>(e);
  const QString text = k->text();
  const bool plain = !(k->modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier));
  // Editing keys and chords (Ctrl+Z, arrows, Backspace) are the field's and the window's as ever.
  if (!plain || text.size() != 1 || !text[0].isPrint()) return QObject::eventFilter(watched, e);
  if (partOfNumber(text[0])) {
    if (e->type() == QEvent::KeyPress) slipped_ = false;
    return QObject::eventFilter(watched, e);
  }
  if (e->type() == QEvent::ShortcutOverride) {
    if (numberTyped() && windowKey(k)) {
      // The value as typed is committed first: the shortcut may take the keyboard away.
      Q_EMIT field_->editingFinished();
      e->ignore();  // the window's shortcut acts
    } else {
      e->accept();  // the field owns the key: its press comes here, and is dropped
    }
    return true;
  }
  slipped_ = true;
  if (refused_) refused_(text);
  return true;
}

}  // namespace linkage::ui
