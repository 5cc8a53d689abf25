// A cam's motion programme (linkage/cam.h): its checks, and s(theta) with its derivatives from
// the segment theta falls in.
#include <algorithm>
#include <charconv>
#include <cmath>

#include "linkage/cam.h"

namespace linkage::cam {

namespace {

constexpr double kTurn = 2 * M_PI;
constexpr double kRad = M_PI / 180;
// The rises' closure and the lowest position are checked to this (the file's unit).
constexpr double kClosure = 1e-9;

std::string shortest(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

}  // namespace

std::string checkProgram(std::span<const Segment> segments, int& at, const char*& key) {
  at = -1;
  key = "to_deg";
  if (segments.empty()) return "no segments: a programme's segments end at 360 degrees";
  double previous = 0, sum = 0;
  for (size_t k = 0; k < segments.size(); ++k) {
    const Segment& s = segments[k];
    at = static_cast<int>(k);
    key = "to_deg";
    if (!(s.toDeg > previous))
      return k == 0 ? "expected an end above 0 degrees, got " + shortest(s.toDeg)
                    : "expected an end above the previous segment's (" + shortest(previous) +
                          " degrees), got " + shortest(s.toDeg);
    if (s.toDeg > 360)
      return "beyond 360 degrees (" + shortest(s.toDeg) + "): a programme is one turn";
    if (s.rise != 0 && !s.law) {
      key = "law";
      return "a rise needs a law: " + lawNames();
    }
    sum += s.rise;
    key = "rise";
    if (sum < -kClosure)
      return "the follower would go " + shortest(-sum) +
             " below its drawn position, which is its lowest (the rises' partial sums stay at "
             "or above 0)";
    previous = s.toDeg;
  }
  key = "to_deg";
  if (previous != 360)
    return "the last segment ends at " + shortest(previous) + " degrees, not at 360";
  at = -1;
  key = "rise";
  if (std::abs(sum) > kClosure)
    return "the rises sum to " + shortest(sum) +
           ", not 0: the follower would not come back where the turn started";
  return {};
}

Program::Program(std::vector<Segment> segments, double scale)
    : segments_(std::move(segments)), scale_(scale) {
  double previous = 0, base = 0;
  for (const Segment& s : segments_) {
    start_.push_back(previous * kRad);
    span_.push_back((s.toDeg - previous) * kRad);
    base_.push_back(base);
    base += scale_ * s.rise;
    previous = s.toDeg;
  }
}

int Program::segmentAt(double theta) const {
  if (segments_.empty()) return -1;
  double t = std::fmod(theta, kTurn);
  if (t < 0) t += kTurn;
  const auto it = std::upper_bound(start_.begin(), start_.end(), t);
  return std::max(0, static_cast<int>(it - start_.begin()) - 1);
}

Displacement Program::at(double theta) const {
  const int k = segmentAt(theta);
  if (k < 0) return {};
  const Segment& seg = segments_[k];
  const double base = base_[k];
  if (!seg.law || seg.rise == 0) return {base, 0, 0, 0};
  double t = std::fmod(theta, kTurn);
  if (t < 0) t += kTurn;
  const double beta = span_[k], h = scale_ * seg.rise;
  const Normalised n = evaluate(*seg.law, (t - start_[k]) / beta);
  return {base + h * n.s, h * n.v / beta, h * n.a / (beta * beta), h * n.j / (beta * beta * beta)};
}

Displacement Program::perRise(double theta, std::span<const double> dRise) const {
  const int k = segmentAt(theta);
  if (k < 0 || dRise.size() != segments_.size()) return {};
  Displacement out;
  for (int i = 0; i < k; ++i) out.s += scale_ * dRise[i];
  const Segment& seg = segments_[k];
  if (!seg.law || seg.rise == 0) return out;  // as at(): such a segment holds its base
  double t = std::fmod(theta, kTurn);
  if (t < 0) t += kTurn;
  const double beta = span_[k], h = scale_ * dRise[k];
  const Normalised n = evaluate(*seg.law, (t - start_[k]) / beta);
  out.s += h * n.s;
  out.v = h * n.v / beta;
  out.a = h * n.a / (beta * beta);
  out.j = h * n.j / (beta * beta * beta);
  return out;
}

}  // namespace linkage::cam
