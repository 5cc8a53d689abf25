// Transmission angles on machines in space and their exact derivatives (linkage/
// transmission_sensitivity.h: each angle in its link's plane class's frame), against
// independent truths:
// - closed forms of mechanisms drawn in a vertical plane V (origin o, x axis (cos 30, sin 30, 0),
//   y axis the world's z), their ground points and slot written in the world: a four-bar's mu by
//   the law of cosines and a slider-crank's by the law of sines, every ground point projected
//   into V ((w - o) . x, (w - o) . y), differentiated by the complex step in every dimension
//   (the ground's world x, y, z, the slot's offset and angle in V, V's origin);
// - the overedge machine's changed designs (changeDimensions, solved again at the same crank
//   angle): central differences, every angle, every dimension.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "changed_design.h"
#include "complex_step.h"
#include "examples.h"
#include "linkage/dimension_change.h"
#include "linkage/io/model_file.h"
#include "linkage/transmission_sensitivity.h"
#include "spatial_fixtures.h"

namespace linkage {
namespace {

using test::C;
using test::CVec;
using test::num;
using test::vec;
using test::vec2;
constexpr double kDeg = M_PI / 180;

// The plane V and a world point in it.
const double kA = 30 * kDeg;
const Vec3 kO(10, 20, 30), kX(std::cos(kA), std::sin(kA), 0), kY(0, 0, 1);
Vec3 world(const Vec2& p) {
  return kO + p.x() * kX + p.y() * kY;
}

// The complex variables of a closed form, by dimension name (the others 0 extra).
struct Vars {
  std::map<std::string, C> x;
  C operator()(const std::string& name, double value) const {
    auto it = x.find(name);
    return value + (it == x.end() ? C(0) : it->second);
  }
};

// A world point (its dimensions `ground.NAME.x`, `.y`, `.z`) seen in V moved by its origin's
// dimensions.
CVec inV(const Vars& v, const std::string& name, const Vec3& w) {
  const C d[3] = {v("ground." + name + ".x", w.x()) - v("planes.v.origin.x", kO.x()),
                  v("ground." + name + ".y", w.y()) - v("planes.v.origin.y", kO.y()),
                  v("ground." + name + ".z", w.z()) - v("planes.v.origin.z", kO.z())};
  return {d[0] * kX.x() + d[1] * kX.y() + d[2] * kX.z(),
          d[0] * kY.x() + d[1] * kY.y() + d[2] * kY.z()};
}

std::string head(const std::string& name) {
  return R"({"format": "linkage", "version": 1, "name": ")" + name + R"(",
  "planes": {"v": {"origin": )" +
         vec(kO) + R"(, "x_axis": )" + vec(kX) + R"(, "y_axis": )" + vec(kY) + "}},\n";
}

// The four-bar: ground pivots O2 = (0, 0) and O4 = (d, 0) of V, the crank at 35 degrees.
constexpr double kD = 60, kCrank = 20, kCoupler = 70, kRocker = 50, kStart = 35;

std::string fourBarText() {
  const Vec2 A = kCrank * Vec2(std::cos(kStart * kDeg), std::sin(kStart * kDeg)), O4(kD, 0);
  // B where the coupler from A meets the rocker from O4 (the circles' upper meeting).
  const Vec2 u = O4 - A;
  const double L = u.norm(), along = (kCoupler * kCoupler - kRocker * kRocker + L * L) / (2 * L);
  const Vec2 B = A + along * u / L + std::sqrt(kCoupler * kCoupler - along * along) * perp(u) / L;
  return head("four-bar in V") + R"(  "bodies": [
    {"name": "ground", "ground": true, "points": {"O2": )" +
         vec(world(Vec2::Zero())) + R"(, "O4": )" + vec(world(O4)) + R"(}},
    {"name": "crank", "plane": "v", "points": {"O2": [0, 0], "A": )" +
         vec2(A) + R"(}},
    {"name": "coupler", "plane": "v", "points": {"A": )" +
         vec2(A) + R"(, "B": )" + vec2(B) + R"(}},
    {"name": "rocker", "plane": "v", "points": {"B": )" +
         vec2(B) + R"(, "O4": )" + vec2(O4) + R"(}}
  ],
  "joints": [
    {"type": "pin", "a": "ground.O2", "b": "crank.O2"},
    {"type": "pin", "a": "crank.A", "b": "coupler.A"},
    {"type": "pin", "a": "coupler.B", "b": "rocker.B"},
    {"type": "pin", "a": "rocker.O4", "b": "ground.O4"}
  ],
  "driver": {"joint": 0, "rpm": 60, "direction": "ccw"}
})";
}

// mu (degrees) by the law of cosines, the crank at theta from V's x.
C fourBarMu(const Vars& v, double theta) {
  const CVec O2 = inV(v, "O2", world(Vec2::Zero())), O4 = inV(v, "O4", world(Vec2(kD, 0)));
  const CVec g = O4 - O2;
  const C a = v("crank.O2-A", kCrank), b = v("coupler.A-B", kCoupler),
          c = v("rocker.B-O4", kRocker);
  const C d = std::sqrt(dot(g, g)), psi = std::atan(g.y / g.x);  // g.x > 0 here
  return std::acos((b * b + c * c - a * a - d * d + 2.0 * a * d * std::cos(theta - psi)) /
                   (2.0 * b * c)) /
         kDeg;
}

// The slider-crank: the crank's pivot O = (0, 0) of V at 30 degrees, its pin A; the rod to B in
// the ground slot u through P0 = (12, 0) of V at 100 degrees from V's x (a pin in the slot, or a
// block on a slider).
constexpr double kR = 20, kL = 70, kE = 12, kAlpha = 100, kSliderStart = 30;

std::string sliderCrankText(bool pin) {
  const Vec2 A = kR * Vec2(std::cos(kSliderStart * kDeg), std::sin(kSliderStart * kDeg));
  const Vec2 P0(kE, 0), t(std::cos(kAlpha * kDeg), std::sin(kAlpha * kDeg)), w = A - P0;
  const double h = cross(t, w);
  const Vec2 B = P0 + (w.dot(t) + std::sqrt(kL * kL - h * h)) * t;
  std::string text = head("slider-crank in V") + R"(  "bodies": [
    {"name": "ground", "ground": true, "points": {"O": )" +
                     vec(world(Vec2::Zero())) + R"(}, "slots": {"u": [)" + vec(world(P0)) + ", " +
                     vec(world(P0 + 80 * t)) + R"(]}},
    {"name": "crank", "plane": "v", "points": {"O": [0, 0], "A": )" +
                     vec2(A) + R"(}},
    {"name": "rod", "plane": "v", "points": {"A": )" +
                     vec2(A) + R"(, "B": )" + vec2(B) + "}}";
  if (!pin)
    text += R"(,
    {"name": "block", "plane": "v", "points": {"B": )" +
            vec2(B) + "}}";
  text += R"(
  ],
  "joints": [
    {"type": "pin", "a": "ground.O", "b": "crank.O"},
    {"type": "pin", "a": "crank.A", "b": "rod.A"},
)";
  text += pin ? R"(    {"type": "pin-in-slot", "a": "rod.B", "slot": "ground.u"})"
              : R"(    {"type": "pin", "a": "rod.B", "b": "block.B"},
    {"type": "slider", "a": "block.B", "slot": "ground.u"})";
  return text + R"(
  ],
  "driver": {"joint": 0, "rpm": 60, "direction": "ccw"}
})";
}

// mu = acos(|cross(t, A - P0)| / l) (degrees): the slot's line through P0 (moved by its offset
// along perp(t), turned by its angle about P0), the crank at theta.
C sliderCrankMu(const Vars& v, double theta) {
  const CVec O = inV(v, "O", world(Vec2::Zero()));
  const C alpha = v("ground.u.angle", kAlpha) * kDeg;
  const CVec t{std::cos(alpha), std::sin(alpha)};
  // The offset moves the line along n x t, which is perp(t) in V; the turn keeps P0.
  const CVec n{-std::sin(C(kAlpha * kDeg)), std::cos(C(kAlpha * kDeg))};
  const CVec P0 = inV(v, "", world(Vec2(kE, 0))) + v("ground.u.offset", 0) * n;
  const C r = v("crank.O-A", kR), l = v("rod.A-B", kL);
  const CVec A = O + r * CVec{std::cos(C(theta)), std::sin(C(theta))};
  C c = cross(t, A - P0);
  if (c.real() < 0) c = -c;
  return std::acos(c / l) / kDeg;
}

Mechanism parsed(const std::string& text) {
  LoadResult r = parseMechanism(text);
  EXPECT_TRUE(r.mechanism.has_value()) << r.error;
  return r.mechanism.value_or(Mechanism{});
}

// Every crank angle's mu against the closed form, and every dimension's derivative against its
// complex step; each dimension must be one the closed form knows.
template <typename Mu>
void expectClosedForm(const Mechanism& m, double start, const Mu& mu, TransmissionKind kind,
                      size_t dimCount) {
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const std::vector<TransmissionJoint> js = transmissionJoints(m);
  ASSERT_EQ(js.size(), 1u);
  EXPECT_EQ(js[0].kind, kind);
  Sensitivity s;
  ASSERT_TRUE(s.prepare(k, dimensions(m), Sensitivity::Space::World).ok());
  ASSERT_EQ(s.dims().size(), dimCount);
  double peak = 0, worst = 0;
  for (int deg = 0; deg < 360; deg += 10) {
    ASSERT_TRUE(k.moveTo(deg).ok());
    ASSERT_TRUE(s.at(k).ok());
    const double theta = (start + deg) * kDeg;
    EXPECT_NEAR(transmissionAngle(k, js[0]).deg, mu(Vars{}, theta).real(), 1e-9) << deg;
    const std::vector<double> got = transmissionAngleDerivatives(k, js[0], s);
    std::vector<double> want;
    for (const Dimension& d : s.dims()) {
      Vars v;
      v.x[d.name] = C(0, test::kH);
      want.push_back(mu(v, theta).imag() / test::kH);
      peak = std::max(peak, std::abs(want.back()));
    }
    for (size_t i = 0; i < want.size(); ++i) worst = std::max(worst, std::abs(got[i] - want[i]));
    for (size_t i = 0; i < want.size(); ++i)
      EXPECT_NEAR(got[i], want[i], 1e-10 * peak) << s.dims()[i].name << " at " << deg;
  }
  EXPECT_GT(peak, 0.5);
  std::cout << "largest difference / the peak derivative: " << worst / peak << "\n";
}

TEST(SpatialTransmissionSensitivity, AFourBarInAVerticalPlaneByTheLawOfCosines) {
  const Mechanism m = parsed(fourBarText());
  // Three lengths, two ground points' x, y, z, V's origin.
  expectClosedForm(m, kStart, fourBarMu, TransmissionKind::Dyad, 12);
}

TEST(SpatialTransmissionSensitivity, ASliderCrankInAVerticalPlaneByTheLawOfSines) {
  for (bool pin : {true, false}) {
    const Mechanism m = parsed(sliderCrankText(pin));
    // Two lengths, the ground point's x, y, z, the slot's offset and angle, V's origin.
    expectClosedForm(m, kSliderStart, sliderCrankMu,
                     pin ? TransmissionKind::RodInSlot : TransmissionKind::RodSlider, 10);
  }
}

// mu of every transmission angle at crank angle deg of the design m, solved afresh.
std::vector<double> angles(const Mechanism& m, const std::vector<TransmissionJoint>& js,
                           double deg) {
  Kinematics k;
  EXPECT_TRUE(k.load(m).ok());
  EXPECT_TRUE(k.moveTo(deg).ok());
  std::vector<double> out;
  for (const TransmissionJoint& j : js) out.push_back(transmissionAngle(k, j).deg);
  return out;
}

TEST(SpatialTransmissionSensitivity, TheOveredgeMachinesAnglesMoveAsChangedDesignsDo) {
  const Mechanism m = test::example("overedge-machine");
  const std::vector<TransmissionJoint> js = transmissionJoints(m);
  ASSERT_EQ(js.size(), 5u);
  const std::vector<Dimension> dims = dimensions(m);
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  Sensitivity s;
  ASSERT_TRUE(s.prepare(k, dims, Sensitivity::Space::World).ok());
  const double h = 1e-6;
  int checked = 0;
  double largest = 0;
  for (double deg : {0.0, 110.0, 250.0}) {
    ASSERT_TRUE(k.moveTo(deg).ok());
    ASSERT_TRUE(s.at(k).ok());
    std::vector<std::vector<double>> got;
    for (const TransmissionJoint& j : js) got.push_back(transmissionAngleDerivatives(k, j, s));
    for (size_t d = 0; d < dims.size(); ++d) {
      std::vector<double> side[2];
      for (int i = 0; i < 2; ++i)
        side[i] = angles(test::changedDesign(m, dims, d, i ? h : -h), js, deg);
      for (size_t j = 0; j < js.size(); ++j) {
        const double want = (side[1][j] - side[0][j]) / (2 * h);
        EXPECT_NEAR(got[j][d], want, 1e-6 * (1 + std::abs(want)))
            << js[j].label << " " << dims[d].name << " at " << deg;
        largest = std::max(largest, std::abs(want));
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, static_cast<int>(3 * 5 * dims.size()));
  EXPECT_GT(largest, 1);
}

}  // namespace
}  // namespace linkage
