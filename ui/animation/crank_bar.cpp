#include "animation/crank_bar.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <algorithm>
#include <cmath>

#include "animation/animator.h"
#include "document/document.h"

namespace linkage::ui {

namespace {
constexpr int kSliderSteps = 3600;  // tenths of a degree over a revolution
}

const std::vector<double>& CrankBar::speeds() {
  static const std::vector<double> s{1.0, 0.5, 0.2, 0.1, 0.05, 0.02, 0.01};
  return s;
}

CrankBar::CrankBar(Animator* animator, QWidget* parent) : QWidget(parent), animator_(animator) {
  slider_ = new QSlider(Qt::Horizontal);
  slider_->setRange(0, kSliderSteps);
  slider_->setPageStep(kSliderSteps / 36);
  slider_->setMinimumWidth(200);
  slider_->setToolTip(tr("Crank angle within the current revolution"));
  slider_->setFocusPolicy(Qt::ClickFocus);
  angle_ = new QDoubleSpinBox;
  angle_->setObjectName("crankAngle");  // for scripts (the probe)
  angle_->setRange(-1e7, 1e7);
  angle_->setDecimals(2);
  angle_->setSuffix(QStringLiteral("\u00b0"));
  angle_->setKeyboardTracking(false);
  angle_->setToolTip(tr("Crank angle from the start, in the driving direction (degrees)"));
  revs_ = new QLabel;
  revs_->setToolTip(tr("Whole revolutions of the crank from the start"));
  increment_ = new QDoubleSpinBox;
  increment_->setObjectName("crankStep");
  increment_->setRange(0.01, 90);
  increment_->setDecimals(2);
  increment_->setValue(animator_->incrementDeg());
  increment_->setSuffix(QStringLiteral("\u00b0"));
  increment_->setToolTip(tr("Step increment (Left and Right keys)"));
  speed_ = new QComboBox;
  for (double f : speeds())
    speed_->addItem(f == 1 ? tr("x1 (real time)") : QStringLiteral("x1/%1").arg(1 / f));
  speed_->setToolTip(tr("Slow motion: the animation runs at this fraction of the driver's speed"));
  driver_ = new QLabel;

  auto* l = new QHBoxLayout(this);
  l->setContentsMargins(4, 0, 4, 0);
  l->addWidget(new QLabel(tr("Crank")));
  l->addWidget(slider_, 1);
  l->addWidget(angle_);
  l->addWidget(revs_);
  l->addSpacing(12);
  l->addWidget(new QLabel(tr("Step")));
  l->addWidget(increment_);
  l->addWidget(new QLabel(tr("Speed")));
  l->addWidget(speed_);
  l->addSpacing(12);
  l->addWidget(driver_);

  connect(slider_, &QSlider::valueChanged, this, [this](int v) {
    if (!doc_) return;
    const double rev = std::floor(doc_->crankDeg() / 360.0);
    seek(rev * 360.0 + v * 360.0 / kSliderSteps);
  });
  connect(angle_, &QDoubleSpinBox::valueChanged, this, [this](double v) { seek(v); });
  connect(increment_, &QDoubleSpinBox::valueChanged, animator_, &Animator::setIncrementDeg);
  connect(speed_, &QComboBox::currentIndexChanged, this, [this](int i) {
    if (i >= 0 && i < int(speeds().size())) animator_->setSlowMotion(speeds()[i]);
  });
}

void CrankBar::setSpeedIndex(int i) {
  speed_->setCurrentIndex(std::clamp(i, 0, int(speeds().size()) - 1));
}

void CrankBar::setDocument(Document* doc) {
  if (doc_) disconnect(doc_, nullptr, this, nullptr);
  doc_ = doc;
  if (doc_) {
    connect(doc_, &Document::poseChanged, this, &CrankBar::showPose);
    connect(doc_, &Document::designChanged, this, &CrankBar::showDriver);
  }
  showDriver();
  showPose();
}

void CrankBar::seek(double deg) {
  if (!doc_ || !doc_->solved()) return;
  animator_->setPlaying(false);
  doc_->setCrankDeg(deg);
}

void CrankBar::showPose() {
  const double deg = doc_ ? doc_->crankDeg() : 0.0;
  const double rev = std::floor(deg / 360.0);
  QSignalBlocker a(slider_), b(angle_);
  // Within the turn (at a crank angle of 1e300 the difference is rounding of any size), and the
  // turns as a number however many (a long long of 2.8e297 was undefined behaviour).
  const double within = std::clamp(deg - 360.0 * rev, 0.0, 360.0);
  slider_->setValue(static_cast<int>(std::lround(within / 360.0 * kSliderSteps)));
  angle_->setValue(deg);
  // A crank turned by a start angle of a file's making (1e300) has more turns than an integer
  // holds: those are written as a number, not converted (undefined behaviour).
  revs_->setText(std::abs(rev) < 1e15 ? tr("rev %1").arg(static_cast<long long>(rev))
                                      : tr("rev %1").arg(rev, 0, 'g', 6));
}

void CrankBar::showDriver() {
  // The design's driver, and whether the solver holds the design it drives (the bar turns only
  // that); the reason it does not is the document's, in the tooltip and the red line over the
  // canvas.
  const Driver* d = doc_ && doc_->design().driver ? &*doc_->design().driver : nullptr;
  const bool solved = doc_ && doc_->solved();
  setEnabled(d && solved);
  driver_->setToolTip(
      doc_ && !solved
          ? tr("Not solved: %1").arg(QString::fromStdString(doc_->solveStatus().message))
          : QString());
  if (!d) {
    driver_->setText(solved ? tr("no driver") : tr("no driver, not solved"));
    return;
  }
  const QString speed =
      tr("%1 rpm %2").arg(d->rpm).arg(d->direction == Direction::Cw ? tr("cw") : tr("ccw"));
  driver_->setText(solved ? speed : tr("%1, not solved").arg(speed));
}

}  // namespace linkage::ui
