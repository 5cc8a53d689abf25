#include "linkage/spectrum.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <unsupported/Eigen/FFT>

namespace linkage {

namespace {

using Cplx = std::complex<double>;

// The full discrete Fourier transform F_k = sum_j f_j exp(-i k phi_j), k < N.
std::vector<Cplx> transform(const std::vector<double>& f) {
  Eigen::FFT<double> fft;
  std::vector<Cplx> F;
  fft.fwd(F, f);
  return F;
}

Spectrum fromTransform(const std::vector<Cplx>& F, int maxK) {
  const int n = static_cast<int>(F.size());
  Spectrum s;
  s.mean = F[0].real() / n;
  const int top = std::min(maxK, n / 2);
  for (int k = 1; k <= top; ++k) {
    Harmonic h;
    h.k = k;
    // f = sum_k c_k e^{i k phi} with c_k = F_k / N; c_k and c_{-k} = conj(c_k) together give
    // 2 Re(c_k) cos(k phi) - 2 Im(c_k) sin(k phi). At k = N / 2 they are one term.
    const double scale = (2 * k == n) ? 1.0 / n : 2.0 / n;
    h.a = scale * F[k].real();
    h.b = (2 * k == n) ? 0.0 : -scale * F[k].imag();
    h.amplitude = std::hypot(h.a, h.b);
    h.phase = std::atan2(-h.b, h.a);
    s.terms.push_back(h);
  }
  return s;
}

}  // namespace

Spectrum harmonics(const std::vector<double>& period, int maxK) {
  if (period.size() < 2 || maxK < 0) return {};
  return fromTransform(transform(period), maxK);
}

Derivative periodicDerivative(const std::vector<double>& period) {
  Derivative d;
  const int n = static_cast<int>(period.size());
  if (n < 2) return d;
  std::vector<Cplx> F = transform(period);
  for (const Harmonic& h : fromTransform(F, n / 2).terms)
    if (4 * h.k >= n) d.errorEstimate += h.k * h.amplitude;
  // d/dphi e^{i k phi} = i k e^{i k phi}, with k the signed frequency (k - N above N / 2); the
  // Nyquist term's derivative is not determined by the samples (sin(N phi / 2) vanishes on
  // them) and is left out.
  for (int k = 0; k < n; ++k) {
    const int kk = (2 * k == n) ? 0 : (2 * k < n ? k : k - n);
    F[k] *= Cplx(0, kk);
  }
  Eigen::FFT<double> fft;
  fft.inv(d.values, F);
  d.values.resize(n);
  return d;
}

PeriodicInterpolant::PeriodicInterpolant(const std::vector<double>& period)
    : n_(static_cast<int>(period.size())), s_(harmonics(period, n_ / 2)) {}

double PeriodicInterpolant::operator()(double phi) const {
  if (n_ == 0) return NAN;
  if (n_ == 1) return s_.mean;
  const double c1 = std::cos(phi), s1 = std::sin(phi);
  double c = 1, s = 0, sum = s_.mean;
  for (const Harmonic& h : s_.terms) {
    // cos and sin of k phi by rotating those of (k - 1) phi: one rounding per term.
    const double cn = c * c1 - s * s1;
    s = s * c1 + c * s1;
    c = cn;
    sum += h.a * c + h.b * s;
  }
  return sum;
}

}  // namespace linkage
