// A parameter study's table for a QTableView: the columns of `linkage-cli study`
// (linkage/io/study_table.h), one row per value of t; a measure a row does not have is empty,
// and a row whose crank does not turn fully is drawn in the warning colour with the reason as
// its tooltip. Qt::UserRole holds each number exactly (a double, or nothing).
#pragma once

#include <QAbstractTableModel>
#include <QColor>
#include <optional>
#include <vector>

#include "linkage/study.h"

namespace linkage::ui {

class StudyTableModel : public QAbstractTableModel {
  Q_OBJECT

 public:
  using QAbstractTableModel::QAbstractTableModel;
  void setStudy(const Mechanism& m, const StudySpec& spec, const Study& s);
  void clear();
  void setWarningColour(const QColor& c) { warning_ = c; }

  int rowCount(const QModelIndex& parent = {}) const override;
  int columnCount(const QModelIndex& parent = {}) const override;
  QVariant data(const QModelIndex& index, int role) const override;
  QVariant headerData(int section, Qt::Orientation o, int role) const override;

  const QStringList& columns() const { return columns_; }
  std::optional<double> value(int row, int column) const { return values_[row][column]; }

 private:
  QStringList columns_;
  std::vector<std::vector<std::optional<double>>> values_;
  std::vector<QString> why_;  // per row: why it has no measures, or empty
  QColor warning_ = QColor(210, 30, 20);
};

}  // namespace linkage::ui
