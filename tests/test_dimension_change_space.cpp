// Exact changes of a machine in space's own dimensions (linkage/dimension_change.h; depths, the
// ground's z, planes' origins, ball rods' lengths, a ground slot in its block's plane): a change
// of +-h solved exactly agrees with Sensitivity's world derivative (a check that the change moves
// what the derivative names, not of the derivative), and a large change gives the machine one
// writes by hand: the example's file text edited, or the RSSR's closed form with another rod.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "changed_design.h"
#include "examples.h"
#include "linkage/dimension_change.h"
#include "linkage/io/model_file.h"
#include "linkage/kinematics.h"
#include "linkage/sensitivity.h"
#include "spatial_fixtures.h"

namespace linkage {
namespace {

bool spaceOwn(const Dimension& d) {
  return !d.depths.empty() || d.lengthOf || d.name.starts_with("ground.u.");
}

Vec3 at(const Kinematics& k, const char* point) {
  return k.motionInSpace(*k.mechanism().findPoint(point)).position;
}

struct Fixture {
  const char* example;
  std::vector<const char*> points;
};

// Each space dimension changed by +-h (1e-6 of its value, of 10 at least) and solved: the
// central difference of each watched point's world position against point3.
TEST(DimensionChangeSpace, SmallChangesMoveThePointsAsTheWorldDerivativeSays) {
  const std::vector<Fixture> fixtures = {
      {"rssr-crank-rocker", {"rocker.C", "crank.A"}},
      {"overedge-machine", {"needlearm.N", "lower.P", "feedbar.T", "upper.V"}}};
  for (const Fixture& f : fixtures) {
    const Mechanism m = test::example(f.example);
    const std::vector<Dimension> dims = dimensions(m);
    Kinematics k;
    ASSERT_TRUE(k.load(m).ok()) << f.example;
    Sensitivity s;
    ASSERT_TRUE(s.prepare(k, dims, Sensitivity::Space::World).ok()) << f.example;
    int checked = 0;
    double worst = 0, peak = 0;
    for (size_t d = 0; d < dims.size(); ++d) {
      if (!spaceOwn(dims[d])) continue;
      const double h = 1e-6 * std::max(10.0, std::abs(dims[d].value));
      Kinematics plus, minus;
      ASSERT_TRUE(plus.load(test::changedDesign(m, dims, d, h)).ok()) << dims[d].name;
      ASSERT_TRUE(minus.load(test::changedDesign(m, dims, d, -h)).ok()) << dims[d].name;
      double moved = 0;
      for (double deg : {0.0, 70.0, 160.0, 250.0}) {
        ASSERT_TRUE(k.moveTo(deg).ok() && s.at(k).ok());
        ASSERT_TRUE(plus.moveTo(deg).ok() && minus.moveTo(deg).ok()) << dims[d].name;
        for (const char* p : f.points) {
          const Vec3 fd = (at(plus, p) - at(minus, p)) / (2 * h);
          const Vec3 exact = s.point3(k, *m.findPoint(p), static_cast<int>(d));
          moved = std::max(moved, exact.norm());
          worst = std::max(worst, (fd - exact).norm());
          EXPECT_LT((fd - exact).norm(), 1e-6 * std::max(1.0, exact.norm()))
              << f.example << " " << dims[d].name << " " << p << " at " << deg;
        }
      }
      peak = std::max(peak, moved);
      checked += moved > 1e-3;  // the change moves a watched point
    }
    std::printf("%-20s %d dimensions move the points; worst |difference - derivative| %.2e\n",
                f.example, checked, worst);
    EXPECT_GE(checked, f.points.size() > 2 ? 15 : 5) << f.example;
  }
}

// The example's file text with `from` replaced by `to` (each exactly once), read.
Mechanism edited(const char* example, const std::vector<std::pair<std::string, std::string>>& e) {
  std::ifstream in(std::string(LINKAGE_EXAMPLES_DIR) + "/" + example + ".linkage.json");
  std::stringstream read;
  read << in.rdbuf();
  std::string text = read.str();
  EXPECT_FALSE(text.empty()) << example;
  for (const auto& [from, to] : e) {
    const size_t i = text.find(from);
    EXPECT_NE(i, std::string::npos) << from;
    EXPECT_EQ(text.find(from, i + 1), std::string::npos) << from;
    if (i != std::string::npos) text.replace(i, from.size(), to);
  }
  const LoadResult h = parseMechanism(text);
  EXPECT_TRUE(h.mechanism.has_value()) << h.error;
  return h.mechanism ? *h.mechanism : Mechanism{};
}

// Every point of a and b in the world at a few crank angles, to 1e-12 of the machine's size.
void sameMotion(const Mechanism& a, const Mechanism& b, const std::string& what) {
  Kinematics ka, kb;
  ASSERT_TRUE(ka.load(a).ok() && kb.load(b).ok()) << what;
  for (double deg : {0.0, 45.0, 130.0, 215.0, 300.0}) {
    ASSERT_TRUE(ka.moveTo(deg).ok() && kb.moveTo(deg).ok()) << what;
    for (const Point& p : a.points) {
      const PointId q = *b.findPoint(a.pointLabel(p.id));  // b's own ids
      const Vec3 pa = ka.motionInSpace(p.id).position, pb = kb.motionInSpace(q).position;
      EXPECT_LT((pa - pb).norm(), 1e-12 * ka.size())
          << what << ": " << a.pointLabel(p.id) << " at " << deg;
    }
  }
}

Mechanism changedBy(const Mechanism& m, const std::string& name, double by) {
  const std::vector<Dimension> dims = dimensions(m);
  for (size_t k = 0; k < dims.size(); ++k)
    if (dims[k].name == name) return test::changedDesign(m, dims, k, by);
  ADD_FAILURE() << "no dimension " << name;
  return m;
}

// +2 mm of a depth, a ground point's z and a plane's origin that move no rod's end: the file as
// one would edit it.
TEST(DimensionChangeSpace, LargeChangesAreTheFileEditedByHand) {
  const Mechanism m = test::example("overedge-machine");
  sameMotion(m, edited("overedge-machine", {}), "nothing changed");
  sameMotion(changedBy(m, "feedbar.T.depth", 2),
             edited("overedge-machine", {{"\"T\": [-9.105431103908423, 15.970301471892197, 68]",
                                          "\"T\": [-9.105431103908423, 15.970301471892197, 70]"}}),
             "feedbar.T.depth");
  sameMotion(changedBy(m, "ground.K.z", 2),
             edited("overedge-machine", {{"\"K\": [78, 51, 69]", "\"K\": [78, 51, 71]"}}),
             "ground.K.z");
  const Mechanism bevel = test::example("lockstitch-bevel");
  sameMotion(changedBy(bevel, "planes.needle.origin.x", 2),
             edited("lockstitch-bevel", {{"\"origin\": [0, 0, 0]", "\"origin\": [2, 0, 0]"}}),
             "planes.needle.origin.x");
  sameMotion(changedBy(bevel, "planes.vertical.origin.z", -2),
             edited("lockstitch-bevel", {{"\"origin\": [20, 0, 0]", "\"origin\": [20, 0, -2]"}}),
             "planes.vertical.origin.z");
}

// The RSSR's rocker angle at crank angle phi with the crank's ball at depth `depth` and the
// rocker's axis point at H, rod l: a cos psi + b sin psi = c (test::rssrEquation's, written
// for any depth and H), the root nearest `near`.
double rockerPsi(double phi, double depth, const Vec3& H, double l, double near) {
  using namespace test::rssr;
  const double t = kPhi0 + phi;
  const Vec3 AH = Vec3(kR * std::cos(t), kR * std::sin(t), depth) - H;
  const double a = 2 * kW * AH.dot(kX), b = 2 * kW * AH.dot(kY);
  const double c = AH.squaredNorm() + kW * kW - l * l;
  double best = 0, gap = INFINITY;
  for (int sign : {1, -1}) {
    const double psi = std::atan2(b, a) + sign * std::acos(c / std::hypot(a, b));
    const double g = std::abs(std::remainder(psi - near, 2 * M_PI));
    if (g < gap) {
      gap = g;
      best = near + std::remainder(psi - near, 2 * M_PI);
    }
  }
  return best;
}

// Depths at a rod's end: the rod keeps its length (as the derivative holds it), so the RSSR with
// its crank's ball 2 mm deeper, or its rocker's C 2 mm along its plane's normal, follows the
// closed form with that ball or that rocker and the drawn rod.
TEST(DimensionChangeSpace, ADepthAtARodsEndKeepsTheRod) {
  using namespace test::rssr;
  const Mechanism m = parseMechanism(test::rssrText()).mechanism.value();
  const double l = test::rssrRod();
  const Vec3 n = kX.cross(kY);
  struct Change {
    const char* name;
    double depth;
    Vec3 H;
  };
  for (const Change& c : {Change{"crank.A.depth", kDepth + 2, kH},
                          Change{"rocker.C.depth", kDepth, Vec3(kH + 2 * n)}}) {
    Kinematics k;
    ASSERT_TRUE(k.load(changedBy(m, c.name, 2)).ok()) << c.name;
    const PointId C = *k.mechanism().findPoint("rocker.C");
    double near = kPsi0;
    for (int deg = 0; deg < 360; deg += 15) {
      ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
      near = rockerPsi(deg * M_PI / 180, c.depth, c.H, l, near);
      const Vec3 want = c.H + kW * (std::cos(near) * kX + std::sin(near) * kY);
      EXPECT_LT((k.motionInSpace(C).position - want).norm(), 1e-10) << c.name << " " << deg;
    }
  }
}

// The ground slot u of the needle arm's slider, in the rocker plane (its block's): its offset
// moves both ends 2 mm across it in that plane (n x t, n the plane's normal x_axis x y_axis, t
// along the slot); its angle turns it about its first end around n (Rodrigues' formula). The
// ends written by hand into the file.
TEST(DimensionChangeSpace, AGroundSlotInItsBlocksPlaneIsTheFileEditedByHand) {
  const Mechanism m = test::example("overedge-machine");
  const Slot* slot = nullptr;
  for (const Slot& s : m.slots)
    if (m.slotLabel(s.id) == "ground.u") slot = &s;
  ASSERT_TRUE(slot);
  const Slot& u = *slot;
  const Plane* rocker = nullptr;
  for (const Plane& f : *m.planes)
    if (f.name == "rocker") rocker = &f;
  ASSERT_TRUE(rocker);
  const Vec3 w0(u.p0.x(), u.p0.y(), u.z[0]), w1(u.p1.x(), u.p1.y(), u.z[1]);
  const Vec3 n = rocker->xAxis.cross(rocker->yAxis), t = (w1 - w0).normalized();
  const Vec3 across = n.cross(t);
  auto slotText = [](const Vec3& a, const Vec3& b) {
    return "\"u\": [" + test::vec(a) + ", " + test::vec(b) + "]";
  };
  const std::string drawn = "\"u\": [[70, 134.5, 53.5], [70, 97.6798058619024, 69.12924513957095]]";
  sameMotion(changedBy(m, "ground.u.offset", 2),
             edited("overedge-machine", {{drawn, slotText(w0 + 2 * across, w1 + 2 * across)}}),
             "ground.u.offset");
  const double turn = 3 * M_PI / 180;
  const Vec3 d = w1 - w0;
  const Vec3 turned =
      d * std::cos(turn) + n.cross(d) * std::sin(turn) + n * n.dot(d) * (1 - std::cos(turn));
  sameMotion(changedBy(m, "ground.u.angle", 3),
             edited("overedge-machine", {{drawn, slotText(w0, w0 + turned)}}), "ground.u.angle");
}

// A ball rod's length: the RSSR with its rod 3 mm longer follows the closed form with l + 3,
// its rod reads back l + 3, and its crank and rocker keep their shapes.
TEST(DimensionChangeSpace, ABallRodsLengthIsTheRssrsClosedFormWithThatRod) {
  const Mechanism m = parseMechanism(test::rssrText()).mechanism.value();
  const double l = test::rssrRod() + 3;
  const Mechanism c = changedBy(m, "ball-rod:crank.A.length", 3);
  for (const Dimension& d : dimensions(c)) {
    if (d.name == "ball-rod:crank.A.length") EXPECT_NEAR(d.value, l, 1e-12 * l);
    if (d.name == "rocker.H-C") EXPECT_NEAR(d.value, test::rssr::kW, 1e-12);
    if (d.name == "crank.O-A") EXPECT_NEAR(d.value, test::rssr::kR, 1e-12);
  }
  Kinematics k;
  ASSERT_TRUE(k.load(c).ok());
  const PointId C = *c.findPoint("rocker.C");
  double near = test::rssr::kPsi0;
  for (int deg = 0; deg < 360; deg += 15) {
    ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
    const test::Rocker r = test::rockerNear(deg * M_PI / 180, near, l);
    near = r.psi;
    using namespace test::rssr;
    const Vec3 want = kH + kW * (std::cos(r.psi) * kX + std::sin(r.psi) * kY);
    EXPECT_LT((k.motionInSpace(C).position - want).norm(), 1e-10) << deg;
  }
  // A rod the machine cannot close with is refused by name.
  std::vector<Dimension> dims = dimensions(m);
  std::vector<double> delta(dims.size(), 0.0);
  for (size_t i = 0; i < dims.size(); ++i)
    if (dims[i].lengthOf) delta[i] = 500;
  Mechanism bad = m;
  const Status s = changeDimensions(bad, dims, delta);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message.find("ball-rod:crank.A.length"), std::string::npos) << s.message;
}

}  // namespace
}  // namespace linkage
