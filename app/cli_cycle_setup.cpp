#include "cli_cycle_setup.h"

#include "cli_common.h"
#include "linkage/timing_text.h"

namespace linkage::cli {

namespace {

// "N1,N2": two window names.
std::optional<std::pair<std::string, std::string>> conflictOf(const std::string& text) {
  const size_t comma = text.find(',');
  if (comma == std::string::npos || comma == 0 || comma + 1 == text.size() ||
      text.find(',', comma + 1) != std::string::npos) {
    error("--conflict " + text + ": not two window names N1,N2");
    return std::nullopt;
  }
  return std::pair{text.substr(0, comma), text.substr(comma + 1)};
}

// The file's timing, each output named as the file writes it.
CycleSetup fromFile(const Mechanism& m) {
  CycleSetup s;
  for (const LimitMeasure& x : m.timing.outputs) s.outputs.push_back({measureText(m, x), x});
  for (const TimingWindow& w : m.timing.windows)
    s.windows.push_back({w.name, {measureText(m, w.output), w.output}, w.below, w.level});
  for (const TimingConflict& c : m.timing.conflicts) s.conflicts.emplace_back(c.first, c.second);
  return s;
}

}  // namespace

std::optional<CycleSetup> cycleSetup(const Mechanism& m, const std::vector<std::string>& windows,
                                     const std::vector<std::string>& conflicts) {
  CycleSetup s;
  if (windows.empty()) {
    s = fromFile(m);
    if (s.windows.empty()) {
      error(
          "timing: give at least one --window NAME=EXPR, or keep windows in the file's "
          "\"timing\" (see linkage-cli timing --help)");
      return std::nullopt;
    }
  }
  for (const std::string& text : windows) {
    std::string why;
    std::optional<CycleWindow> w = parseWindow(m, text, &why);
    if (!w) {
      error("--window " + text + ": " + why);
      return std::nullopt;
    }
    s.windows.push_back(*w);
  }
  for (const std::string& text : conflicts) {
    std::optional<std::pair<std::string, std::string>> c = conflictOf(text);
    if (!c) return std::nullopt;
    s.conflicts.push_back(*c);
  }
  return s;
}

}  // namespace linkage::cli
