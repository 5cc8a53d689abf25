#include "forces/mass_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QVBoxLayout>

namespace linkage::ui {

namespace {

QDoubleSpinBox* spin(double lo, double hi, int decimals, const QString& suffix) {
  auto* s = new QDoubleSpinBox;
  s->setRange(lo, hi);
  s->setDecimals(decimals);
  s->setSuffix(suffix);
  return s;
}

}  // namespace

MassDialog::MassDialog(const Mechanism& m, BodyId body, QWidget* parent)
    : QDialog(parent), m_(m), body_(body) {
  setWindowTitle(tr("Estimate Mass from Outline"));
  shape_ = new QComboBox;
  shape_->addItems({tr("Bar (round ends, between its two farthest points)"),
                    tr("Plate (the outline around its points)")});
  material_ = new QComboBox;
  for (const Material& mat : materials()) material_->addItem(QString::fromUtf8(mat.name));
  material_->addItem(tr("other"));
  density_ = spin(1, 30000, 0, tr(" kg/m\u00b3"));
  thickness_ = spin(0.1, 1000, 1, tr(" mm"));
  width_ = spin(0.1, 1000, 1, tr(" mm"));
  result_ = new QLabel;
  result_->setWordWrap(true);
  result_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  auto* form = new QFormLayout;
  form->addRow(tr("Shape"), shape_);
  form->addRow(tr("Material"), material_);
  form->addRow(tr("Density"), density_);
  form->addRow(tr("Thickness"), thickness_);
  form->addRow(tr("Bar width"), width_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
  ok_ = buttons->button(QDialogButtonBox::Ok);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(result_);
  layout->addWidget(buttons);

  QSettings s;
  s.beginGroup(QStringLiteral("massEstimate"));
  shape_->setCurrentIndex(s.value(QStringLiteral("shape"), 0).toInt());
  material_->setCurrentIndex(s.value(QStringLiteral("material"), 0).toInt());
  density_->setValue(s.value(QStringLiteral("density"), materials()[0].kgPerM3).toDouble());
  thickness_->setValue(s.value(QStringLiteral("thickness"), 5.0).toDouble());
  width_->setValue(s.value(QStringLiteral("width"), 10.0).toDouble());
  connect(material_, &QComboBox::currentIndexChanged, this, [this](int i) {
    if (i >= 0 && i < static_cast<int>(materials().size()))
      density_->setValue(materials()[i].kgPerM3);
  });
  connect(density_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
    // A density typed that is no listed material's is "other".
    int match = static_cast<int>(materials().size());
    for (size_t i = 0; i < materials().size(); ++i)
      if (materials()[i].kgPerM3 == v) match = static_cast<int>(i);
    QSignalBlocker b(material_);
    material_->setCurrentIndex(match);
  });
  for (QDoubleSpinBox* box : {density_, thickness_, width_})
    connect(box, &QDoubleSpinBox::valueChanged, this, &MassDialog::update);
  connect(shape_, &QComboBox::currentIndexChanged, this, &MassDialog::update);
  update();
}

MassDialog::~MassDialog() {
  if (result() != Accepted) return;
  QSettings s;
  s.beginGroup(QStringLiteral("massEstimate"));
  s.setValue(QStringLiteral("shape"), shape_->currentIndex());
  s.setValue(QStringLiteral("material"), material_->currentIndex());
  s.setValue(QStringLiteral("density"), density_->value());
  s.setValue(QStringLiteral("thickness"), thickness_->value());
  s.setValue(QStringLiteral("width"), width_->value());
}

Outline MassDialog::outline() const {
  Outline o;
  o.shape = shape_->currentIndex() == 1 ? Outline::Shape::Plate : Outline::Shape::Bar;
  o.kgPerM3 = density_->value();
  o.thicknessMm = thickness_->value();
  o.widthMm = width_->value();
  return o;
}

QString MassDialog::resultText() const {
  return result_->text();
}

void MassDialog::update() {
  width_->setEnabled(shape_->currentIndex() == 0);
  const MassEstimate e = estimateMass(m_, body_, outline());
  estimate_ = e.mass;
  ok_->setEnabled(bool(estimate_));
  if (!estimate_) {
    result_->setText(tr("No estimate: %1.").arg(QString::fromStdString(e.why)));
    return;
  }
  result_->setText(tr("%1 kg, centre of mass at (%2, %3) mm, moment of inertia %4 "
                      "kg\u00b7mm\u00b2 about it")
                       .arg(estimate_->kg, 0, 'g', 4)
                       .arg(estimate_->com.x(), 0, 'f', 2)
                       .arg(estimate_->com.y(), 0, 'f', 2)
                       .arg(estimate_->jKgMm2, 0, 'g', 4));
}

}  // namespace linkage::ui
