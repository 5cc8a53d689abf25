// Estimate from Outline: a link's mass properties from its drawn outline as a bar or a plate of
// a chosen material and thickness (linkage/mass_estimate.h), shown as they are typed, so that a
// designer without a CAD model gets plausible numbers. The last choices are remembered.
#pragma once

#include <QDialog>
#include <optional>

#include "linkage/mass_estimate.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;

namespace linkage::ui {

class MassDialog : public QDialog {
  Q_OBJECT

 public:
  MassDialog(const Mechanism& m, BodyId body, QWidget* parent = nullptr);
  ~MassDialog() override;
  // What OK applies (none while the outline cannot give one).
  const std::optional<Mass>& estimate() const { return estimate_; }
  Outline outline() const;
  // The widgets, for tests.
  QComboBox* shapeBox() const { return shape_; }
  QComboBox* materialBox() const { return material_; }
  QDoubleSpinBox* thicknessBox() const { return thickness_; }
  QDoubleSpinBox* widthBox() const { return width_; }
  QString resultText() const;

 private:
  void update();

  const Mechanism& m_;
  BodyId body_;
  QComboBox *shape_, *material_;
  QDoubleSpinBox *density_, *thickness_, *width_;
  QLabel* result_;
  QPushButton* ok_ = nullptr;
  std::optional<Mass> estimate_;
};

}  // namespace linkage::ui
