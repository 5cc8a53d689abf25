// The crank-angle scrubber under the canvas: a slider over one revolution, the angle in a spin
// box (any number of revolutions), the revolutions counted, the step increment, the slow-motion
// factor and the driver's speed. Moving the slider or typing an angle moves the mechanism
// there continuously (the solver tracks the motion, so it never jumps to the other branch).
#pragma once

#include <QPointer>
#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QSlider;

namespace linkage::ui {

class Animator;
class Document;

class CrankBar : public QWidget {
  Q_OBJECT

 public:
  CrankBar(Animator* animator, QWidget* parent = nullptr);
  void setDocument(Document* doc);
  QSlider* slider() const { return slider_; }
  QDoubleSpinBox* angleBox() const { return angle_; }
  QComboBox* speedBox() const { return speed_; }
  QDoubleSpinBox* incrementBox() const { return increment_; }
  // The driver's speed and direction, or why nothing turns ("no driver", "not solved").
  QLabel* driverLabel() const { return driver_; }
  // Slow-motion factors offered, fastest first.
  static const std::vector<double>& speeds();
  void setSpeedIndex(int i);

 private:
  void showPose();
  void showDriver();
  void seek(double deg);

  Animator* animator_;
  QPointer<Document> doc_;
  QSlider* slider_;
  QDoubleSpinBox* angle_;
  QLabel* revs_;
  QDoubleSpinBox* increment_;
  QComboBox* speed_;
  QLabel* driver_;
};

}  // namespace linkage::ui
