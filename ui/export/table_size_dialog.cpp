#include "export/table_size_dialog.h"

#include <QDialog>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QSpinBox>

namespace linkage::ui {

bool askTableSize(QWidget* parent, const QString& title, TableSize* size) {
  QDialog dialog(parent);
  dialog.setWindowTitle(title);
  auto* steps = new QSpinBox;
  steps->setRange(1, 100000);
  steps->setValue(size->stepsPerRev);
  steps->setToolTip(QDialog::tr("Rows per revolution of the crank"));
  auto* revs = new QSpinBox;
  revs->setRange(1, 1000);
  revs->setValue(size->revs);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
  auto* form = new QFormLayout(&dialog);
  form->addRow(QDialog::tr("Steps per revolution"), steps);
  form->addRow(QDialog::tr("Revolutions"), revs);
  form->addRow(buttons);
  QObject::connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
  QObject::connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
  if (dialog.exec() != QDialog::Accepted) return false;
  size->stepsPerRev = steps->value();
  size->revs = revs->value();
  return true;
}

}  // namespace linkage::ui
