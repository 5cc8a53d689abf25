// Mechanism files: reading the spec's example, round trips, unknown fields, locale independence
// and atomic saving. The refusals are in test_model_io_errors.cpp.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cfloat>
#include <clocale>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <locale>
#include <sstream>

#include "linkage/io/atomic_file.h"
#include "linkage/io/model_file.h"
#include "linkage/io/numbers.h"

namespace linkage {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::StartsWith;

std::string readText(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void writeText(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

TEST(Numbers, FormatIsGeneralWithDotAndPlainZero) {
  EXPECT_EQ(formatNumber(1.5), "1.5");
  EXPECT_EQ(formatNumber(0.1), "0.10000000000000001");
  EXPECT_EQ(formatNumber(0.1, 6), "0.1");
  EXPECT_EQ(formatNumber(3.14159265, 3), "3.14");
  EXPECT_EQ(formatNumber(123456), "123456");
  EXPECT_EQ(formatNumber(-2.5e20), "-2.5e+20");
  EXPECT_EQ(formatNumber(1e-7), "9.9999999999999995e-08");
  EXPECT_EQ(formatNumber(-0.0), "0");
  EXPECT_EQ(formatNumber(0.0), "0");
}

// What people read (notes, `info`): six digits, and 0 where a value is rounding next to its
// quantity's scale (-8.8e-17 next to a 62 mm slot is an exact 0, issue 26).
TEST(Numbers, ShownNumbersRoundRoundingToZero) {
  EXPECT_EQ(formatShown(-8.8e-17, 62), "0");
  EXPECT_EQ(formatShown(1.5e-7, 62), "1.5e-07");  // a real 150 nm, above 1e-9 of the scale
  EXPECT_EQ(formatShown(36.58191234567, 100), "36.5819");
  EXPECT_EQ(formatShown(2.5e-14), "2.5e-14");  // no scale: the value as it is
  EXPECT_EQ(formatShown(4.73826, 1, 2), "4.7");
}

TEST(Numbers, SeventeenDigitsRoundTripExactly) {
  const double values[] = {0.1,
                           1.0 / 3,
                           -1e-300,
                           1e300,
                           DBL_MAX,
                           DBL_MIN,
                           DBL_TRUE_MIN,
                           std::nextafter(1.0, 2.0),
                           9007199254740993.0,
                           -41.260300000000001};
  for (double v : values) {
    std::optional<double> back = parseNumber(formatNumber(v));
    ASSERT_TRUE(back) << formatNumber(v);
    EXPECT_EQ(*back, v) << formatNumber(v);
  }
}

TEST(Numbers, NonFiniteIsACallerBugNeverNanText) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::string text = "unset";
  EXPECT_DEBUG_DEATH(text = formatNumber(nan), "non-finite");
#ifdef NDEBUG
  EXPECT_EQ(text, "");
  EXPECT_EQ(formatNumber(-std::numeric_limits<double>::infinity()), "");
#endif
}

TEST(Numbers, ParseAcceptsWholeFiniteNumbersOnly) {
  EXPECT_EQ(parseNumber("1.5"), 1.5);
  EXPECT_EQ(parseNumber("-2e3"), -2000.0);
  EXPECT_EQ(parseNumber("+3"), 3.0);
  EXPECT_EQ(parseNumber("0.10000000000000001"), 0.1);
  for (const char* bad : {"", "+", "-", " 1", "1 ", "1,5", "1.5x", "0x10", "+-1", "++1", "1e", ".",
                          "nan", "inf", "-inf", "infinity", "1e999", "-1e999", "1e-400"})
    EXPECT_FALSE(parseNumber(bad).has_value()) << '"' << bad << '"';
}

TEST(ModelFile, ReadsTheSpecExample) {
  LoadResult r = loadMechanismFile(LINKAGE_TEST_DATA_DIR "/io_wanzer.json");
  ASSERT_TRUE(r.mechanism) << r.error;
  const Mechanism& m = *r.mechanism;
  EXPECT_EQ(m.name, "Wanzer needle bar, inversion 2");
  ASSERT_EQ(m.bodies.size(), 6u);
  ASSERT_NE(m.ground(), nullptr);
  EXPECT_EQ(m.ground()->name, "ground");
  EXPECT_EQ(m.points.size(), 8u);
  EXPECT_EQ(m.slots.size(), 3u);
  ASSERT_EQ(m.joints.size(), 7u);
  EXPECT_EQ(m.joints[2].type, JointType::Slider);
  EXPECT_EQ(m.slotLabel(m.joints[2].slot), "disk.B");
  EXPECT_EQ(m.pointLabel(m.joints[6].a), "needlebar.G");
  const Slot* c = m.slotNamed(m.bodyNamed("disk")->id, "C");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->p0, Vec2(-31, 10));
  EXPECT_EQ(m.point(*m.findPoint("triangle.G"))->pos, Vec2(0, -41.2603));
  ASSERT_TRUE(m.driver);
  EXPECT_EQ(m.jointIndex(m.driver->joint), 0);
  EXPECT_EQ(m.driver->rpm, 240);
  EXPECT_EQ(m.driver->direction, Direction::Cw);
  EXPECT_EQ(m.driver->startDeg, 0);
  ASSERT_EQ(m.outputs.size(), 1u);
  EXPECT_EQ(m.pointLabel(m.outputs[0]), "needlebar.G");
  EXPECT_EQ(m.extras, "");
  EXPECT_EQ(m.bodies[0].extras, "");
}

TEST(ModelFile, UnknownFieldsSurviveSaveAndReload) {
  LoadResult r = loadMechanismFile(LINKAGE_TEST_DATA_DIR "/io_extras.json");
  ASSERT_TRUE(r.mechanism) << r.error;
  const Mechanism& m = *r.mechanism;
  EXPECT_EQ(
      m.extras,
      R"({"zeta":{"nested":[1,2.5,"x",null,true]},"alpha":1e-07,"view":{"zoom":2.5,"centre":[10,-3]}})");
  EXPECT_EQ(m.unitsExtras, R"({"angle":"deg"})");
  EXPECT_EQ(m.bodies[0].extras, R"({"colour":"#808080","locked":false})");
  EXPECT_EQ(m.bodies[1].extras, R"({"mass_kg":0.25})");
  EXPECT_EQ(m.bodies[2].extras, "");
  EXPECT_EQ(m.joints[0].extras, R"({"comment":"main bearing"})");
  EXPECT_EQ(m.joints[3].extras, R"({"label":"pivot"})");
  EXPECT_EQ(m.driver->extras, R"({"motor":"M1"})");
  EXPECT_EQ(m.driver->startDeg, 12.5);
  EXPECT_EQ(m.outputsExtras, R"({"colour":"red"})");
  EXPECT_EQ(m.bodies[1].number, 2);

  std::string text = serializeMechanism(m);
  // Known keys in the spec's order, then the unknown ones in their original order.
  std::vector<std::string> order = {"\"format\"", "\"version\"", "\"name\"",   "\"units\"",
                                    "\"bodies\"", "\"joints\"",  "\"driver\"", "\"outputs\"",
                                    "\"zeta\"",   "\"alpha\"",   "\"view\""};
  size_t last = 0;
  for (const std::string& key : order) {
    size_t at = text.find("\n  " + key + ": ");
    ASSERT_NE(at, std::string::npos) << key << " in\n" << text;
    EXPECT_GT(at, last) << key << " out of order in\n" << text;
    last = at;
  }
  EXPECT_THAT(text, HasSubstr("\"b\": \"rocker.P\",\n      \"label\": \"pivot\"\n"));
  LoadResult again = parseMechanism(text);
  ASSERT_TRUE(again.mechanism) << again.error << "\n" << text;
  EXPECT_EQ(mechanismDifference(m, *again.mechanism), "");
  EXPECT_EQ(again.mechanism->extras, m.extras);
  EXPECT_EQ(again.mechanism->joints[3].extras, R"({"label":"pivot"})");
  EXPECT_EQ(serializeMechanism(*again.mechanism), text);
}

TEST(ModelFile, SerializedLayoutIsReadable) {
  Mechanism m;
  BodyId g = m.addBody("ground", true);
  BodyId c = m.addBody("crank");
  PointId o = m.addPoint(g, "O", {0, 0});
  PointId co = m.addPoint(c, "O", {-0.0, 0});
  m.addPoint(c, "A", {12.5, 1e-7});
  m.addSlot(g, "S", {0, 0}, {100, 0});
  m.addPin(o, co);
  m.driver = Driver{m.joints[0].id, 60, Direction::Ccw, 0, ""};
  EXPECT_EQ(serializeMechanism(m), R"({
  "format": "linkage",
  "version": 1,
  "units": {
    "length": "mm"
  },
  "bodies": [
    {
      "name": "ground",
      "ground": true,
      "points": {
        "O": [0, 0]
      },
      "slots": {
        "S": [[0, 0], [100, 0]]
      }
    },
    {
      "name": "crank",
      "points": {
        "O": [0, 0],
        "A": [12.5, 1e-07]
      }
    }
  ],
  "joints": [
    {
      "type": "pin",
      "a": "ground.O",
      "b": "crank.O"
    }
  ],
  "driver": {
    "joint": 0,
    "rpm": 60,
    "direction": "ccw"
  }
}
)");
}

// A mechanism using every feature, built the way an editor would (ids interleaved across bodies).
Mechanism everything() {
  Mechanism m;
  m.name = "every \"feature\" \xC3\xA9";
  BodyId g = m.addBody("ground", true);
  m.bodies.back().number = 1;
  BodyId disk = m.addBody("disk");
  PointId ga = m.addPoint(g, "A", {0.1, -1.0 / 3});
  PointId da = m.addPoint(disk, "A", {0.1, -1.0 / 3});
  SlotId slot = m.addSlot(disk, "B", {10, -31.000000000000004}, {10, 31});
  SlotId groundSlot = m.addSlot(g, "D", {1e-300, 0}, {DBL_TRUE_MIN, -1e300});
  BodyId block = m.addBody("block");
  m.body(block)->extras = R"({"colour":"blue","tags":["a","b"]})";
  m.body(block)->number = 7;
  PointId be = m.addPoint(block, "E", {std::nextafter(10.0, 11.0), 9007199254740993.0});
  PointId bf = m.addPoint(block, "F", {-123456789.125, 2.5e-17});
  BodyId pin = m.addBody("pin");
  PointId pg = m.addPoint(pin, "G", {0, -41.260300000000001});
  JointId drive = m.addPin(ga, da);
  m.addSlider(be, slot);
  m.addPinInSlot(pg, groundSlot);
  m.joints.back().extras = R"({"note":"guide"})";
  m.addPin(bf, m.addPoint(pin, "F", {-123456789.125, 2.5e-17}));
  m.driver = Driver{drive, 12.345678901234567, Direction::Cw, -30.000000000000004, R"({"k":1})"};
  m.outputs = {pg, bf};
  m.extras = R"({"view":{"zoom":1.5}})";
  m.unitsExtras = R"({"angle":"deg"})";
  m.outputsExtras = R"({"plot":true})";
  return m;
}

TEST(ModelFile, HandBuiltMechanismsRoundTripFieldByField) {
  Mechanism minimal;
  minimal.addPoint(minimal.addBody("g", true), "P", {1, 2});
  Mechanism noDriver = everything();
  noDriver.driver.reset();
  noDriver.outputs.clear();
  noDriver.outputsExtras.clear();
  for (const Mechanism& m : {everything(), minimal, noDriver}) {
    std::string text = serializeMechanism(m);
    LoadResult r = parseMechanism(text);
    ASSERT_TRUE(r.mechanism) << r.error << "\n" << text;
    EXPECT_EQ(mechanismDifference(m, *r.mechanism), "") << text;
    EXPECT_EQ(serializeMechanism(*r.mechanism), text);
  }
}

TEST(ModelFile, DifferenceNoticesOneUlpAndRenamedReferences) {
  Mechanism a = everything(), b = everything();
  b.points[3].pos.y() = std::nextafter(b.points[3].pos.y(), 0.0);
  EXPECT_EQ(
      mechanismDifference(a, b),
      "bodies[2].points[1]: [-123456789.125, 2.5e-17] vs [-123456789.125, 2.4999999999999996e-17]");
  b = everything();
  b.driver->startDeg = -30;
  EXPECT_THAT(mechanismDifference(a, b), StartsWith("driver.start_deg"));
  b = everything();
  b.joints[1].extras = R"({"note":"other"})";
  EXPECT_THAT(mechanismDifference(a, b), StartsWith("joints[1]: unknown fields differ"));
  b = everything();
  b.outputs = {b.outputs[1], b.outputs[0]};
  EXPECT_EQ(mechanismDifference(a, b), "outputs.points[0] differs");
}

TEST(ModelFile, ExtrasThatWouldChangeMeaningAreNotWritten) {
  Mechanism m = everything();
  m.bodies[1].extras = R"({"ground":true,"points":{},"fine":1})";
  m.extras = "not json";
  std::string text = serializeMechanism(m);
  LoadResult r = parseMechanism(text);
  ASSERT_TRUE(r.mechanism) << r.error << "\n" << text;
  EXPECT_EQ(r.mechanism->bodies[1].extras, R"({"fine":1})");
  EXPECT_EQ(r.mechanism->extras, "");
}

// Restores the C and C++ global locales however the test ends.
struct LocaleGuard {
  std::string c = std::setlocale(LC_ALL, nullptr);
  std::locale cpp;
  ~LocaleGuard() {
    std::locale::global(cpp);
    std::setlocale(LC_ALL, c.c_str());
  }
};

TEST(ModelFile, CommaDecimalLocaleChangesNothing) {
  LocaleGuard guard;
  std::string chosen;
  for (const char* name : {"de_DE.UTF-8", "de_DE.utf8", "fr_FR.UTF-8", "fr_FR.utf8"}) {
    try {
      std::locale::global(std::locale(name));
    } catch (const std::runtime_error&) {
      continue;
    }
    if (std::setlocale(LC_ALL, name)) {
      chosen = name;
      break;
    }
  }
  if (chosen.empty())
    GTEST_SKIP() << "no locale with a ',' decimal point is installed (tried de_DE.UTF-8, "
                    "fr_FR.UTF-8); on Debian: apt-get install locales && localedef -i de_DE -f "
                    "UTF-8 de_DE.UTF-8";
  // The environment really is hostile, or this test proves nothing.
  ASSERT_STREQ(std::localeconv()->decimal_point, ",") << chosen;
  char buf[16];
  std::snprintf(buf, sizeof buf, "%.2f", 1.25);
  ASSERT_STREQ(buf, "1,25");
  std::ostringstream stream;
  stream << 1.25;
  ASSERT_EQ(stream.str(), "1,25");

  EXPECT_EQ(formatNumber(1.25), "1.25");
  EXPECT_EQ(formatNumber(-2.5e-20, 6), "-2.5e-20");
  EXPECT_EQ(parseNumber("1.25"), 1.25);
  EXPECT_FALSE(parseNumber("1,25").has_value());
  std::string wanzer = readText(LINKAGE_TEST_DATA_DIR "/io_wanzer.json");
  LoadResult r =
      parseMechanism(wanzer.replace(wanzer.find("[10, 19.9279]"), 13, "[10.25, -5.5e-3]"));
  ASSERT_TRUE(r.mechanism) << r.error;
  EXPECT_EQ(r.mechanism->point(*r.mechanism->findPoint("triangle.E"))->pos, Vec2(10.25, -5.5e-3));
  std::string text = serializeMechanism(*r.mechanism);
  EXPECT_THAT(text, HasSubstr("[10.25, -0.0055]"));
  Mechanism m = everything();
  EXPECT_EQ(mechanismDifference(*parseMechanism(serializeMechanism(m)).mechanism, m), "");
}

class AtomicSave : public ::testing::Test {
 protected:
  fs::path dir;
  void SetUp() override {
    std::string tmpl = (fs::temp_directory_path() / "linkage-io-XXXXXX").string();
    ASSERT_NE(::mkdtemp(tmpl.data()), nullptr);
    dir = tmpl;
  }
  void TearDown() override { fs::remove_all(dir); }
  std::vector<std::string> entries(const fs::path& d) const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(d)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
};

TEST_F(AtomicSave, NewFileIsWrittenWholeWithUsualPermissions) {
  fs::path file = dir / "m.linkage.json";
  Mechanism m = everything();
  WriteResult w = saveMechanismFile(m, file.string());
  ASSERT_TRUE(w.ok) << w.error;
  EXPECT_EQ(w.error, "");
  EXPECT_EQ(entries(dir), std::vector<std::string>{"m.linkage.json"});
  LoadResult r = loadMechanismFile(file.string());
  ASSERT_TRUE(r.mechanism) << r.error;
  EXPECT_EQ(mechanismDifference(m, *r.mechanism), "");
  mode_t mask = ::umask(022);
  ::umask(mask);
  EXPECT_EQ(fs::status(file).permissions(), static_cast<fs::perms>(0666 & ~mask));
}

TEST_F(AtomicSave, ReplacesAnExistingFileWholeAndKeepsItsPermissions) {
  fs::path file = dir / "m.json";
  writeText(file, std::string(10000, 'x'));
  fs::permissions(file, static_cast<fs::perms>(0640));
  WriteResult w = writeFileAtomically(file.string(), "short");
  ASSERT_TRUE(w.ok) << w.error;
  EXPECT_EQ(readText(file), "short");
  EXPECT_EQ(fs::status(file).permissions(), static_cast<fs::perms>(0640));
  EXPECT_EQ(entries(dir), std::vector<std::string>{"m.json"});
}

TEST_F(AtomicSave, SavingThroughALinkReplacesTheLinkedFile) {
  writeText(dir / "real.json", "old");
  fs::create_symlink("real.json", dir / "link.json");
  ASSERT_TRUE(writeFileAtomically((dir / "link.json").string(), "new").ok);
  EXPECT_TRUE(fs::is_symlink(dir / "link.json"));
  EXPECT_EQ(readText(dir / "real.json"), "new");
  EXPECT_EQ(entries(dir), (std::vector<std::string>{"link.json", "real.json"}));
}

TEST_F(AtomicSave, MissingDirectoryFailsNamingThePathAndLeavesNothing) {
  std::string path = (dir / "no-such-dir" / "m.json").string();
  WriteResult w = saveMechanismFile(everything(), path);
  EXPECT_FALSE(w.ok);
  EXPECT_THAT(w.error, StartsWith(path + ": "));
  EXPECT_THAT(w.error, HasSubstr("No such file or directory"));
  EXPECT_TRUE(entries(dir).empty());
}

TEST_F(AtomicSave, APathThatIsADirectoryFailsAndLeavesItAlone) {
  fs::create_directory(dir / "sub");
  writeText(dir / "sub" / "inside.json", "old");
  WriteResult w = writeFileAtomically((dir / "sub").string(), "new");
  EXPECT_FALSE(w.ok);
  EXPECT_THAT(w.error, StartsWith((dir / "sub").string() + ": "));
  EXPECT_THAT(w.error, HasSubstr("Is a directory"));
  EXPECT_EQ(entries(dir), std::vector<std::string>{"sub"});
  EXPECT_EQ(entries(dir / "sub"), std::vector<std::string>{"inside.json"});
  EXPECT_EQ(readText(dir / "sub" / "inside.json"), "old");
}

// A write that fails half-way (here: the file size limit, which binds even root) must leave the
// old file as it was and no temporary file.
TEST_F(AtomicSave, AFailedWriteLeavesTheOldFileIntact) {
  fs::path file = dir / "m.json";
  writeText(file, "old contents");
  rlimit old{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old), 0);
  auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit small = old;
  small.rlim_cur = 100;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  WriteResult w = writeFileAtomically(file.string(), std::string(5000, 'n'));
  ::setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, oldHandler);
  EXPECT_FALSE(w.ok);
  EXPECT_THAT(w.error, StartsWith(file.string() + ": cannot write: "));
  EXPECT_EQ(readText(file), "old contents");
  EXPECT_EQ(entries(dir), std::vector<std::string>{"m.json"});
}

TEST_F(AtomicSave, LoadErrorsStartWithThePath) {
  std::string missing = (dir / "absent.json").string();
  EXPECT_EQ(loadMechanismFile(missing).error, missing + ": cannot open: No such file or directory");
  EXPECT_THAT(loadMechanismFile(dir.string()).error, StartsWith(dir.string() + ": cannot read: "));
  fs::path bad = dir / "bad.json";
  writeText(bad, R"({"format": "linkage", "version": 1, "bodies": [{"name": "g", "ground": true,
      "points": {"A": [0, 0]}}], "joints": [{"type": "slider", "a": "g.A", "slot": "g.X"}]})");
  LoadResult r = loadMechanismFile(bad.string());
  EXPECT_FALSE(r.mechanism);
  EXPECT_EQ(r.error, bad.string() + ": joints[0].slot: no slot \"X\" on body \"g\"");
}

}  // namespace
}  // namespace linkage
