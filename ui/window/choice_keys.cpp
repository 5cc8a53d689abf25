#include "window/choice_keys.h"

#include <QApplication>
#include <QComboBox>
#include <QKeyEvent>

namespace linkage::ui {

void ChoiceKeys::install() {
  static ChoiceKeys* filter = nullptr;
  if (filter || !qApp) return;
  filter = new ChoiceKeys(qApp);
  qApp->installEventFilter(filter);
}

bool ChoiceKeys::eventFilter(QObject* watched, QEvent* e) {
  if (e->type() != QEvent::ShortcutOverride || !qobject_cast<QComboBox*>(watched)) return false;
  const auto* k = static_cast<QKeyEvent*>(e);
  // A printable key, as typed (Shift allowed): the box's. Ctrl, Alt and the function keys stay
  // the window's.
  const Qt::KeyboardModifiers mods = k->modifiers() & ~(Qt::ShiftModifier | Qt::KeypadModifier);
  if (mods == Qt::NoModifier && !k->text().isEmpty() && k->text().at(0).isPrint()) e->accept();
  return false;
}

}  // namespace linkage::ui
