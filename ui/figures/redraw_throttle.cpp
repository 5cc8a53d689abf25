#include "figures/redraw_throttle.h"

#include <QTimer>
#include <algorithm>

namespace linkage::ui {

RedrawThrottle::RedrawThrottle(QWidget* owner, std::function<void()> work, int minMs)
    : owner_(owner), work_(std::move(work)), minMs_(minMs) {}

void RedrawThrottle::ask() {
  if (!owner_ || !owner_->isVisible() || pending_) return;
  pending_ = true;
  const int wait = last_.isValid() ? std::max(0, minMs_ - int(last_.elapsed())) : 0;
  QTimer::singleShot(wait, owner_, [this] {
    if (!pending_) return;  // done meanwhile
    pending_ = false;
    work_();
    last_.start();
  });
}

void RedrawThrottle::done() {
  pending_ = false;
}

}  // namespace linkage::ui
