// The motion laws of linkage/cam.h, exact: each law's closed form and its first three
// derivatives; the piecewise laws (modified trapezoid, modified sine) integrated by hand piece by
// piece on their first half, the second half by the symmetry of a rise.
#include <algorithm>
#include <cmath>

#include "linkage/cam.h"

namespace linkage::cam {

namespace {

constexpr double kPi = M_PI;
constexpr double kK = 4 * kPi;  // the quarter waves' sine: period 1/2

// Norton's constants, from S(1/2) = 1/2 (see linkage/cam.h).
const double kTrapezoidC = 1 / (0.125 + 1 / (4 * kPi));
const double kSineC = 1 / (1 / (4 * kPi) + 1 / (kPi * kPi));

Normalised cycloidal(double x) {
  const double w = 2 * kPi * x, c = std::cos(w), s = std::sin(w);
  return {x - s / (2 * kPi), 1 - c, 2 * kPi * s, 4 * kPi * kPi * c};
}

Normalised harmonic(double x) {
  const double w = kPi * x, c = std::cos(w), s = std::sin(w);
  return {(1 - c) / 2, kPi / 2 * s, kPi * kPi / 2 * c, -kPi * kPi * kPi / 2 * s};
}

Normalised poly345(double x) {
  const double x2 = x * x, x3 = x2 * x;
  return {x3 * (10 - 15 * x + 6 * x2), 30 * x2 * (1 - 2 * x + x2), 60 * x * (1 - 3 * x + 2 * x2),
          60 - 360 * x + 360 * x2};
}

Normalised poly4567(double x) {
  const double x2 = x * x, x3 = x2 * x, y = 1 - x;
  return {x2 * x2 * (35 - 84 * x + 70 * x2 - 20 * x3), 140 * x3 * y * y * y,
          x2 * (420 - 1680 * x + 2100 * x2 - 840 * x3),
          x * (840 - 5040 * x + 8400 * x2 - 4200 * x3)};
}

// The rising quarter wave both piecewise laws start with: A = C sin(k x) on [0, 1/8].
Normalised quarterWave(double C, double x) {
  const double c = std::cos(kK * x), s = std::sin(kK * x);
  return {C * (x / kK - s / (kK * kK)), C * (1 - c) / kK, C * s, C * kK * c};
}

// On [0, 1/2]: the quarter wave, the plateau (t = x - 1/8), the falling wave (t = x - 3/8).
Normalised trapezoidHalf(double x) {
  const double C = kTrapezoidC;
  if (x <= 0.125) return quarterWave(C, x);
  const double v1 = C / kK, s1 = C * (0.125 / kK - 1 / (kK * kK));
  if (x <= 0.375) {
    const double t = x - 0.125;
    return {s1 + v1 * t + C * t * t / 2, v1 + C * t, C, 0};
  }
  const double t = x - 0.375, v2 = v1 + C / 4, s2 = s1 + v1 / 4 + C / 32;
  const double c = std::cos(kK * t), s = std::sin(kK * t);
  return {s2 + v2 * t + C * (1 - c) / (kK * kK), v2 + C * s / kK, C * c, -C * kK * s};
}

// On [0, 1/2]: the quarter wave, then the slow wave (t = x - 1/8, m = 4 pi / 3).
Normalised sineHalf(double x) {
  const double C = kSineC;
  if (x <= 0.125) return quarterWave(C, x);
  const double m = 4 * kPi / 3, t = x - 0.125;
  const double v1 = C / kK, s1 = C * (0.125 / kK - 1 / (kK * kK));
  const double c = std::cos(m * t), s = std::sin(m * t);
  return {s1 + v1 * t + C * (1 - c) / (m * m), v1 + C * s / m, C * c, -C * m * s};
}

// A symmetric rise from its first half.
template <class Half>
Normalised symmetric(Half half, double x) {
  if (x <= 0.5) return half(x);
  const Normalised h = half(1 - x);
  return {1 - h.s, h.v, -h.a, h.j};
}

constexpr Law kLaws[] = {Law::Cycloidal,      Law::Harmonic,          Law::Polynomial345,
                         Law::Polynomial4567, Law::ModifiedTrapezoid, Law::ModifiedSine};
constexpr const char* kNames[] = {"cycloidal",       "harmonic",           "polynomial-345",
                                  "polynomial-4567", "modified-trapezoid", "modified-sine"};

}  // namespace

Normalised evaluate(Law law, double x) {
  x = std::clamp(x, 0.0, 1.0);
  switch (law) {
    case Law::Cycloidal:
      return cycloidal(x);
    case Law::Harmonic:
      return harmonic(x);
    case Law::Polynomial345:
      return poly345(x);
    case Law::Polynomial4567:
      return poly4567(x);
    case Law::ModifiedTrapezoid:
      return symmetric(trapezoidHalf, x);
    case Law::ModifiedSine:
      return symmetric(sineHalf, x);
  }
  return {};
}

const char* lawName(Law law) {
  return kNames[static_cast<size_t>(law)];
}

std::optional<Law> lawNamed(std::string_view name) {
  for (Law l : kLaws)
    if (name == lawName(l)) return l;
  return std::nullopt;
}

std::span<const Law> allLaws() {
  return kLaws;
}

std::string lawNames() {
  std::string s;
  const size_t n = std::size(kLaws);
  for (size_t i = 0; i < n; ++i)
    s += std::string(i == 0 ? "" : i + 1 == n ? " or " : ", ") + "\"" + kNames[i] + "\"";
  return s;
}

}  // namespace linkage::cam
