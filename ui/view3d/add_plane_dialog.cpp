#include "view3d/add_plane_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QRegularExpression>
#include <QStackedWidget>
#include <QVBoxLayout>
#include <cmath>

#include "linkage/edits.h"

namespace linkage::ui {

namespace {

// "x, y, z" (or spaces between) in millimetres, `.` the decimal point as in the files.
std::optional<Vec3> readVector(const QLineEdit* e) {
  const QStringList parts =
      e->text().split(QRegularExpression(QStringLiteral("[,\\s]+")), Qt::SkipEmptyParts);
  if (parts.size() != 3) return std::nullopt;
  Vec3 v;
  for (int k = 0; k < 3; ++k) {
    bool ok = false;
    v[k] = QLocale::c().toDouble(parts[k], &ok);
    if (!ok || !std::isfinite(v[k])) return std::nullopt;
  }
  return v;
}

std::optional<double> readNumber(const QLineEdit* e) {
  bool ok = false;
  const double v = QLocale::c().toDouble(e->text().trimmed(), &ok);
  return ok && std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}

QLineEdit* field(const QString& text, const QString& tip) {
  auto* e = new QLineEdit(text);
  e->setToolTip(tip);
  return e;
}

}  // namespace

AddPlaneDialog::AddPlaneDialog(const Mechanism& m, QWidget* parent)
    : QDialog(parent), m_(m), shafts_(shafts(m)) {
  setWindowTitle(tr("Add Plane"));
  auto* form = new QFormLayout;
  name = field(QString::fromStdString(newPlaneName(m)), tr("The plane's name in the file"));
  how = new QComboBox;
  how->addItems(
      {tr("Typed origin and axes"), tr("Square to a shaft"), tr("Inclined by rho about x")});
  form->addRow(tr("Name"), name);
  form->addRow(tr("Made"), how);
  pages_ = new QStackedWidget;
  pages_->addWidget(typedPage());
  pages_->addWidget(shaftPage());
  pages_->addWidget(inclinedPage());
  connect(how, &QComboBox::currentIndexChanged, pages_, &QStackedWidget::setCurrentIndex);
  problem = new QLabel;
  problem->setObjectName(QStringLiteral("planeProblem"));
  problem->setWordWrap(true);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
  connect(buttons, &QDialogButtonBox::accepted, this, &AddPlaneDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* box = new QVBoxLayout(this);
  box->addLayout(form);
  box->addWidget(pages_);
  box->addWidget(problem);
  box->addWidget(buttons);
}

QWidget* AddPlaneDialog::typedPage() {
  auto* page = new QWidget;
  auto* f = new QFormLayout(page);
  origin = field(QStringLiteral("0, 0, 0"), tr("Where the plane's (0, 0) is in the world (mm)"));
  xAxis = field(QStringLiteral("1, 0, 0"), tr("The plane's x axis in the world (unit)"));
  yAxis = field(QStringLiteral("0, 1, 0"),
                tr("The plane's y axis in the world (unit, perpendicular to x)"));
  f->addRow(tr("Origin [mm]"), origin);
  f->addRow(tr("x axis"), xAxis);
  f->addRow(tr("y axis"), yAxis);
  return page;
}

QWidget* AddPlaneDialog::shaftPage() {
  auto* page = new QWidget;
  auto* f = new QFormLayout(page);
  shaft = new QComboBox;
  for (PointId p : shafts_) shaft->addItem(QString::fromStdString(m_.pointLabel(p)));
  shaft->setToolTip(tr("A ground pivot: the shaft is along the normal of what turns on it"));
  along = field(QStringLiteral("10"), tr("How far along the shaft from the pivot (mm)"));
  f->addRow(tr("Shaft at"), shaft);
  f->addRow(tr("Along it [mm]"), along);
  return page;
}

QWidget* AddPlaneDialog::inclinedPage() {
  auto* page = new QWidget;
  auto* f = new QFormLayout(page);
  inclinedOrigin = field(QStringLiteral("0, 0, 0"), tr("Where the plane's (0, 0) is (mm)"));
  rho = field(QStringLiteral("23"), tr("The plane's y axis turned up from the world's y by rho"));
  f->addRow(tr("Origin [mm]"), inclinedOrigin);
  f->addRow(QString::fromUtf8("rho [\u00b0]"), rho);
  return page;
}

std::optional<Plane> AddPlaneDialog::plane(std::string* why) const {
  const std::string n = name->text().trimmed().toStdString();
  auto refuse = [&](const QString& text) {
    *why = text.toStdString();
    return std::nullopt;
  };
  std::optional<Plane> p;
  if (how->currentIndex() == 0) {
    const auto o = readVector(origin), x = readVector(xAxis), y = readVector(yAxis);
    if (!o || !x || !y) return refuse(tr("origin and axes: three numbers each, as 0, 0, 80"));
    p = Plane{n, *o, *x, *y, {}};
  } else if (how->currentIndex() == 1) {
    const auto d = readNumber(along);
    if (shaft->currentIndex() < 0) return refuse(tr("the machine has no shaft (a ground pivot)"));
    if (!d) return refuse(tr("along: not a number"));
    p = planeOnShaft(m_, n, shafts_[shaft->currentIndex()], *d);
  } else {
    const auto o = readVector(inclinedOrigin);
    const auto r = readNumber(rho);
    if (!o || !r) return refuse(tr("origin: three numbers; rho: a number of degrees"));
    p = planeInclinedAboutX(n, *o, *r);
  }
  Mechanism probe = m_;
  if (!p || !addPlane(probe, *p, why)) return std::nullopt;
  return p;
}

void AddPlaneDialog::accept() {
  std::string why;
  if (!plane(&why)) {
    problem->setText(QString::fromStdString(why));
    adjustSize();  // room for the reason, whole
    return;
  }
  QDialog::accept();
}

}  // namespace linkage::ui
