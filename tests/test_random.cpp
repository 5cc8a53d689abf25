// Robustness on inputs nobody drew on purpose: random mechanisms (many of them unable to turn
// fully, or to close at all) and random corruptions of valid files. Every run must end in a
// solution with finite numbers or a failure with a message: never a crash, a hang or a NaN.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>
#include <sstream>

#include "linkage/io/model_file.h"
#include "linkage/kinematics.h"
#include "mechanisms.h"
#include "slow_build.h"

namespace linkage {
namespace {

constexpr int kScale = test::kSlowBuild ? 1 : 4;

// Loads and turns a mechanism two revolutions; checks every outcome is finite or explained.
void exercise(const Mechanism& m, const std::string& what) {
  for (bool closedForm : {true, false}) {
    KinematicsOptions opt;
    opt.closedForm = closedForm;
    Kinematics k(opt);
    const Status s = k.load(m);
    if (!s.ok()) {
      EXPECT_FALSE(s.message.empty()) << what;
      EXPECT_FALSE(k.valid()) << what;
      continue;
    }
    std::vector<PointId> points;
    for (const Point& p : m.points) points.push_back(p.id);
    for (double a = 0; a <= 720; a += 7.5) {
      const Status step = k.moveTo(a);
      EXPECT_TRUE(k.q().allFinite()) << what << " at " << a;
      if (!step.ok()) {
        EXPECT_FALSE(step.message.empty()) << what << " at " << a;
        EXPECT_TRUE(step.message.find("crank angle") != std::string::npos ||
                    step.message.find("driver") != std::string::npos)
            << step.message;
        break;
      }
      for (PointId p : points) {
        ASSERT_TRUE(k.position(p).allFinite()) << what << " at " << a;
        ASSERT_TRUE(k.velocity(p).allFinite()) << what << " at " << a;
        ASSERT_TRUE(k.acceleration(p).allFinite()) << what << " at " << a;
      }
    }
  }
}

TEST(Random, MechanismsOfAnyProportionsTurnOrSayWhyNot) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> len(1, 120), ang(0, 360), off(-30, 30);
  for (int i = 0; i < 60 * kScale; ++i) {
    const Direction dir = rng() % 2 ? Direction::Cw : Direction::Ccw;
    switch (i % 3) {
      case 0: {
        auto f = test::fourBar(len(rng), len(rng), len(rng), len(rng), ang(rng), rng() % 2,
                               off(rng), off(rng), dir);
        exercise(f.m, "four-bar #" + std::to_string(i));
        break;
      }
      case 1: {
        auto s = test::sliderCrank(len(rng), len(rng), off(rng), ang(rng), dir, 100, rng() % 2);
        exercise(s.m, "slider-crank #" + std::to_string(i));
        break;
      }
      default: {
        // A four-bar with a second dyad on its coupler: six bodies, two loops.
        auto f = test::fourBar(len(rng), len(rng), len(rng), len(rng), ang(rng), true, off(rng),
                               off(rng), dir);
        Mechanism& m = f.m;
        const Vec2 P = m.point(f.P)->pos;
        const Vec2 Q(len(rng), -len(rng));
        const Vec2 C = (P + Q) / 2 + Vec2(off(rng), off(rng));
        const BodyId a = m.addBody("a"), b = m.addBody("b");
        m.addPin(*m.findPoint("coupler.P"), m.addPoint(a, "P", P));
        m.addPin(m.addPoint(a, "C", C), m.addPoint(b, "C", C));
        m.addPin(m.addPoint(b, "Q", Q), m.addPoint(m.ground()->id, "Q", Q));
        exercise(m, "six-bar #" + std::to_string(i));
      }
    }
  }
}

std::string slurp(const std::string& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

TEST(Random, CorruptedFilesAreRefusedOrWorkNeverCrash) {
  std::mt19937 rng(11);
  const char* numbers[] = {"0",    "-0",  "1e308", "-1e308", "1e-308", "123456789", "1e-9", "-7",
                           "1e15", "NaN", "\"x\"", "[]",     "{}",     "null",      "true"};
  const char* punctuation = "{}[],:\"-.0123456789e";
  int loaded = 0, refused = 0;
  for (const char* name : {"wanzer-inversion-2", "slider-crank-22a-lambda-0.5",
                           "four-bar-crank-rocker", "wanzer-inversion-1"}) {
    const std::string text =
        slurp(std::string(LINKAGE_EXAMPLES_DIR) + "/" + name + ".linkage.json");
    ASSERT_FALSE(text.empty());
    for (int i = 0; i < 50 * kScale; ++i) {
      std::string t = text;
      std::uniform_int_distribution<size_t> at(0, t.size() - 1);
      switch (rng() % 5) {
        case 0:
          t.erase(at(rng), 1 + rng() % 8);
          break;
        case 1:
          t.insert(at(rng), 1, punctuation[rng() % 20]);
          break;
        case 2: {  // replace a number by another value
          size_t p = at(rng);
          while (p < t.size() && !std::isdigit(static_cast<unsigned char>(t[p]))) ++p;
          size_t e = p;
          while (e < t.size() && (std::isdigit(static_cast<unsigned char>(t[e])) || t[e] == '.' ||
                                  t[e] == 'e' || t[e] == '-'))
            ++e;
          if (p < t.size()) t.replace(p, e - p, numbers[rng() % 15]);
          break;
        }
        case 3:
          t.resize(at(rng));
          break;
        default: {  // a name swapped for another one of the file
          const char* names[] = {"\"disk\"", "\"ground\"", "\"E\"",  "\"B\"",
                                 "\"pin\"",  "\"slider\"", "\"cw\"", "\"triangle.G\""};
          size_t p = t.find('"', at(rng));
          size_t e = p == std::string::npos ? p : t.find('"', p + 1);
          if (e != std::string::npos) t.replace(p, e - p + 1, names[rng() % 8]);
        }
      }
      const LoadResult r = parseMechanism(t);
      if (!r.mechanism) {
        ++refused;
        EXPECT_FALSE(r.error.empty());
        continue;
      }
      ++loaded;
      EXPECT_EQ(mechanismDifference(*parseMechanism(serializeMechanism(*r.mechanism)).mechanism,
                                    *r.mechanism),
                "");
      exercise(*r.mechanism, std::string(name) + " corrupted #" + std::to_string(i));
    }
  }
  // Both kinds of outcome happen, or the corruptions test nothing.
  EXPECT_GT(loaded, 10);
  EXPECT_GT(refused, 10);
}

}  // namespace
}  // namespace linkage
