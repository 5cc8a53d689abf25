// A minimal 2-D vector for the reference solutions, templated on the scalar so that the same code
// runs in double, long double and __float128 (Eigen is deliberately not used: the references
// must share nothing with the program they check).
#pragma once

#include "reference/scalar.h"

namespace linkref {

template <class T>
struct Vec2 {
  T x{}, y{};
};

template <class T>
Vec2<T> operator+(Vec2<T> a, Vec2<T> b) {
  return {a.x + b.x, a.y + b.y};
}
template <class T>
Vec2<T> operator-(Vec2<T> a, Vec2<T> b) {
  return {a.x - b.x, a.y - b.y};
}
template <class T>
Vec2<T> operator-(Vec2<T> a) {
  return {-a.x, -a.y};
}
template <class T>
Vec2<T> operator*(T k, Vec2<T> a) {
  return {k * a.x, k * a.y};
}
template <class T>
T dot(Vec2<T> a, Vec2<T> b) {
  return a.x * b.x + a.y * b.y;
}
// z component of a x b: positive when b lies counter-clockwise of a.
template <class T>
T cross(Vec2<T> a, Vec2<T> b) {
  return a.x * b.y - a.y * b.x;
}
template <class T>
T norm(Vec2<T> a) {
  return sqrt(dot(a, a));
}
// a turned by +90 degrees: the velocity direction of a point at offset a on a body turning ccw.
template <class T>
Vec2<T> perp(Vec2<T> a) {
  return {-a.y, a.x};
}
template <class T>
Vec2<T> unit_at(T angle) {
  return {cos(angle), sin(angle)};
}
// a rotated counter-clockwise by the angle whose cosine and sine are c and s.
template <class T>
Vec2<T> rotate(Vec2<T> a, T c, T s) {
  return {c * a.x - s * a.y, s * a.x + c * a.y};
}
template <class T>
T angle_of(Vec2<T> a) {
  return atan2(a.y, a.x);
}

}  // namespace linkref
