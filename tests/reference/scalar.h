// Math functions for the reference solutions, overloaded for double, long double and __float128.
//
// The references are templates on the scalar type; calling linkref::sin etc. (rather than std::sin)
// lets one source serve all three precisions, since __float128 has no std:: overloads and
// argument-dependent lookup does not apply to built-in types.
#pragma once

#include <quadmath.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace linkref {

inline double sin(double x) {
  return std::sin(x);
}
inline double cos(double x) {
  return std::cos(x);
}
inline double sqrt(double x) {
  return std::sqrt(x);
}
inline double atan2(double y, double x) {
  return std::atan2(y, x);
}
inline double abs(double x) {
  return std::fabs(x);
}

inline long double sin(long double x) {
  return std::sin(x);
}
inline long double cos(long double x) {
  return std::cos(x);
}
inline long double sqrt(long double x) {
  return std::sqrt(x);
}
inline long double atan2(long double y, long double x) {
  return std::atan2(y, x);
}
inline long double abs(long double x) {
  return std::fabs(x);
}

inline __float128 sin(__float128 x) {
  return sinq(x);
}
inline __float128 cos(__float128 x) {
  return cosq(x);
}
inline __float128 sqrt(__float128 x) {
  return sqrtq(x);
}
inline __float128 atan2(__float128 y, __float128 x) {
  return atan2q(y, x);
}
inline __float128 abs(__float128 x) {
  return fabsq(x);
}

template <class T>
T pi();
template <>
inline double pi<double>() {
  return 3.14159265358979323846;
}
template <>
inline long double pi<long double>() {
  return 3.14159265358979323846264338327950288L;
}
template <>
inline __float128 pi<__float128>() {
  return M_PIq;
}

template <class T>
T deg2rad(T deg) {
  return deg * (pi<T>() / T(180));
}

// Angular speed in rad/s of a shaft turning at `rpm` revolutions per minute.
template <class T>
T rpm_to_rad_s(T rpm) {
  return rpm * T(2) * pi<T>() / T(60);
}

// Machine epsilon of T; std::numeric_limits<__float128> is not specialised in strict modes.
template <class T>
T epsilon();
template <>
inline double epsilon<double>() {
  return 2.220446049250313e-16;
}
template <>
inline long double epsilon<long double>() {
  return 1.0842021724855044340e-19L;
}
template <>
inline __float128 epsilon<__float128>() {
  return FLT128_EPSILON;
}

// Text of a value with all its digits, for test diagnostics.
inline std::string to_string(__float128 x) {
  char buf[64];
  quadmath_snprintf(buf, sizeof buf, "%.36Qg", x);
  return buf;
}
inline std::string to_string(long double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.21Lg", x);
  return buf;
}
inline std::string to_string(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

}  // namespace linkref
