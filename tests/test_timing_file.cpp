// The machine's timing as a document keeps it (linkage/model.h's Timing, the file's optional
// "timing"): read from the text a user types, written back the same, refused with the place
// named, taken along by a removal and put back by restore, following a rename; and the diagram
// it gives equals the one of the same windows typed on the command line.
#include <gtest/gtest.h>

#include "examples.h"
#include "linkage/clearance.h"
#include "linkage/io/model_file.h"
#include "linkage/timing.h"
#include "linkage/timing_text.h"

namespace linkage {
namespace {

// The lockstitch machine's file with `timing` (a JSON object's text) in place of its own.
std::string withTiming(const std::string& timing) {
  Mechanism m = test::example("lockstitch-machine");
  m.timing = {};
  std::string text = serializeMechanism(m);
  const size_t end = text.rfind('}');
  return text.substr(0, end) + ",\n\"timing\": " + timing + "\n}\n";
}

const char* kTiming = R"({
  "outputs": ["takeup.E:y", "hook:angle", "feedbar.T:1,1"],
  "windows": ["needle=needlebar.N:y<-185", "feed=feedbar.T:y>-185"],
  "conflicts": [["needle", "feed"]],
  "clearances": [{"between": ["hook.K", "needlebar.N"], "min_mm": 0.1},
                 {"between": ["ground.plate", "hook.K"]},
                 {"between": ["needlebar.N-B", "hook.K"], "min_mm": 0.5}],
  "note": "kept"
})";

TEST(TimingFile, ReadsWritesAndReadsBackTheSame) {
  LoadResult r = parseMechanism(withTiming(kTiming));
  ASSERT_TRUE(r.mechanism) << r.error;
  const Mechanism& m = *r.mechanism;
  const Timing& t = m.timing;
  ASSERT_EQ(t.outputs.size(), 3u);
  EXPECT_EQ(t.outputs[1].body, m.bodyNamed("hook")->id);
  EXPECT_NEAR((t.outputs[2].direction - Vec2(1, 1).normalized()).norm(), 0, 1e-15);
  EXPECT_EQ(t.outputs[2].direction.normalized(), t.outputs[2].direction);  // as written
  ASSERT_EQ(t.windows.size(), 2u);
  EXPECT_EQ(t.windows[0].name, "needle");
  EXPECT_TRUE(t.windows[0].below);
  EXPECT_EQ(t.windows[0].level, -185);
  EXPECT_EQ(t.windows[1].output.point, *m.findPoint("feedbar.T"));
  ASSERT_EQ(t.conflicts.size(), 1u);
  ASSERT_EQ(t.clearances.size(), 3u);
  EXPECT_EQ(t.clearances[0].minMm, 0.1);
  // A slot or a segment named first is the second side: the point comes first.
  EXPECT_EQ(t.clearances[1].point, *m.findPoint("hook.K"));
  EXPECT_TRUE(t.clearances[1].other.isSlot());
  EXPECT_EQ(t.clearances[2].point, *m.findPoint("hook.K"));
  EXPECT_EQ(t.clearances[2].other,
            ClearancePart::segment(*m.findPoint("needlebar.N"), *m.findPoint("needlebar.B")));
  EXPECT_EQ(t.extras, R"({"note":"kept"})");
  const std::string text = serializeMechanism(m);
  EXPECT_NE(text.find(R"("needle=needlebar.N:y<-185")"), std::string::npos) << text;
  EXPECT_NE(text.find(R"("hook.K", "ground.plate")"), std::string::npos) << text;
  EXPECT_NE(text.find(R"("hook.K", "needlebar.N-B")"), std::string::npos) << text;
  LoadResult back = parseMechanism(text);
  ASSERT_TRUE(back.mechanism) << back.error;
  EXPECT_EQ(mechanismDifference(m, *back.mechanism), "");
  EXPECT_EQ(back.mechanism->timing.outputs[2].direction, t.outputs[2].direction);
  EXPECT_EQ(serializeMechanism(*back.mechanism), text);
}

TEST(TimingFile, RefusesWithThePlaceNamed) {
  struct Case {
    const char* timing;
    const char* error;
  };
  const Case cases[] = {
      {R"({"windows": ["n=needlebar.X:y<3"]})", R"(timing.windows[0]: no point "needlebar.X")"},
      {R"({"windows": ["n=needlebar.N:y<3", "n=takeup.E:y>1"]})",
       R"(timing.windows[1]: a second window named "n")"},
      {R"({"windows": ["a b=needlebar.N:y<3"]})", "timing.windows[0]: \"a b=needlebar"},
      {R"({"windows": ["n=needlebar.N:y<x"]})", R"(timing.windows[0]: "x" after '<')"},
      {R"({"outputs": ["needlebar.N:0,0"]})", "timing.outputs[0]: \"0,0\" after"},
      {R"({"outputs": "needlebar.N:y"})", "timing.outputs: expected an array"},
      {R"({"windows": ["n=needlebar.N:y<3"], "conflicts": [["n", "m"]]})",
       R"(timing.conflicts[0]: no window named "m")"},
      {R"({"windows": ["n=needlebar.N:y<3"], "conflicts": [["n", "n"]]})",
       "timing.conflicts[0]: a window cannot conflict with itself"},
      {R"({"conflicts": [["n"]]})", "timing.conflicts[0]: expected two window names"},
      {R"({"clearances": [{"between": ["ground.plate", "ground.needle"]}]})",
       "timing.clearances[0].between: two segments or slots"},
      {R"({"clearances": [{"between": ["ground.O", "ground.plate"]}]})",
       "timing.clearances[0]: the point ground.O is on the body of the slot ground.plate"},
      {R"({"clearances": [{"between": ["hook.K", "hook.K"]}]})",
       "timing.clearances[0]: a point's clearance to itself"},
      {R"({"clearances": [{"between": ["hook.K", "needlebar.N"], "min_mm": -1}]})",
       "timing.clearances[0]: the minimum is not a number >= 0"},
      {R"({"clearances": [{"between": ["hook.K"]}]})", "timing.clearances[0].between: expected"},
      {R"({"clearances": [{"between": ["hook.K", "nobody.X"]}]})",
       R"(timing.clearances[0].between[1]: no point, segment or slot "nobody.X")"},
      {R"({"clearances": [{"between": ["needlebar.N-B", "ground.plate"]}]})",
       "timing.clearances[0].between: two segments or slots"},
      {R"({"clearances": [{"between": ["needlebar.N", "needlebar.N-B"]}]})",
       "timing.clearances[0]: a point's clearance to itself"},
      {R"({"clearances": [{"between": ["needlebar.B", "needlebar.N-X"]}]})",
       R"(timing.clearances[0].between[1]: no point, segment or slot "needlebar.N-X")"},
      {R"({"clearances": [{"between": ["needlebar.B", "needlebar.N-N"]}]})",
       R"(timing.clearances[0].between[1]: no point, segment or slot "needlebar.N-N")"},
  };
  for (const Case& c : cases) {
    LoadResult r = parseMechanism(withTiming(c.timing));
    EXPECT_FALSE(r.mechanism) << c.timing;
    EXPECT_EQ(r.error.rfind(c.error, 0), 0u) << c.timing << "\n" << r.error;
  }
}

TEST(TimingFile, ARemovalTakesWhatFollowsItAndRestorePutsItBack) {
  Mechanism m = *parseMechanism(withTiming(kTiming)).mechanism;
  const Timing before = m.timing;
  // The needle bar carries the needle window, the conflict that names it, and the hook's
  // clearance to the needle point.
  const Removal r = m.remove(m.bodyNamed("needlebar")->id);
  ASSERT_EQ(m.timing.windows.size(), 1u);
  EXPECT_EQ(m.timing.windows[0].name, "feed");
  EXPECT_TRUE(m.timing.conflicts.empty());
  ASSERT_EQ(m.timing.clearances.size(), 1u);
  EXPECT_TRUE(m.timing.clearances[0].other.isSlot());
  EXPECT_EQ(m.timing.outputs.size(), 3u);
  EXPECT_EQ(timingProblem(m, m.timing), "");
  EXPECT_TRUE(parseMechanism(serializeMechanism(m)).mechanism);  // what is written reads back
  m.restore(r);
  EXPECT_EQ(m.timing, before);
  // A body's angle goes with the body.
  const Removal h = m.remove(m.bodyNamed("hook")->id);
  EXPECT_EQ(m.timing.outputs.size(), 2u);
  EXPECT_EQ(m.timing.clearances.size(), 0u);
  m.restore(h);
  EXPECT_EQ(m.timing, before);
}

TEST(TimingFile, ARenameIsFollowed) {
  Mechanism m = *parseMechanism(withTiming(kTiming)).mechanism;
  for (Body& b : m.bodies)
    if (b.name == "needlebar") b.name = "bar";
  const std::string text = serializeMechanism(m);
  EXPECT_NE(text.find(R"("needle=bar.N:y<-185")"), std::string::npos) << text;
  EXPECT_NE(text.find(R"("hook.K", "bar.N")"), std::string::npos) << text;
}

TEST(TimingFile, ReplacingAndRemovingAWindowKeepConflictsTrue) {
  Mechanism m = *parseMechanism(withTiming(kTiming)).mechanism;
  std::string why;
  std::optional<TimingWindow> w = parseTimingWindow(m, "down=needlebar.N:y<-180", &why);
  ASSERT_TRUE(w) << why;
  m.timing.replaceWindow(0, *w);
  EXPECT_EQ(m.timing.conflicts[0].first, "down");
  m.timing.removeWindow(1);
  EXPECT_TRUE(m.timing.conflicts.empty());
  EXPECT_EQ(timingProblem(m, m.timing), "");
}

// The diagram of the kept timing is the one of the same windows typed.
TEST(TimingFile, DiagramEqualsTheTypedOne) {
  const Mechanism m = *parseMechanism(withTiming(kTiming)).mechanism;
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const CycleDiagram kept = cycleDiagram(k, m.timing);
  ASSERT_TRUE(kept.status.ok()) << kept.status.message;
  std::string why;
  const CycleDiagram typed = cycleDiagram(k, {},
                                          {*parseWindow(m, "needle=needlebar.N:y<-185", &why),
                                           *parseWindow(m, "feed=feedbar.T:y>-185", &why)},
                                          {{"needle", "feed"}});
  ASSERT_EQ(kept.windows.size(), typed.windows.size());
  for (size_t i = 0; i < kept.windows.size(); ++i) {
    ASSERT_EQ(kept.windows[i].intervals.size(), typed.windows[i].intervals.size());
    for (size_t j = 0; j < kept.windows[i].intervals.size(); ++j) {
      EXPECT_EQ(kept.windows[i].intervals[j].fromDeg, typed.windows[i].intervals[j].fromDeg);
      EXPECT_EQ(kept.windows[i].intervals[j].toDeg, typed.windows[i].intervals[j].toDeg);
    }
  }
  EXPECT_EQ(kept.conflicts.size(), 1u);
  // The kept rows are the outputs, then the windows' outputs, named as the file writes them.
  ASSERT_EQ(kept.rows.size(), 5u);
  EXPECT_EQ(kept.rows[0].output.name, "takeup.E:y");
  EXPECT_EQ(kept.rows[1].output.name, "hook:angle");
  EXPECT_EQ(kept.rows[3].output.name, "needlebar.N:y");
}

TEST(TimingText, MeasuresReadBackExactly) {
  const Mechanism m = test::example("lockstitch-machine");
  for (const char* text :
       {"needlebar.N:y", "needlebar.N:x", "hook:angle", "feedbar.T:1,1", "feedbar.T:-0.3,2.5e-3"}) {
    std::string why;
    const std::optional<LimitMeasure> x = parseMeasure(m, text, &why);
    ASSERT_TRUE(x) << text << ": " << why;
    const std::optional<LimitMeasure> y = parseMeasure(m, measureText(m, *x), &why);
    ASSERT_TRUE(y) << measureText(m, *x);
    EXPECT_EQ(*x, *y) << text;
  }
  EXPECT_EQ(shortestText(0.1), "0.1");
  EXPECT_EQ(shortestText(-185), "-185");
  EXPECT_FALSE(validWindowName("a\nb"));
  EXPECT_FALSE(validWindowName("a\"b"));
  EXPECT_TRUE(validWindowName("needle_1"));
}

}  // namespace
}  // namespace linkage
