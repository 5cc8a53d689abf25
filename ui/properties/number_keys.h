// The keys typed into a number field. A field with the keyboard owns what is typed there: a key
// that cannot be part of a number ("abc" typed into Mass) is dropped, and the field says why,
// never passed to the window, whose single letters choose tools (the B of the Slider block
// tool). One exception, for drafting: a window's key typed right after a number typed there
// (the L of the Link tool after "-29.34") commits the number and acts. After a key the field
// refused, until a number's key is typed again, no key is a window's: a slip is not a command.
#pragma once

#include <QObject>
#include <functional>

class QKeyEvent;
class QLineEdit;

namespace linkage::ui {

class NumberKeys : public QObject {
 public:
  // Filters `field`'s keys; `refused` is told each key dropped (its text).
  NumberKeys(QLineEdit* field, std::function<void(const QString&)> refused);
  bool eventFilter(QObject* watched, QEvent* e) override;

  // What a number is typed with: digits, a point, signs, an exponent.
  static bool partOfNumber(QChar c);

 private:
  // A number typed in the field (not the one shown), and no key refused since.
  bool numberTyped() const;
  // A shortcut of one of the window's actions (enabled) is this key.
  bool windowKey(const QKeyEvent* k) const;

  QLineEdit* field_;
  std::function<void(const QString&)> refused_;
  bool slipped_ = false;
};

}  // namespace linkage::ui
