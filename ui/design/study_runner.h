// A parameter study run off the GUI thread, so that the window stays responsive: variants are
// handed out one at a time to worker threads (one per core), progress is reported after each
// and a run can be cancelled between variants.
//
// runStudy (linkage/study.h) takes neither a progress callback nor a cancel flag, so each
// variant is its own runStudy call on the whole mechanism with from = to = t and one value:
// runStudy computes row i of a study as exactly that (the mechanism moved by t from the
// original, loaded afresh and measured with the spec's point, direction, bodies and steps), so
// the rows equal those of one runStudy call on the whole spec, bit for bit.
#pragma once

#include <QObject>
#include <atomic>
#include <thread>
#include <vector>

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
  bool running() const { return !workers_.empty(); }

  // The last finished run: the rows computed (all of them unless it was cancelled or failed),
  // in t order. status: BadModel for a spec that cannot run (as runStudy says).
  const Study& study() const { return study_; }
  const Mechanism& mechanism() const { return m_; }
  const StudySpec& spec() const { return spec_; }
  bool cancelled() const { return cancelled_; }
  // The values of t a spec asks for, as runStudy computes them.
  static std::vector<double> values(const StudySpec& spec);

 Q_SIGNALS:
  void progress(int done, int total);
  void finished();

 private:
  void work();
  void finish();

  Mechanism m_;
  StudySpec spec_;
  std::vector<double> t_;
  std::vector<Study> results_;  // [variant]: one row each, or the reason it cannot run
  std::vector<char> computed_;
  std::atomic<int> next_{0}, done_{0}, working_{0};
  std::atomic<bool> cancel_{false};
  std::vector<std::thread> workers_;
  Study study_;
  bool cancelled_ = false;
};

}  // namespace linkage::ui
