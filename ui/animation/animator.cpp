#include "animation/animator.h"

#include <cmath>

#include "document/document.h"
#include "document/shown_numbers.h"

namespace linkage::ui {

namespace {
// A stall longer than this (a debugger, a suspended laptop) does not fling the mechanism on.
constexpr double kMaxFrameSeconds = 0.5;
}  // namespace

Animator::Animator(QObject* parent) : QObject(parent) {
  timer_.setTimerType(Qt::PreciseTimer);
  timer_.setInterval(15);
  connect(&timer_, &QTimer::timeout, this, &Animator::tick);
}

void Animator::setDocument(Document* doc) {
  setPlaying(false);
  if (doc_) disconnect(doc_, nullptr, this, nullptr);
  doc_ = doc;
  resetLimits();
  if (doc_) connect(doc_, &Document::designChanged, this, &Animator::resetLimits);
}

void Animator::resetLimits() {
  low_.reset();
  high_.reset();
  sweep_ = 1;
}

void Animator::setPlaying(bool on) {
  if (on == playing()) return;
  if (on) {
    const Status s = doc_ ? doc_->motionStatus() : Status::success();
    if (!doc_ || !s.ok()) {
      emit message(doc_ ? QStringLiteral("Cannot play: %1").arg(QString::fromStdString(s.message))
                        : QString(),
                   true);
      return;
    }
    clock_.start();
    lastNs_ = 0;
    timer_.start();
  } else {
    timer_.stop();
  }
  emit playingChanged(on);
}

void Animator::setIncrementDeg(double deg) {
  if (deg > 0 && std::isfinite(deg)) increment_ = deg;
}

void Animator::setSlowMotion(double factor) {
  if (factor > 0 && std::isfinite(factor)) slow_ = std::min(factor, 1.0);
}

double Animator::degreesPerSecond() const {
  return doc_ ? std::abs(doc_->kinematics().rpm()) * 6.0 * slow_ : 0.0;
}

void Animator::tick() {
  const qint64 now = clock_.nsecsElapsed();
  const double dt = (now - lastNs_) * 1e-9;
  lastNs_ = now;
  advance(dt);
}

void Animator::step(int direction) {
  setPlaying(false);
  if (!doc_) return;
  if (const Status m = doc_->motionStatus(); !m.ok()) {
    emit message(QStringLiteral("Cannot turn the crank: %1").arg(QString::fromStdString(m.message)),
                 true);
    return;
  }
  const double from = doc_->crankDeg();
  Status s = doc_->setCrankDeg(from + (direction >= 0 ? 1 : -1) * increment_);
  if (!s.ok()) emit message(QString::fromStdString(s.message), true);
}

void Animator::advance(double seconds) {
  if (!doc_ || !doc_->motionStatus().ok()) {
    setPlaying(false);
    return;
  }
  const double delta = degreesPerSecond() * std::min(seconds, kMaxFrameSeconds);
  if (delta == 0) return;
  const Status s = doc_->setCrankDeg(doc_->crankDeg() + sweep_ * delta);
  if (s.ok()) return;
  if (s.code == StatusCode::Unreachable) {
    // A limit position: the driver turns back, as a hand moving it would.
    (sweep_ > 0 ? high_ : low_) = doc_->crankDeg();
    sweep_ = -sweep_;
    QString text;
    if (low_ && high_)
      text = QStringLiteral("Swings between the limit positions at crank %1\u00b0 and %2\u00b0")
                 .arg(angleText(*low_, 2))
                 .arg(angleText(*high_, 2));
    else
      text = QStringLiteral("Limit position at crank %1\u00b0: turning back")
                 .arg(angleText(doc_->crankDeg(), 2));
    emit message(
        text + QStringLiteral(" (") + QString::fromStdString(s.message) + QStringLiteral(")"),
        false);
    return;
  }
  // A change point or a position the solver cannot pass: stop there and say why.
  setPlaying(false);
  emit message(QStringLiteral("Stopped at crank %1\u00b0: %2")
                   .arg(angleText(doc_->crankDeg(), 3))
                   .arg(QString::fromStdString(s.message)),
               true);
}

}  // namespace linkage::ui
