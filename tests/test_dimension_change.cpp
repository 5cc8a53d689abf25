// Exact finite changes of dimensions (linkage/dimension_change.h): a change reads back as the
// dimension's new value (dimensions() of the changed drawing, measured independently of how it
// was drawn), and a small change moves the solved point as the exact derivative says.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "examples.h"
#include "linkage/dimension_change.h"
#include "linkage/kinematics.h"
#include "linkage/sensitivity.h"
#include "mechanisms.h"

namespace linkage {
namespace {

struct Case {
  std::string name;
  Mechanism m;
  PointId out;
};

std::vector<Case> cases() {
  std::vector<Case> c;
  const test::FourBar f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  c.push_back({"four-bar", f.m, f.P});
  for (bool pin : {false, true}) {
    const test::SliderCrank s = test::sliderCrank(20, 70, 8, 30, Direction::Ccw, 60, pin);
    c.push_back({pin ? "slider-crank, pin in slot" : "slider-crank, block", s.m, s.B});
  }
  for (const char* e : {"wanzer-inversion-2", "planet-epicycloid"}) {
    Mechanism m = test::example(e);
    const PointId p = *m.findPoint(e[0] == 'w' ? "needlebar.G" : "planet.P");
    c.push_back({e, m, p});
  }
  // An arc slot's centre and radius, a block in it (the rod's end B pinned to it).
  Mechanism curved = test::example("curved-guide");
  const PointId B = *curved.findPoint("rod.B");
  c.push_back({"curved-guide", curved, B});
  return c;
}

Mechanism changed(const Mechanism& m, const std::vector<Dimension>& dims, size_t k, double by) {
  std::vector<double> delta(dims.size(), 0.0);
  delta[k] = by;
  Mechanism out = m;
  EXPECT_TRUE(changeDimensions(out, dims, delta).ok()) << dims[k].name;
  return out;
}

// A big change of one dimension reads back as its value plus the change, the others as they
// were (a slot's offset excepted when its angle turns: measured from elsewhere, it changes).
TEST(DimensionChange, EveryKindReadsBackExactly) {
  int checked = 0;
  for (const Case& c : cases()) {
    const std::vector<Dimension> dims = dimensions(c.m);
    for (size_t k = 0; k < dims.size(); ++k) {
      const double by = dims[k].unit == Dimension::Unit::Deg     ? 7.5
                        : dims[k].unit == Dimension::Unit::Ratio ? 0.25
                                                                 : 1.75;
      const std::vector<Dimension> now = dimensions(changed(c.m, dims, k, by));
      ASSERT_EQ(now.size(), dims.size()) << c.name << " " << dims[k].name;
      for (size_t i = 0; i < dims.size(); ++i) {
        ASSERT_EQ(now[i].name, dims[i].name);
        const bool turnedOffset =
            dims[k].name.ends_with(".angle") && dims[i].name.ends_with(".offset");
        if (turnedOffset) continue;
        const double want = dims[i].value + (i == k ? by : 0.0);
        EXPECT_NEAR(now[i].value, want, 1e-12 * std::max(1.0, std::abs(want)))
            << c.name << ": changed " << dims[k].name << ", read " << dims[i].name;
      }
      ++checked;
    }
  }
  EXPECT_GE(checked, 30);
}

// The triangle of the Wanzer needle bar, all three sides at once: each reads back.
TEST(DimensionChange, TriangleSidesAllAtOnce) {
  const Mechanism m = test::example("wanzer-inversion-2");
  const std::vector<Dimension> dims = dimensions(m);
  std::vector<double> delta(dims.size(), 0.0);
  std::map<std::string, double> want;
  const std::map<std::string, double> by = {
      {"triangle.E-F", 3}, {"triangle.F-G", -2}, {"triangle.E-G", 1.5}};
  for (size_t k = 0; k < dims.size(); ++k)
    if (by.count(dims[k].name)) {
      delta[k] = by.at(dims[k].name);
      want[dims[k].name] = dims[k].value + delta[k];
    }
  ASSERT_EQ(want.size(), 3u);
  Mechanism c = m;
  ASSERT_TRUE(changeDimensions(c, dims, delta).ok());
  auto at = [&](const char* p) { return c.point(*c.findPoint(p))->pos; };
  EXPECT_NEAR((at("triangle.F") - at("triangle.E")).norm(), want["triangle.E-F"], 1e-12);
  EXPECT_NEAR((at("triangle.G") - at("triangle.F")).norm(), want["triangle.F-G"], 1e-12);
  EXPECT_NEAR((at("triangle.G") - at("triangle.E")).norm(), want["triangle.E-G"], 1e-12);
  // Sides that do not meet are refused by name, not drawn.
  delta.assign(dims.size(), 0.0);
  for (size_t k = 0; k < dims.size(); ++k)
    if (dims[k].name == "triangle.E-G") delta[k] = 500;
  Mechanism bad = m;
  const Status s = changeDimensions(bad, dims, delta);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message.find("triangle.G"), std::string::npos) << s.message;
}

// A change of +-h solved exactly against the derivative: the central difference agrees to
// O(h^2) (h = 1e-5 in each dimension's unit): a consistency check of the two.
TEST(DimensionChange, SmallChangesMoveThePointAsTheDerivativeSays) {
  const double h = 1e-5;
  for (const Case& c : cases()) {
    const std::vector<Dimension> dims = dimensions(c.m);
    Kinematics k;
    ASSERT_TRUE(k.load(c.m).ok()) << c.name;
    Sensitivity s;
    ASSERT_TRUE(s.prepare(k, dims).ok()) << c.name;
    std::vector<Kinematics> plus(dims.size()), minus(dims.size());
    for (size_t d = 0; d < dims.size(); ++d) {
      ASSERT_TRUE(plus[d].load(changed(c.m, dims, d, h)).ok()) << dims[d].name;
      ASSERT_TRUE(minus[d].load(changed(c.m, dims, d, -h)).ok()) << dims[d].name;
    }
    double worst = 0, peak = 0;
    for (double deg : {0.0, 50.0, 135.0, 220.0, 310.0}) {
      ASSERT_TRUE(k.moveTo(deg).ok());
      ASSERT_TRUE(s.at(k).ok());
      for (size_t d = 0; d < dims.size(); ++d) {
        ASSERT_TRUE(plus[d].moveTo(deg).ok() && minus[d].moveTo(deg).ok()) << dims[d].name;
        const Vec2 fd = (plus[d].position(c.out) - minus[d].position(c.out)) / (2 * h);
        const Vec2 exact = s.point(k, c.out, static_cast<int>(d));
        peak = std::max(peak, exact.norm());
        worst = std::max(worst, (fd - exact).norm());
      }
    }
    std::printf("%-28s worst |difference - derivative| %.2e of peak %.3g\n", c.name.c_str(),
                worst / peak, peak);
    EXPECT_LT(worst, 1e-6 * peak) << c.name;
  }
}

}  // namespace
}  // namespace linkage

namespace linkage {
namespace {

// A point on its body's line P0P1 is given along and across P0->P1; a change of P0-P1 keeps those
// (its derivative moves it not), where placing it by its two distances failed ("do not meet":
// the circles about P0 and the moved P1 are apart on the line).
TEST(DimensionChange, APointOnTheBodysLineKeepsItsAlongAndAcross) {
  test::SliderCrank sc = test::sliderCrank(20, 70, 8, 30);
  const Vec2 A = sc.m.point(sc.A)->pos, B = sc.m.point(*sc.m.findPoint("rod.B"))->pos;
  const PointId M = sc.m.addPoint(sc.rod, "M", A + 0.4 * (B - A));
  const std::vector<Dimension> dims = dimensions(sc.m);
  std::vector<double> delta(dims.size(), 0.0);
  bool named = false;
  for (size_t d = 0; d < dims.size(); ++d) {
    if (dims[d].name == "rod.A-B") delta[d] = 3;
    named = named || dims[d].name == "rod.M.along";
  }
  ASSERT_TRUE(named);
  Mechanism changed = sc.m;
  const Status s = changeDimensions(changed, dims, delta);
  ASSERT_TRUE(s.ok()) << s.message;
  const Vec2 e = (B - A).normalized();
  EXPECT_NEAR((changed.point(M)->pos - (A + 0.4 * (B - A).norm() * e)).norm(), 0, 1e-12);
  EXPECT_NEAR((changed.point(*changed.findPoint("rod.B"))->pos - (B + 3 * e)).norm(), 0, 1e-12);
}

}  // namespace
}  // namespace linkage
