// The Cycle dock's window form (issue 26): a window made by choosing rather than typing. Its
// output is a point of the mechanism, from a list of them named as the canvas names them
// ("needlebar.N") or picked on the canvas, along an axis (y or x; a direction typed in the
// line is kept), or a body's angle; then below or above, the threshold in a number field
// (it can also be dragged on the dock's diagram), and the window's name. The form shows a new
// window, added with Add, or the window chosen in the dock's list, which each change edits.
// It only shows and asks: the dock (cycle/cycle_panel.h) makes the changes, as undo steps.
#pragma once

#include <QWidget>
#include <optional>

#include "linkage/model.h"

class QAbstractButton;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QToolButton;

namespace linkage::ui {

class WindowForm : public QWidget {
  Q_OBJECT

 public:
  explicit WindowForm(QWidget* parent = nullptr);

  // The points and bodies to choose from, and the names taken (after each change of the
  // design); what is shown stays, where the mechanism still has it.
  void offer(const Mechanism& m);
  // Shows window w of m: `index` >= 0 is m's window of that index, edited by each change; -1 a
  // new window, made by Add.
  void load(int index, const TimingWindow& w, const Mechanism& m);
  int target() const { return target_; }
  // A new window from the fields shown (its name made anew from the point's body).
  void startNew();
  // The window the fields describe, or nullopt with why (no point chosen, a name not allowed).
  std::optional<TimingWindow> window(const Mechanism& m, QString* why) const;
  // Shown without a signal: a level dragged on the diagram, or moved into the output's stroke.
  void setLevel(double v);
  double level() const;
  // The output a point picked on the canvas: as if chosen from the list (edited() follows).
  void choosePoint(const Mechanism& m, PointId p);
  // What the window gives: its crank angles, or why it has none.
  void setResult(const QString& text);
  void setPicking(bool on);

  // For tests and the probe.
  QComboBox* pointBox() const { return point_; }
  QComboBox* axisBox() const { return axis_; }
  QComboBox* compareBox() const { return compare_; }
  QDoubleSpinBox* levelField() const { return level_; }
  QLineEdit* nameField() const { return name_; }
  QToolButton* pickButton() const { return pick_; }
  QPushButton* addButton() const { return add_; }
  QPushButton* newButton() const { return new_; }
  QString resultText() const;
  QStringList probeLines() const;

 Q_SIGNALS:
  // The user changed a field; `outputChanged` when the point, body or axis did (the threshold
  // may have to move into the new output's stroke).
  void edited(bool outputChanged);
  void addRequested();
  void newRequested();
  // The Pick button: on, the next click on the canvas gives a point (choosePoint); off, give up.
  void pickRequested(bool on);

 private:
  void build();
  void connectFields();
  void outputChosen();
  void showMode();
  void suggestName(const QString& base);
  bool angleChosen() const;

  int target_ = -1;
  bool quiet_ = false;
  QString autoName_;  // the name the form gave (replaced when another point is chosen)
  std::vector<std::string> taken_;
  QLabel* mode_;
  QLineEdit* name_;
  QComboBox *point_, *axis_, *compare_;
  QToolButton* pick_;
  QDoubleSpinBox* level_;
  QLabel* result_;
  QPushButton *add_, *new_;
};

}  // namespace linkage::ui
