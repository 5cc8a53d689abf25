// Cam mechanisms for the cam tests, as file text: a cam on the ground's pin O driven at constant
// speed, and its follower, translating (a block in a straight ground slot, offset e to the right
// of the cam's centre, rising upwards) or oscillating (a rocker pinned to the ground at P).
// Every number is written with 17 digits, so the drawing is the lowest position to rounding.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

namespace linkage::test {

// The spec's example programme: rise 10 cycloidal to 90, dwell to 150, fall by 3-4-5 to 270,
// dwell to 360.
inline const char* kSpecMotion =
    R"([{"to_deg": 90, "rise_mm": 10, "law": "cycloidal"}, {"to_deg": 150},
       {"to_deg": 270, "rise_mm": -10, "law": "polynomial-345"}, {"to_deg": 360}])";

inline std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

struct TranslatingCam {
  double base = 30, roller = 8, e = 10;
  bool flat = false;
  std::string motion = kSpecMotion;
  std::string direction = "ccw";
  double rpm = 300;
  // The follower's mass and a spring-like load (forces' tests), as extra body and model text.
  std::string followerMass, cam = R"("mass": {"kg": 0.5, "com": [0, 0], "j_kg_mm2": 200},)";
  std::string extra;

  // b: on the slot's line x = e, at sqrt((base + roller)^2 - e^2) above the foot (e, 0); a
  // flat face at base above it.
  double by() const {
    const double r = base + roller;
    return flat ? base : std::sqrt(r * r - e * e);
  }
  std::string text() const {
    const std::string b = "[" + num(e) + ", " + num(by()) + "]";
    return R"({"format": "linkage", "version": 1, "name": "translating cam",
      "bodies": [
        {"name": "ground", "ground": true, "points": {"O": [0, 0]},
         "slots": {"guide": [[)" +
           num(e) + R"(, 0], [)" + num(e) + R"(, 100]]}},
        {"name": "cam", )" +
           cam + R"( "points": {"O": [0, 0]}},
        {"name": "follower", )" +
           followerMass + R"( "points": {"R": )" + b + R"(}}
      ],
      "joints": [
        {"type": "pin", "a": "ground.O", "b": "cam.O"},
        {"type": "slider", "a": "follower.R", "slot": "ground.guide"},
        {"type": "cam", "a": "cam.O", "b": "follower.R", "base_mm": )" +
           num(base) + (flat ? R"(, "flat": true)" : R"(, "roller_mm": )" + num(roller)) +
           R"(, "motion": )" + motion + R"(}
      ],
      "driver": {"joint": 0, "rpm": )" +
           num(rpm) + R"(, "direction": ")" + direction + R"("},
      "outputs": {"points": ["follower.R"]})" +
           extra + "}";
  }
};

// An oscillating roller follower: the rocker pinned to the ground at P = (60, 0), its roller
// centre R on the circle of radius base + roller about O at `at` degrees; it rises 20 degrees.
struct OscillatingCam {
  double base = 30, roller = 8, atDeg = 60;
  bool flat = false;
  std::string motion =
      R"([{"to_deg": 120, "rise_deg": 20, "law": "modified-sine"}, {"to_deg": 180},
          {"to_deg": 300, "rise_deg": -20, "law": "polynomial-4567"}, {"to_deg": 360}])";
  std::string direction = "ccw";
  double rpm = 300;
  double px = 60, py = 0;
  std::string extra;

  double r() const { return base + (flat ? 0 : roller); }
  std::string text() const {
    const double a = atDeg * M_PI / 180;
    const std::string b = "[" + num(r() * std::cos(a)) + ", " + num(r() * std::sin(a)) + "]";
    const std::string p = "[" + num(px) + ", " + num(py) + "]";
    return R"({"format": "linkage", "version": 1, "name": "oscillating cam",
      "bodies": [
        {"name": "ground", "ground": true, "points": {"O": [0, 0], "P": )" +
           p + R"(}},
        {"name": "cam", "points": {"O": [0, 0]}},
        {"name": "rocker", "points": {"P": )" +
           p + R"(, "R": )" + b + R"(}}
      ],
      "joints": [
        {"type": "pin", "a": "ground.O", "b": "cam.O"},
        {"type": "pin", "a": "ground.P", "b": "rocker.P"},
        {"type": "cam", "a": "cam.O", "b": "rocker.R", "base_mm": )" +
           num(base) + (flat ? R"(, "flat": true)" : R"(, "roller_mm": )" + num(roller)) +
           R"(, "motion": )" + motion + R"(}
      ],
      "driver": {"joint": 0, "rpm": )" +
           num(rpm) + R"(, "direction": ")" + direction + R"("},
      "outputs": {"points": ["rocker.R"]})" +
           extra + "}";
  }
};

}  // namespace linkage::test
