// A parameter study run off the GUI thread, so that the window stays responsive: runStudy
// (linkage/study.h), with its own pool of threads (one per core), runs on one thread of this
// runner's; its progress after each variant comes here as a signal, and a cancel stops it
// between variants (StudyControl). The rows are runStudy's, bit for bit.
#pragma once

#include <QObject>
#include <atomic>
#include <thread>

#include "linkage/study.h"

namespace linkage::ui {

class StudyRunner : public QObject {
  Q_OBJECT

 public:
  explicit StudyRunner(QObject* parent = nullptr);
  // Cancels a run under way and waits for the variants being computed.
  ~StudyRunner() override;

  // Starts a study of m (copied) with `spec`; false when a run is under way.
  bool start(const Mechanism& m, const StudySpec& spec);
  void cancel();
  bool running() const { return thread_.joinable(); }

  // The last finished run: the rows computed (all of them unless it was cancelled), in t order.
  // status: BadModel for a spec that cannot run (as runStudy says).
  const Study& study() const { return study_; }
  const Mechanism& mechanism() const { return m_; }
  const StudySpec& spec() const { return spec_; }
  bool cancelled() const { return study_.cancelled; }

 Q_SIGNALS:
  void progress(int done, int total);
  void finished();

 private:
  void finish();

  Mechanism m_;
  StudySpec spec_;
  std::atomic<bool> cancel_{false};
  std::thread thread_;
  Study running_, study_;
};

}  // namespace linkage::ui
