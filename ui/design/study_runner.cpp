#include "design/study_runner.h"

#include <algorithm>

namespace linkage::ui {

StudyRunner::StudyRunner(QObject* parent) : QObject(parent) {}

StudyRunner::~StudyRunner() {
  cancel_ = true;
  for (std::thread& w : workers_) w.join();
}

std::vector<double> StudyRunner::values(const StudySpec& spec) {
  std::vector<double> t;
  for (int i = 0; i < spec.values; ++i)
    t.push_back(spec.values == 1 ? spec.from
                                 : spec.from + (spec.to - spec.from) * i / (spec.values - 1));
  return t;
}

bool StudyRunner::start(const Mechanism& m, const StudySpec& spec) {
  if (running()) return false;
  m_ = m;
  spec_ = spec;
  t_ = values(spec);
  results_.assign(t_.size(), Study{});
  computed_.assign(t_.size(), 0);
  next_ = 0;
  done_ = 0;
  cancel_ = false;
  cancelled_ = false;
  study_ = Study{};
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int threads =
      std::max(1, std::min(spec.threads > 0 ? spec.threads : cores, static_cast<int>(t_.size())));
  working_ = threads;
  for (int i = 0; i < threads; ++i) workers_.emplace_back([this] { work(); });
  return true;
}

void StudyRunner::cancel() {
  cancel_ = true;
}

void StudyRunner::work() {
  const int total = static_cast<int>(t_.size());
  for (int i = next_++; i < total && !cancel_; i = next_++) {
    StudySpec one = spec_;
    one.from = one.to = t_[i];
    one.values = 1;
    one.threads = 1;
    results_[i] = runStudy(m_, one);
    computed_[i] = 1;
    // A spec that cannot run fails alike for every value: stop at the first.
    if (!results_[i].status.ok()) cancel_ = true;
    emit progress(++done_, total);
  }
  if (--working_ == 0)
    QMetaObject::invokeMethod(
        this, [this] { finish(); }, Qt::QueuedConnection);
}

void StudyRunner::finish() {
  for (std::thread& w : workers_) w.join();
  study_.threads = static_cast<int>(workers_.size());
  workers_.clear();
  bool failed = false;
  for (size_t i = 0; i < results_.size(); ++i) {
    if (!computed_[i]) continue;
    const Study& s = results_[i];
    if (!s.status.ok()) {
      study_.status = s.status;
      study_.rows.clear();
      failed = true;
      break;
    }
    if (study_.joints.empty()) study_.joints = s.joints;
    study_.rows.push_back(s.rows.front());
  }
  cancelled_ = !failed && study_.rows.size() < t_.size();
  results_.clear();
  emit finished();
}

}  // namespace linkage::ui
