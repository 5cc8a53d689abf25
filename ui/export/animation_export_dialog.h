// The dialog of File > Export > Animation: format (GIF or PNG sequence), size, frame count,
// revolutions, and the speed as frames per second or as a factor of the mechanism's real
// speed, and the file. run() shows it, then renders with a progress dialog.
//
//   QString err;
//   if (!AnimationExportDialog::run(this, doc->kinematics().rpm(), renderer, &err) &&
//   !err.isEmpty())
//     QMessageBox::warning(this, "Export", err);
#pragma once

#include <QDialog>

#include "export/animation_export.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QRadioButton;
class QSpinBox;

namespace linkage::ui {

class AnimationExportDialog : public QDialog {
  Q_OBJECT

 public:
  // rpm: the driver's speed, for the real-speed factor.
  AnimationExportDialog(double rpm, QWidget* parent = nullptr);

  AnimationSpec spec() const;
  void setSpec(const AnimationSpec& s);

  // Shows the dialog; if accepted, exports with a progress dialog. False when cancelled (error
  // left empty) or failed (error says why).
  static bool run(QWidget* parent, double rpm, const FrameRenderer& render, QString* error);

 private:
  void updateSpeedText();
  void browse();

  double rpm_;
  QComboBox* format_;
  QSpinBox *width_, *height_, *frames_;
  QDoubleSpinBox *revs_, *fps_, *speed_;
  QRadioButton *byFps_, *bySpeed_;
  QLabel* speedText_;
  QLineEdit* path_;
};

}  // namespace linkage::ui
