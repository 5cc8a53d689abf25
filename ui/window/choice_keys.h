// Letters typed into a choice box (a QComboBox with the keyboard) are the box's: it finds its
// entries by them, as every Qt program's boxes do. Qt asks the focused widget first whether it
// wants a key that is also a shortcut (a ShortcutOverride event); a line edit says yes for
// text, a combo box does not, and the window's single-letter keys took them (the B typed in a
// gear's Type box chose the Slider block tool; issue 26, item 9). One filter on the
// application says yes for every combo box; number fields have their own rule (NumberKeys).
#pragma once

#include <QObject>

namespace linkage::ui {

class ChoiceKeys : public QObject {
 public:
  // Installs the filter on the application, once however many windows ask.
  static void install();
  bool eventFilter(QObject* watched, QEvent* e) override;

 private:
  using QObject::QObject;
};

}  // namespace linkage::ui
