#include "design/study_table_model.h"

#include "linkage/tables/study_table.h"

namespace linkage::ui {

void StudyTableModel::setStudy(const Mechanism& m, const StudySpec& spec, const Study& s) {
  beginResetModel();
  columns_.clear();
  for (const std::string& c : studyColumns(m, spec, s)) columns_ << QString::fromStdString(c);
  values_.clear();
  why_.clear();
  for (const StudyRow& r : s.rows) {
    values_.push_back(studyValues(spec, s, r));
    why_.push_back(r.status.ok() ? QString() : QString::fromStdString(r.status.message));
  }
  endResetModel();
}

void StudyTableModel::clear() {
  beginResetModel();
  columns_.clear();
  values_.clear();
  why_.clear();
  endResetModel();
}

int StudyTableModel::rowCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : static_cast<int>(values_.size());
}

int StudyTableModel::columnCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : static_cast<int>(columns_.size());
}

QVariant StudyTableModel::data(const QModelIndex& index, int role) const {
  if (!index.isValid()) return {};
  const std::optional<double>& v = values_[index.row()][index.column()];
  switch (role) {
    case Qt::DisplayRole:
      return v ? QString::number(*v, 'g', 8) : QString();
    case Qt::UserRole:
      return v ? QVariant(*v) : QVariant();
    case Qt::TextAlignmentRole:
      return int(Qt::AlignRight | Qt::AlignVCenter);
    case Qt::ForegroundRole:
      return why_[index.row()].isEmpty() ? QVariant() : QVariant(warning_);
    case Qt::ToolTipRole:
      return why_[index.row()].isEmpty() ? QVariant() : QVariant(why_[index.row()]);
  }
  return {};
}

QVariant StudyTableModel::headerData(int section, Qt::Orientation o, int role) const {
  if (role != Qt::DisplayRole) return {};
  if (o == Qt::Horizontal) return columns_.value(section);
  return section + 1;
}

}  // namespace linkage::ui
