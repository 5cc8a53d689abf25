// Mass properties from a body's outline (linkage/mass_estimate.h) against closed forms: a
// rectangle's and a triangle's polar moments, a stadium's by the parallel-axis theorem on its
// half discs' centroids (a route the program does not take), and refusals that say what is
// missing.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "linkage/mass_estimate.h"

namespace linkage {
namespace {

constexpr double kSteel = 7850, kT = 6;  // kg/m^3, mm
constexpr double kPerMm2 = kSteel * 1e-9 * kT;

struct Drawn {
  Mechanism m;
  BodyId body;
};

Drawn withPoints(const std::vector<Vec2>& pts) {
  Drawn d;
  d.m.addBody("ground", true);
  d.body = d.m.addBody("plate");
  for (size_t i = 0; i < pts.size(); ++i) d.m.addPoint(d.body, "P" + std::to_string(i), pts[i]);
  return d;
}

Outline plate() {
  Outline o;
  o.shape = Outline::Shape::Plate;
  o.kgPerM3 = kSteel;
  o.thicknessMm = kT;
  return o;
}

void expectNear(double got, double want, const char* what) {
  EXPECT_LT(std::abs(got - want), 1e-9 * std::abs(want)) << what << ": " << got << " vs " << want;
}

TEST(MassEstimate, ARectanglePlateFarFromTheOriginIsExact) {
  // Corners, a point inside and one on an edge: the hull keeps the four corners only.
  const Vec2 o(1e5, -2e5);
  const double w = 80, h = 30;
  Drawn d = withPoints(
      {o, o + Vec2(w, 0), o + Vec2(w, h), o + Vec2(0, h), o + Vec2(10, 10), o + Vec2(40, 0)});
  const MassEstimate e = estimateMass(d.m, d.body, plate());
  ASSERT_TRUE(e.mass) << e.why;
  EXPECT_EQ(e.outline.size(), 4u);
  const double kg = kPerMm2 * w * h;
  expectNear(e.mass->kg, kg, "kg");
  EXPECT_LT((e.mass->com - (o + Vec2(w / 2, h / 2))).norm(), 1e-9 * w);
  expectNear(e.mass->jKgMm2, kg * (w * w + h * h) / 12, "J");
  EXPECT_TRUE(e.mass->counterweights.empty());
}

TEST(MassEstimate, ATrianglePlateHasItsClosedFormPolarMoment) {
  // About the centroid, J = A (a^2 + b^2 + c^2) / 36 per unit area.
  const Vec2 p(3, 4), q(91, 17), r(25, 70);
  Drawn d = withPoints({p, q, r});
  const MassEstimate e = estimateMass(d.m, d.body, plate());
  ASSERT_TRUE(e.mass) << e.why;
  const double area = std::abs((q - p).x() * (r - p).y() - (q - p).y() * (r - p).x()) / 2;
  const double sides = (q - p).squaredNorm() + (r - q).squaredNorm() + (p - r).squaredNorm();
  expectNear(e.mass->kg, kPerMm2 * area, "kg");
  EXPECT_LT((e.mass->com - (p + q + r) / 3).norm(), 1e-12 * 100);
  expectNear(e.mass->jKgMm2, kPerMm2 * area * sides / 36, "J");
}

TEST(MassEstimate, ABarIsAStadiumBetweenItsFarthestPoints) {
  const Vec2 a(10, 20), b(10 + 120 * 0.6, 20 + 120 * 0.8), mid(30, 60);
  Drawn d = withPoints({a, mid, b});
  Outline o = plate();
  o.shape = Outline::Shape::Bar;
  o.widthMm = 16;
  const MassEstimate e = estimateMass(d.m, d.body, o);
  ASSERT_TRUE(e.mass) << e.why;
  // Rectangle L x w, and two half discs of radius r whose centroids lie 4r/(3 pi) beyond the
  // ends: each half disc's J about its own centroid is m (r^2/2 - (4r/3pi)^2), moved by the
  // parallel-axis theorem to L/2 + 4r/(3 pi) from the middle.
  const double L = 120, r = 8, pi = std::numbers::pi;
  const double mRect = kPerMm2 * L * 2 * r, mHalf = kPerMm2 * pi * r * r / 2;
  const double c = 4 * r / (3 * pi);
  const double J = mRect * (L * L + 4 * r * r) / 12 +
                   2 * mHalf * (r * r / 2 - c * c + (L / 2 + c) * (L / 2 + c));
  expectNear(e.mass->kg, mRect + 2 * mHalf, "kg");
  EXPECT_LT((e.mass->com - (a + b) / 2).norm(), 1e-12 * L);
  expectNear(e.mass->jKgMm2, J, "J");
  // The same shape as a fine polygon converges to it (second order in the arc's step).
  std::vector<Vec2> poly;
  const Vec2 u = (b - a) / L, n(-u.y(), u.x());
  const int N = 4000;
  for (int i = 0; i <= N; ++i) {
    const double t = pi * i / N - pi / 2;
    poly.push_back(b + r * (std::cos(t) * u + std::sin(t) * n));
  }
  for (int i = 0; i <= N; ++i) {
    const double t = pi * i / N + pi / 2;
    poly.push_back(a + r * (std::cos(t) * u + std::sin(t) * n));
  }
  const PolygonMoments pm = polygonMoments(poly);
  EXPECT_LT(std::abs(kPerMm2 * pm.polar - J), 1e-6 * J);
}

TEST(MassEstimate, WhatAnOutlineLacksIsSaid) {
  Drawn line = withPoints({Vec2(0, 0), Vec2(10, 0), Vec2(30, 0)});
  MassEstimate e = estimateMass(line.m, line.body, plate());
  EXPECT_FALSE(e.mass);
  EXPECT_EQ(e.why, "a plate needs three points of 'plate' not in line: try a bar");
  Drawn one = withPoints({Vec2(5, 5)});
  Outline bar = plate();
  bar.shape = Outline::Shape::Bar;
  e = estimateMass(one.m, one.body, bar);
  EXPECT_FALSE(e.mass);
  EXPECT_EQ(e.why, "a bar needs two points of 'plate' apart");
  bar.thicknessMm = 0;
  EXPECT_EQ(estimateMass(line.m, line.body, bar).why,
            "the density and the thickness must be positive");
  bar.thicknessMm = 5;
  bar.widthMm = std::nan("");
  EXPECT_EQ(estimateMass(line.m, line.body, bar).why, "the bar's width must be positive");
  EXPECT_EQ(estimateMass(line.m, BodyId{}, bar).why, "no such body");
}

TEST(MassEstimate, TheHullIsCounterClockwiseWithoutCollinearOrRepeatedPoints) {
  const std::vector<Vec2> h = convexHull(
      {Vec2(0, 0), Vec2(2, 0), Vec2(4, 0), Vec2(4, 4), Vec2(0, 4), Vec2(2, 2), Vec2(0, 0)});
  ASSERT_EQ(h.size(), 4u);
  double twiceArea = 0;
  for (size_t i = 0; i < h.size(); ++i) twiceArea += cross(h[i], h[(i + 1) % h.size()]);
  EXPECT_EQ(twiceArea, 32);
}

}  // namespace
}  // namespace linkage
