// Edit > Add Plane (issue 27): a plane for a machine in space, made one of three ways a
// designer names it: typed (origin, x axis, y axis in the world), square to a shaft at a
// distance along it (where another crank on that shaft turns), or inclined by rho about the
// world's x through an origin (seed 004's rocker plane). The plane is checked as a file's is
// (linkage/edits.h: addPlane) before the dialog closes; a refusal is said in it, naming the
// field, and the dialog stays open.
#pragma once

#include <QDialog>
#include <optional>
#include <string>

#include "linkage/model.h"

class QComboBox;
class QLabel;
class QLineEdit;
class QStackedWidget;

namespace linkage::ui {

class AddPlaneDialog : public QDialog {
  Q_OBJECT

 public:
  AddPlaneDialog(const Mechanism& m, QWidget* parent = nullptr);

  // The plane the fields make, checked against the mechanism; none with `why`.
  std::optional<Plane> plane(std::string* why) const;
  void accept() override;

  QLineEdit* name;
  QComboBox* how;  // Typed, OnShaft, Inclined
  QLineEdit *origin, *xAxis, *yAxis;
  QComboBox* shaft;
  QLineEdit* along;
  QLineEdit *inclinedOrigin, *rho;
  QLabel* problem;

 private:
  QWidget* typedPage();
  QWidget* shaftPage();
  QWidget* inclinedPage();

  const Mechanism& m_;
  std::vector<PointId> shafts_;
  QStackedWidget* pages_;
};

}  // namespace linkage::ui
