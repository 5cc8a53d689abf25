// The plots of a parameter study: any measure of the table against t, and the family of
// designs at a glance: the measured point's path of every variant in the plane (equal scales),
// or its position along the stroke's direction against the crank angle, one curve per value of
// t coloured by t on a scale beside it; a variant whose crank stops is drawn dashed as far as it
// went.
#pragma once

#include <QWidget>
#include <vector>

#include "linkage/study.h"

class QComboBox;
class QCustomPlot;
class QCPColorGradient;

namespace linkage::ui {

class StudyTableModel;

class StudyPlots : public QWidget {
  Q_OBJECT

 public:
  enum class Family { Paths, AgainstCrank };

  explicit StudyPlots(QWidget* parent = nullptr);
  // Shows a finished study (its rows with their paths) and the model's columns as measures.
  // The family is drawn as paths, or against the crank angle where every path lies on one
  // line along the stroke, until the user chooses.
  void setStudy(const Mechanism& m, const StudySpec& spec, const Study& s,
                const StudyTableModel* model);
  void clear();

  QCustomPlot* measurePlot() const { return measure_; }
  QCustomPlot* familyPlot() const { return family_; }
  QComboBox* measureBox() const { return measureBox_; }
  QComboBox* familyBox() const { return familyBox_; }
  // The curves of the family drawn now (one per variant with a path).
  int familyCurves() const;

 protected:
  bool eventFilter(QObject* o, QEvent* e) override;

 private:
  void plotMeasure();
  void plotFamily();
  void fitFamily();

  const StudyTableModel* model_ = nullptr;
  Study study_;
  StudySpec spec_;
  Vec2 direction_ = Vec2::UnitY();
  QString pointLabel_, crankLabel_;
  bool familyChosen_ = false;  // the user chose the family's view: kept
  QComboBox *measureBox_, *familyBox_;
  QCustomPlot *measure_, *family_;
};

}  // namespace linkage::ui
