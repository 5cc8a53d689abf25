// Outputs and windows as a user writes them: see linkage/timing.h; the text itself is the
// model's (linkage/timing_text.h), shared with the file's "timing".
#include "linkage/timing.h"
#include "linkage/timing_text.h"

namespace linkage {

std::optional<CycleOutput> parseOutput(const Mechanism& m, const std::string& text,
                                       std::string* why) {
  std::optional<LimitMeasure> x = parseMeasure(m, text, why);
  if (!x) return std::nullopt;
  return CycleOutput{text, *x};
}

std::optional<CycleWindow> parseWindow(const Mechanism& m, const std::string& text,
                                       std::string* why) {
  std::optional<TimingWindow> w = parseTimingWindow(m, text, why);
  if (!w) return std::nullopt;
  const size_t op = text.find_first_of("<>", text.find('=') + 1);
  const std::string output = text.substr(text.find('=') + 1, op - text.find('=') - 1);
  return CycleWindow{w->name, CycleOutput{output, w->output}, w->below, w->level};
}

CycleDiagram cycleDiagram(const Kinematics& k, const Timing& t, const CycleOptions& opt) {
  const Mechanism& m = k.mechanism();
  std::vector<CycleOutput> outputs;
  for (const LimitMeasure& x : t.outputs) outputs.push_back({measureText(m, x), x});
  std::vector<CycleWindow> windows;
  for (const TimingWindow& w : t.windows)
    windows.push_back({w.name, {measureText(m, w.output), w.output}, w.below, w.level});
  std::vector<std::pair<std::string, std::string>> conflicts;
  for (const TimingConflict& c : t.conflicts) conflicts.emplace_back(c.first, c.second);
  return cycleDiagram(k, outputs, windows, conflicts, opt);
}

}  // namespace linkage
