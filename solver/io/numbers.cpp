#include "linkage/io/numbers.h"

#include <algorithm>
#include <cassert>
#include <charconv>
#include <cmath>
#include <system_error>

namespace linkage {

std::string formatNumber(double v, int significant) {
  assert(std::isfinite(v) && "formatNumber: non-finite value; check results before writing them");
  if (!std::isfinite(v)) return {};
  if (v == 0) return "0";  // also turns -0 into "0": a "-0" column reads as a sign glitch
  significant = std::clamp(significant, 1, 17);
  char buf[64];  // 17 digits, sign, point, "e-308" fit easily
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, significant);
  assert(ec == std::errc());
  return std::string(buf, end);
}

std::string formatShown(double v, double scale, int significant) {
  if (std::isfinite(v) && std::abs(v) <= 1e-9 * std::abs(scale)) return "0";
  return formatNumber(v, significant);
}

std::optional<double> parseNumber(std::string_view text) {
  // from_chars refuses a leading '+', people type it; "+-1" and "++1" stay refused below.
  if (!text.empty() && text.front() == '+') {
    text.remove_prefix(1);
    if (text.empty() || text.front() == '-' || text.front() == '+') return std::nullopt;
  }
  if (text.empty()) return std::nullopt;
  double v = 0;
  const char* first = text.data();
  const char* last = first + text.size();
  auto [ptr, ec] = std::from_chars(first, last, v, std::chars_format::general);
  if (ec != std::errc() || ptr != last || !std::isfinite(v)) return std::nullopt;
  return v;
}

}  // namespace linkage
