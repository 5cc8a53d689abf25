#include "design/study_runner.h"

namespace linkage::ui {

StudyRunner::StudyRunner(QObject* parent) : QObject(parent) {}

StudyRunner::~StudyRunner() {
  cancel_ = true;
  if (thread_.joinable()) thread_.join();
}

bool StudyRunner::start(const Mechanism& m, const StudySpec& spec) {
  if (running()) return false;
  m_ = m;
  spec_ = spec;
  cancel_ = false;
  study_ = Study{};
  thread_ = std::thread([this] {
    StudyControl control;
    control.cancel = &cancel_;
    // From the pool's threads: queued to the receivers on the GUI thread.
    control.progress = [this](int done, int total) { emit progress(done, total); };
    running_ = runStudy(m_, spec_, control);
    QMetaObject::invokeMethod(
        this, [this] { finish(); }, Qt::QueuedConnection);
  });
  return true;
}

void StudyRunner::cancel() {
  cancel_ = true;
}

void StudyRunner::finish() {
  thread_.join();
  study_ = std::move(running_);
  running_ = Study{};
  emit finished();
}

}  // namespace linkage::ui
