// The mechanisms of a machine (linkage/mechanisms.h): which bodies and joints make each, on the
// lockstitch machine (a shared arm shaft, a hook shaft alone, a feed shaft with one linkage), two
// four-bars on one crank and a single four-bar; the file's entries that name, colour and hide
// them, found again after edits; and that an edit of one mechanism re-solves only its groups.
#include <gtest/gtest.h>

#include <algorithm>

#include "examples.h"
#include "kinematics/kinematics_state.h"
#include "linkage/groups.h"
#include "linkage/io/model_file.h"
#include "linkage/kinematics.h"
#include "linkage/mechanisms.h"
#include "mechanisms.h"

namespace linkage {
namespace {

std::vector<std::string> bodyNames(const Mechanism& m, const SubMechanism& s) {
  std::vector<std::string> out;
  for (BodyId id : s.bodies) out.push_back(m.body(id)->name);
  return out;
}

std::vector<int> jointIndices(const Mechanism& m, const SubMechanism& s) {
  std::vector<int> out;
  for (JointId id : s.joints) out.push_back(m.jointIndex(id));
  return out;
}

using Names = std::vector<std::string>;

TEST(Mechanisms, LockstitchMachineSplitsAtItsShafts) {
  const Mechanism m = test::example("lockstitch-machine");
  const std::vector<SubMechanism> all = subMechanisms(m);
  ASSERT_EQ(all.size(), 5u);
  // The arm shaft drives two linkages: a mechanism of its own; the hook shaft drives none; the
  // feed shaft drives one and belongs to it.
  EXPECT_EQ(bodyNames(m, all[0]), Names({"armshaft"}));
  EXPECT_TRUE(all[0].shaft);
  EXPECT_EQ(bodyNames(m, all[1]), Names({"rod", "needlebar"}));
  EXPECT_EQ(bodyNames(m, all[2]), Names({"takeup", "link"}));
  EXPECT_EQ(bodyNames(m, all[3]), Names({"hook"}));
  EXPECT_TRUE(all[3].shaft);
  EXPECT_EQ(bodyNames(m, all[4]), Names({"feedshaft", "advancerod", "feedrock", "feedbar"}));
  EXPECT_FALSE(all[4].shaft);
  // Joints: the driver with its shaft, a crank pin with the rod it drives, a belt with the
  // shaft it turns.
  EXPECT_EQ(jointIndices(m, all[0]), std::vector<int>({0}));
  EXPECT_EQ(jointIndices(m, all[1]), std::vector<int>({1, 2, 3}));
  EXPECT_EQ(jointIndices(m, all[2]), std::vector<int>({4, 5, 6}));
  EXPECT_EQ(jointIndices(m, all[3]), std::vector<int>({7, 8}));
  EXPECT_EQ(jointIndices(m, all[4]), std::vector<int>({9, 10, 11, 12, 13, 14, 15}));
  EXPECT_EQ(all[1].name, "rod");  // no entry: its first body's name
  EXPECT_EQ(all[1].entry, -1);
  EXPECT_EQ(subMechanismOf(all, m.bodyNamed("link")->id), 2);
  EXPECT_EQ(subMechanismOf(all, m.ground()->id), -1);
}

// A second four-bar on the same crank pin's opposite side: the first one reflected through the
// crank pivot.
test::FourBar twoFourBars() {
  test::FourBar f = test::fourBar(60, 15, 55, 40, 30);
  Mechanism& m = f.m;
  const Vec2 A = m.point(f.A)->pos, B = m.point(f.B)->pos, O4 = m.point(f.O4)->pos;
  const BodyId c2 = m.addBody("coupler2"), r2 = m.addBody("rocker2");
  const PointId cA2 = m.addPoint(f.crank, "A2", -A);
  const PointId gO4b = m.addPoint(f.ground, "O4b", -O4);
  m.addPin(cA2, m.addPoint(c2, "A", -A));
  m.addPin(m.addPoint(c2, "B", -B), m.addPoint(r2, "B", -B));
  m.addPin(m.addPoint(r2, "O4", -O4), gO4b);
  return f;
}

TEST(Mechanisms, TwoFourBarsOnOneCrank) {
  const test::FourBar f = twoFourBars();
  const std::vector<SubMechanism> all = subMechanisms(f.m);
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(bodyNames(f.m, all[0]), Names({"crank"}));
  EXPECT_TRUE(all[0].shaft);
  EXPECT_EQ(bodyNames(f.m, all[1]), Names({"coupler", "rocker"}));
  EXPECT_EQ(bodyNames(f.m, all[2]), Names({"coupler2", "rocker2"}));
  EXPECT_EQ(jointIndices(f.m, all[0]), std::vector<int>({0}));
  EXPECT_EQ(jointIndices(f.m, all[1]), std::vector<int>({1, 2, 3}));
  EXPECT_EQ(jointIndices(f.m, all[2]), std::vector<int>({4, 5, 6}));
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());  // and it moves
  ASSERT_TRUE(k.moveTo(90).ok());
}

TEST(Mechanisms, ASingleFourBarIsOneMechanism) {
  const test::FourBar f = test::fourBar(60, 15, 55, 40, 30);
  const std::vector<SubMechanism> all = subMechanisms(f.m);
  ASSERT_EQ(all.size(), 1u);
  EXPECT_EQ(bodyNames(f.m, all[0]), Names({"crank", "coupler", "rocker"}));
  EXPECT_FALSE(all[0].shaft);
  EXPECT_EQ(jointIndices(f.m, all[0]), std::vector<int>({0, 1, 2, 3}));
  EXPECT_TRUE(subMechanisms(Mechanism{}).empty());
}

TEST(Mechanisms, EntriesFollowEditsThatAddOrRemoveBodies) {
  test::FourBar f = twoFourBars();
  Mechanism& m = f.m;
  std::vector<SubMechanism> all = subMechanisms(m);
  setSubMechanismLook(m, all[2], "second", "#1f77b4", true);
  ASSERT_EQ(m.mechanismEntries.size(), 1u);
  all = subMechanisms(m);
  EXPECT_EQ(all[2].name, "second");
  EXPECT_EQ(all[2].colour, "#1f77b4");
  EXPECT_TRUE(all[2].hidden);
  EXPECT_EQ(all[1].name, "coupler");
  EXPECT_FALSE(all[1].hidden);
  // A body added to it (a bar pinned to rocker2): the entry still names it.
  const BodyId extra = m.addBody("extra");
  m.addPin(m.addPoint(extra, "P", Vec2(-70, 0)),
           m.addPoint(m.bodyNamed("rocker2")->id, "P", Vec2(-70, 0)));
  all = subMechanisms(m);
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(all[2].name, "second");
  EXPECT_EQ(all[2].bodies.size(), 3u);
  // Its first body removed: the rest keep the entry.
  m.remove(m.bodyNamed("coupler2")->id);
  all = subMechanisms(m);
  const int rocker2 = subMechanismOf(all, m.bodyNamed("rocker2")->id);
  ASSERT_GE(rocker2, 0);
  EXPECT_EQ(all[rocker2].name, "second");
  EXPECT_TRUE(all[rocker2].hidden);
  // Back to the defaults: the entry goes.
  setSubMechanismLook(m, all[rocker2], all[rocker2].bodies.empty() ? "" : "rocker2", "", false);
  EXPECT_TRUE(m.mechanismEntries.empty());
}

TEST(Mechanisms, TheFileKeepsNamesColoursAndVisibility) {
  Mechanism m = test::example("lockstitch-machine");
  std::vector<SubMechanism> all = subMechanisms(m);
  setSubMechanismLook(m, all[1], "needle bar", "#1f77b4", false);
  setSubMechanismLook(m, all[3], "hook", "", true);
  const std::string text = serializeMechanism(m);
  EXPECT_NE(text.find("\"mechanisms\""), std::string::npos);
  LoadResult r = parseMechanism(text);
  ASSERT_TRUE(r.mechanism) << r.error;
  EXPECT_EQ(mechanismDifference(m, *r.mechanism), "");
  all = subMechanisms(*r.mechanism);
  EXPECT_EQ(all[1].name, "needle bar");
  EXPECT_EQ(all[1].colour, "#1f77b4");
  EXPECT_TRUE(all[3].hidden);
  EXPECT_EQ(all[3].name, "hook");
  EXPECT_EQ(serializeMechanism(*r.mechanism), text);
}

// Two named mechanisms joined by a new link: the merged one keeps the first's entry; once it
// is renamed, no body is left in two entries, and the file reads back.
TEST(Mechanisms, JoinedMechanismsWriteAFileThatReadsBack) {
  test::FourBar f = twoFourBars();
  Mechanism& m = f.m;
  std::vector<SubMechanism> all = subMechanisms(m);
  setSubMechanismLook(m, all[1], "first", "", false);
  setSubMechanismLook(m, all[2], "second", "", true);
  const BodyId bridge = m.addBody("bridge");
  m.addPin(m.addPoint(bridge, "R", Vec2(0, 50)),
           m.addPoint(m.bodyNamed("rocker")->id, "X", Vec2(0, 50)));
  m.addPin(m.addPoint(bridge, "S", Vec2(0, 60)),
           m.addPoint(m.bodyNamed("rocker2")->id, "X", Vec2(0, 60)));
  all = subMechanisms(m);
  // Both linkages joined: the crank drives one linkage now and belongs to it.
  ASSERT_EQ(all.size(), 1u);
  EXPECT_EQ(all[0].name, "first");  // a tie of 2 bodies each: the earlier entry
  setSubMechanismLook(m, all[0], "both", "#2ca02c", false);
  LoadResult r = parseMechanism(serializeMechanism(m));
  ASSERT_TRUE(r.mechanism) << r.error;
  all = subMechanisms(*r.mechanism);
  ASSERT_EQ(all.size(), 1u);
  EXPECT_EQ(all[0].name, "both");
  EXPECT_EQ(all[0].colour, "#2ca02c");
  EXPECT_FALSE(all[0].hidden);
  EXPECT_EQ(r.mechanism->mechanismEntries.size(), 1u);  // the second's bodies all given up
}

std::string refusal(const std::string& mechanisms) {
  const std::string text =
      R"({"format": "linkage", "version": 1, "bodies": [{"name": "ground", "ground": true,
      "points": {"O": [0, 0]}}, {"name": "crank", "points": {"O": [0, 0], "A": [10, 0]}}],
      "joints": [{"type": "pin", "a": "ground.O", "b": "crank.O"}],
      "driver": {"joint": 0, "rpm": 60, "direction": "ccw"}, "mechanisms": )" +
      mechanisms + "}";
  LoadResult r = parseMechanism(text);
  return r.mechanism ? "" : r.error;
}

TEST(Mechanisms, BadEntriesAreRefusedByPlace) {
  EXPECT_EQ(refusal(R"([{"bodies": ["crank"], "name": "c"}])"), "");
  EXPECT_NE(refusal(R"({})").find("mechanisms"), std::string::npos);
  EXPECT_NE(refusal(R"([{"bodies": ["nope"]}])").find("mechanisms[0].bodies[0]"),
            std::string::npos);
  EXPECT_NE(refusal(R"([{"bodies": []}])").find("mechanisms[0].bodies"), std::string::npos);
  EXPECT_NE(refusal(R"([{"bodies": ["crank"], "colour": "blue"}])").find("mechanisms[0].colour"),
            std::string::npos);
  EXPECT_NE(refusal(R"([{"bodies": ["crank"], "hidden": 1}])").find("mechanisms[0].hidden"),
            std::string::npos);
  EXPECT_NE(refusal(R"([{"bodies": ["crank"]}, {"bodies": ["crank"]}])").find("mechanisms[1]"),
            std::string::npos);
  // Unknown fields of an entry are kept.
  const std::string text = R"({"format": "linkage", "version": 1, "bodies": [{"name": "ground",
      "ground": true, "points": {"O": [0, 0]}}, {"name": "crank", "points": {"O": [0, 0]}}],
      "joints": [{"type": "pin", "a": "ground.O", "b": "crank.O"}],
      "mechanisms": [{"bodies": ["crank"], "note": {"x": 1}}]})";
  LoadResult r = parseMechanism(text);
  ASSERT_TRUE(r.mechanism) << r.error;
  EXPECT_NE(serializeMechanism(*r.mechanism).find("\"note\""), std::string::npos);
}

// The groups of the decomposition whose bodies are all in `s`: what an edit of `s` alone may
// solve again (derived from the decomposition, not from the solver's edit). Bodies of `s` that
// no group reached count as one more (in the machines here they are pinned together: one part).
int groupsWithin(const Mechanism& m, const SubMechanism& s) {
  const AssurDecomposition d = decomposeAssur(m);
  const auto within = [&](BodyId b) {
    return std::find(s.bodies.begin(), s.bodies.end(), b) != s.bodies.end();
  };
  int n = 0;
  for (const AssurGroup& g : d.groups)
    n += !g.bodies.empty() && std::all_of(g.bodies.begin(), g.bodies.end(), within);
  return n + std::any_of(d.unresolved.begin(), d.unresolved.end(), within);
}

using EditPath = KinematicsState::EditPath;

// k, at crank angle deg, edited to `edited`, an edit of the mechanism of body `inside` of m
// alone: that mechanism's groups are solved again and nothing else (`path` says how), every
// other moving body (`others` of them) keeps its motion bit for bit, and the edited
// mechanism's points move as a fresh solve of the edited design moves them.
void expectOnlyMechanismSolved(Kinematics& k, const Mechanism& m, const Mechanism& edited,
                               const char* inside, double deg, int others, EditPath path,
                               const KinematicsOptions& opt = {}) {
  const std::vector<SubMechanism> all = subMechanisms(m);
  const int mine = subMechanismOf(all, m.bodyNamed(inside)->id);
  ASSERT_GE(mine, 0);
  const Kinematics before = k;
  ASSERT_TRUE(k.edit(edited).ok());
  EXPECT_EQ(internal::state(k).lastEdit, path);
  EXPECT_EQ(k.lastEditGroups(), groupsWithin(m, all[mine]));
  EXPECT_GE(k.lastEditGroups(), 1);
  int kept = 0;
  for (const Body& b : m.bodies) {
    if (b.ground || subMechanismOf(all, b.id) == mine) continue;
    ++kept;
    const Transform t0 = before.bodyTransform(b.id), t1 = k.bodyTransform(b.id);
    EXPECT_EQ(t0.R.c, t1.R.c) << b.name;
    EXPECT_EQ(t0.R.s, t1.R.s) << b.name;
    EXPECT_EQ(t0.t, t1.t) << b.name;
    EXPECT_EQ(before.bodyOmega(b.id), k.bodyOmega(b.id)) << b.name;
    EXPECT_EQ(before.bodyAlpha(b.id), k.bodyAlpha(b.id)) << b.name;
  }
  EXPECT_EQ(kept, others);
  Kinematics fresh(opt);
  ASSERT_TRUE(fresh.load(edited).ok());
  ASSERT_TRUE(fresh.moveTo(deg).ok());
  for (BodyId id : all[mine].bodies)
    for (const Point& p : edited.points) {
      if (p.body != id) continue;
      EXPECT_LT((k.position(p.id) - fresh.position(p.id)).norm(), 1e-9 * k.size()) << p.name;
      EXPECT_LT((k.velocity(p.id) - fresh.velocity(p.id)).norm(),
                1e-9 * (1 + fresh.velocity(p.id).norm()))
          << p.name;
      EXPECT_LT((k.acceleration(p.id) - fresh.acceleration(p.id)).norm(),
                1e-9 * (1 + fresh.acceleration(p.id).norm()))
          << p.name;
    }
}

// Naming, colouring or hiding a mechanism solves nothing again.
void expectLookSolvesNothing(Kinematics& k, const Mechanism& m) {
  const std::vector<SubMechanism> all = subMechanisms(m);
  Mechanism named = m;
  setSubMechanismLook(named, all[1], "hook", "#ff7f0e", true);
  ASSERT_TRUE(k.edit(named).ok());
  EXPECT_EQ(k.lastEditGroups(), 0);
}

// m with the points named moved by d.
Mechanism withPointsMoved(const Mechanism& m, std::initializer_list<const char*> points,
                          const Vec2& d) {
  Mechanism out = m;
  for (const char* p : points) out.point(*out.findPoint(p))->pos += d;
  return out;
}

// On the 30-body machine (a main shaft with 14 mechanisms, solved group by group in closed
// form), rod 0 made 2 mm longer (its pin and its block moved along the block's slot).
TEST(Mechanisms, AnEditOfOneMechanismSolvesOnlyItsGroups) {
  const Mechanism m = test::shaftMachine(14);
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  ASSERT_TRUE(k.closedForm());
  ASSERT_TRUE(k.moveTo(137).ok());
  const std::vector<SubMechanism> all = subMechanisms(m);
  ASSERT_EQ(all.size(), 16u);  // the main shaft, the hook, 14 linkages
  EXPECT_EQ(bodyNames(m, all[subMechanismOf(all, m.bodyNamed("rod0")->id)]),
            Names({"rod0", "block0"}));
  const Mechanism edited = withPointsMoved(m, {"rod0.B", "block0.B"}, Vec2(2, 0));
  expectOnlyMechanismSolved(k, m, edited, "rod0", 137, 28, EditPath::InPlace);
  expectLookSolvesNothing(k, edited);
}

// The same off the closed-form path (the general solve asked for): Newton on that mechanism's
// bodies alone.
TEST(Mechanisms, AnEditOfOneMechanismSolvesOnlyItsGroupsByNewton) {
  const Mechanism m = test::shaftMachine(14);
  KinematicsOptions opt;
  opt.closedForm = false;
  Kinematics k(opt);
  ASSERT_TRUE(k.load(m).ok());
  ASSERT_FALSE(k.closedForm());
  ASSERT_TRUE(k.moveTo(137).ok());
  const Mechanism edited = withPointsMoved(m, {"rod0.B", "block0.B"}, Vec2(2, 0));
  expectOnlyMechanismSolved(k, m, edited, "rod0", 137, 28, EditPath::Blocks, opt);
  expectLookSolvesNothing(k, edited);
  // The motion goes on from there as from a fresh load.
  ASSERT_TRUE(k.moveTo(250).ok());
  Kinematics fresh(opt);
  ASSERT_TRUE(fresh.load(edited).ok());
  ASSERT_TRUE(fresh.moveTo(250).ok());
  const PointId b = *edited.findPoint("block0.B");
  EXPECT_LT((k.position(b) - fresh.position(b)).norm(), 1e-9 * k.size());
}

// A machine that is off the closed-form path whatever the option says: the 14-mechanism one
// with a second pin between coupler 1 and rocker 1 where the first is (redundant: the two are
// no group the closed form solves, and the decomposition leaves them unresolved). An edit of
// rod 0, then one of coupler 1 and rocker 1 (their pins moved together), each solves that
// mechanism alone.
TEST(Mechanisms, AnEditOfOneMechanismOffTheClosedFormPathSolvesOnlyIt) {
  Mechanism m = test::shaftMachine(14);
  const Vec2 C = m.point(*m.findPoint("rocker1.C"))->pos;
  m.addPin(m.addPoint(m.bodyNamed("coupler1")->id, "C2", C),
           m.addPoint(m.bodyNamed("rocker1")->id, "C2", C));
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  ASSERT_FALSE(k.closedForm());
  ASSERT_EQ(k.structure().redundantJoints.size(), 1u);
  ASSERT_TRUE(k.moveTo(137).ok());
  const Mechanism rod = withPointsMoved(m, {"rod0.B", "block0.B"}, Vec2(2, 0));
  expectOnlyMechanismSolved(k, m, rod, "rod0", 137, 28, EditPath::Blocks);
  const Mechanism coupler =
      withPointsMoved(rod, {"coupler1.C", "coupler1.C2", "rocker1.C", "rocker1.C2"}, Vec2(0.5, -1));
  expectOnlyMechanismSolved(k, rod, coupler, "coupler1", 137, 28, EditPath::Blocks);
}

// The 14-mechanism machine with a triad (a group of four bodies the closed form does not solve,
// tests/mechanisms.h) pushed by a fifteenth pin of the main shaft: an edit of the triad solves
// its group alone, an edit of rod 0 leaves the triad's motion as it was, bit for bit.
TEST(Mechanisms, AnEditOfATriadOnTheShaftSolvesOnlyIt) {
  Mechanism m = test::shaftMachine(14);
  const BodyId main = m.bodyNamed("main")->id;
  test::addTriad(m, m.ground()->id, m.addPoint(main, "T", {5, 0}), {70, 5}, "_t");
  const AssurDecomposition d = decomposeAssur(m);
  ASSERT_EQ(d.groups[d.groupOf(m.bodyNamed("triangle_t")->id)].kind, GroupKind::Other);
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  ASSERT_FALSE(k.closedForm());
  ASSERT_TRUE(k.moveTo(137).ok());
  const Mechanism triad = withPointsMoved(m, {"right_t.G", "ground.G3__t"}, Vec2(1, 0.5));
  expectOnlyMechanismSolved(k, m, triad, "triangle_t", 137, 30, EditPath::Blocks);
  const Mechanism rod = withPointsMoved(triad, {"rod0.B", "block0.B"}, Vec2(2, 0));
  expectOnlyMechanismSolved(k, triad, rod, "rod0", 137, 32, EditPath::Blocks);
}

// The lockstitch machine, solved group by group since its feed bar is a PR group: the needle
// bar's rod made 2 mm longer solves the rod and needle bar's group again and nothing else; the
// take-up lever, the hook and the whole drop feed keep their motion bit for bit.
TEST(Mechanisms, AnEditOfTheLockstitchNeedleBarSolvesOnlyIt) {
  const Mechanism m = test::example("lockstitch-machine");
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  ASSERT_TRUE(k.closedForm());
  ASSERT_TRUE(k.moveTo(73).ok());
  const std::vector<SubMechanism> all = subMechanisms(m);
  const int needle = subMechanismOf(all, m.bodyNamed("needlebar")->id);
  ASSERT_GE(needle, 0);
  Mechanism edited = m;
  for (const char* p : {"rod.B", "needlebar.B", "needlebar.N"})
    edited.point(*edited.findPoint(p))->pos.y() -= 2;
  const Kinematics before = k;
  ASSERT_TRUE(k.edit(edited).ok());
  EXPECT_EQ(k.lastEditGroups(), 1);
  int others = 0;
  for (const Body& b : m.bodies) {
    if (b.ground || subMechanismOf(all, b.id) == needle) continue;
    ++others;
    const Transform t0 = before.bodyTransform(b.id), t1 = k.bodyTransform(b.id);
    EXPECT_EQ(t0.R.c, t1.R.c) << b.name;
    EXPECT_EQ(t0.R.s, t1.R.s) << b.name;
    EXPECT_EQ(t0.t, t1.t) << b.name;
    EXPECT_EQ(before.bodyOmega(b.id), k.bodyOmega(b.id)) << b.name;
  }
  EXPECT_EQ(others, 8);
  Kinematics fresh;
  ASSERT_TRUE(fresh.load(edited).ok());
  ASSERT_TRUE(fresh.moveTo(73).ok());
  const PointId n = *edited.findPoint("needlebar.N");
  EXPECT_NEAR(k.position(n).y(), fresh.position(n).y(), 1e-9 * k.size());
}

}  // namespace
}  // namespace linkage
