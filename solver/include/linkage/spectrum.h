// Curves over one crank revolution as Fourier series in the crank angle: the harmonics a needle
// designer reads (the amplitude of each multiple of the crank frequency), the spectral
// derivative that gives the jerk from the solver's exact accelerations, and the trigonometric
// interpolant that evaluates a curve between its samples.
//
// Input is always one period of uniform samples f_j = f(phi_j), phi_j = 2 pi j / N, j < N (the
// end of the period, equal to the start, left out). The discrete Fourier transform of such
// samples gives the series' coefficients up to N / 2 exactly when the curve has no harmonics
// above N / 2; a smooth curve's harmonics decay geometrically, so what lies above is the error,
// and its size can be read off the highest harmonics computed (see Derivative::errorEstimate).
#pragma once

#include <vector>

namespace linkage {

// f(phi) = mean + sum_k a_k cos(k phi) + b_k sin(k phi)
//        = mean + sum_k amplitude_k cos(k phi + phase_k)
struct Harmonic {
  int k = 0;
  double a = 0, b = 0;
  double amplitude = 0;  // sqrt(a^2 + b^2)
  double phase = 0;      // rad, atan2(-b, a)
};

struct Spectrum {
  double mean = 0;
  std::vector<Harmonic> terms;  // k = 1 ... min(maxK, N / 2)
};

// The harmonics of one period of samples (at least 2). At k = N / 2 (N even) only the cosine
// part is determined: the sample grid cannot see sin(N phi / 2).
Spectrum harmonics(const std::vector<double>& period, int maxK);

// df/dphi at the same points, by differentiating the trigonometric interpolant.
struct Derivative {
  std::vector<double> values;
  // A bound on max_j |error| for curves whose spectrum decays (every mechanism's motion away
  // from singular positions): the sum of the derivative's harmonics from N / 4 to N / 2. The
  // part of the spectrum above N / 2 that the samples cannot see is smaller than that upper
  // half band when the decay is geometric; with the samples' rounding (relative 1e-16 of f)
  // the band never falls below about N^2 1e-17 max|f|.
  double errorEstimate = 0;
};
Derivative periodicDerivative(const std::vector<double>& period);

// The trigonometric interpolant of one period of samples: passes through every sample and is
// exact between them up to the truncated spectrum (as above). Evaluation costs O(N).
class PeriodicInterpolant {
 public:
  PeriodicInterpolant() = default;
  explicit PeriodicInterpolant(const std::vector<double>& period);
  bool empty() const { return n_ == 0; }
  double operator()(double phi) const;  // phi in radians, any value (periodic)

 private:
  int n_ = 0;
  Spectrum s_;
};

}  // namespace linkage
