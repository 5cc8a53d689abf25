// A cam's motion programme: the follower's displacement s(theta) over a turn of the cam, made of
// segments, each a rise (or a fall) by a motion law over an angle, or a dwell
// (../shared/specs/model-format.md, "Cams"). Plain C++: the cam joint (elements/cam.cpp), its
// profile and the editor's cam table all read these.
//
// Laws: a normalised rise S(x), x = 0 to 1 over the segment, S(0) = 0, S(1) = 1, with its
// derivatives V = dS/dx, A = d2S/dx2, J = d3S/dx3 exact (closed forms, no sampling):
//
//   cycloidal          S = x - sin(2 pi x) / (2 pi)           V = 1 - cos(2 pi x)
//                      A = 2 pi sin(2 pi x)                   J = 4 pi^2 cos(2 pi x)
//                      peaks: Cv = 2 at x = 1/2, Ca = 2 pi at x = 1/4
//   harmonic           S = (1 - cos(pi x)) / 2                V = (pi / 2) sin(pi x)
//                      A = (pi^2 / 2) cos(pi x)               J = -(pi^3 / 2) sin(pi x)
//                      peaks: Cv = pi / 2, Ca = pi^2 / 2 (at the ends: A jumps from a dwell)
//   polynomial-345     S = 10x^3 - 15x^4 + 6x^5               V = 30x^2 - 60x^3 + 30x^4
//                      A = 60x - 180x^2 + 120x^3              J = 60 - 360x + 360x^2
//                      peaks: Cv = 15/8, Ca = 10 / sqrt(3) = 5.7735 at x = (3 - sqrt 3) / 6
//   polynomial-4567    S = 35x^4 - 84x^5 + 70x^6 - 20x^7      V = 140x^3 (1 - x)^3
//                      A = 420x^2 - 1680x^3 + 2100x^4 - 840x^5
//                      J = 840x - 5040x^2 + 8400x^3 - 4200x^4
//                      peaks: Cv = 35/16, Ca = 7.5132 at x = (5 - sqrt 5) / 10
//   modified-trapezoid (Norton, Cam Design and Manufacturing Handbook) A made of quarter waves
//                      of a sine of period 1/2 (k = 4 pi) joined by constant plateaus:
//                        x in [0, 1/8]    A = C sin(k x)
//                        x in [1/8, 3/8]  A = C
//                        x in [3/8, 5/8]  A = C cos(k (x - 3/8))
//                        x in [5/8, 7/8]  A = -C,   x in [7/8, 1]  A = -C sin(k (1 - x))
//                      V and S their integrals from 0; S(1) = 1 gives C = 1 / (1/8 + 1/(4 pi))
//                      = 4.8881, Cv = C (1/4 + 1/(2 pi)) = 2
//   modified-sine      (Norton) A a quarter wave of a sine of period 1/2 on [0, 1/8] and
//                      [7/8, 1], and three quarters of a period-3/2 wave (m = 4 pi / 3) between:
//                        x in [0, 1/8]    A = C sin(k x)
//                        x in [1/8, 7/8]  A = C cos(m (x - 1/8))
//                        x in [7/8, 1]    A = -C sin(k (1 - x))
//                      C = 1 / (1/(4 pi) + 1/pi^2) = 5.5280, Cv = C / pi = 1.7596
// Every law is a symmetric rise: for x > 1/2, S(x) = 1 - S(1 - x), V(x) = V(1 - x),
// A(x) = -A(1 - x), J(x) = J(1 - x); the piecewise laws are evaluated on their first half so.
//
// A programme's segment k runs from theta_{k-1} (0 for the first) to its `to_deg`; over its span
// beta (radians) with rise h, x = (theta - theta_{k-1}) / beta and
//   s = s_{k-1} + h S(x),  s' = h V / beta,  s'' = h A / beta^2,  s''' = h J / beta^3
// (derivatives in theta in radians), s_{k-1} the sum of the rises before it. A dwell holds s.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace linkage::cam {

enum class Law : unsigned char {
  Cycloidal,
  Harmonic,
  Polynomial345,
  Polynomial4567,
  ModifiedTrapezoid,
  ModifiedSine
};

// A normalised rise and its derivatives in x.
struct Normalised {
  double s = 0, v = 0, a = 0, j = 0;
};

// At x in [0, 1] (clamped: a segment's own ends).
Normalised evaluate(Law law, double x);
// The name in files ("cycloidal", "polynomial-345", ...).
const char* lawName(Law law);
// nullopt for a name no law has.
std::optional<Law> lawNamed(std::string_view name);
// Every law, in the order above.
std::span<const Law> allLaws();
// For messages: "cycloidal", "harmonic", ... or "modified-sine" (quoted).
std::string lawNames();

// A segment as written: its end (cam degrees from the drawing), its rise (the file's unit: mm,
// or degrees for an oscillating follower; negative: a fall) and its law; no law: a dwell.
struct Segment {
  double toDeg = 0;
  double rise = 0;
  std::optional<Law> law;
  bool operator==(const Segment&) const = default;
};

// The follower's displacement and its derivatives in the cam angle (per radian).
struct Displacement {
  double s = 0, v = 0, a = 0, j = 0;
};

// What is wrong with segments as a programme, "" when nothing: the ends increase from above 0
// to exactly 360, a rise has a law, the rises sum to 0 (to 1e-9) and their partial sums stay at
// or above 0 (to 1e-9: the drawing is the lowest position). `at` is the segment at fault and
// `key` its field ("to_deg", "rise", "law"); at = -1 for the programme as a whole.
std::string checkProgram(std::span<const Segment> segments, int& at, const char*& key);

class Program {
 public:
  Program() = default;  // no segments: s = 0 all round
  // Checked segments (checkProgram() says ""); the rises times `scale` (pi / 180 for an
  // oscillating follower's degrees: s in radians).
  explicit Program(std::vector<Segment> segments, double scale = 1);

  // At a cam angle in radians, any number of turns (s has period 2 pi).
  Displacement at(double theta) const;
  // The segment theta (radians, any turn) is in: [start, end) of its span.
  int segmentAt(double theta) const;
  // The change of at(theta) for changes dRise of the segments' rises (the file's unit, one a
  // segment), ends and laws held: s and its derivatives are linear in the rises (a segment's
  // law its normalised shape there, the rises before it its base). The sensitivities' rises.
  Displacement perRise(double theta, std::span<const double> dRise) const;

  const std::vector<Segment>& segments() const { return segments_; }
  double scale() const { return scale_; }
  // Where segment k starts (radians, 0 to 2 pi) and the displacement there.
  double startOf(size_t k) const { return start_[k]; }
  double baseOf(size_t k) const { return base_[k]; }
  bool operator==(const Program& o) const { return segments_ == o.segments_ && scale_ == o.scale_; }

 private:
  std::vector<Segment> segments_;
  std::vector<double> start_, span_, base_;  // radians, radians, scaled rise
  double scale_ = 1;
};

// What a follower is, whatever joins it (the cam joint reads it from the file: linkage/
// cam_joint.h): translating (a block in a straight slot of the body the cam turns on, the guide)
// or oscillating (pinned to the guide), with a roller, a knife edge (roller 0) or a flat face.
struct Follower {
  bool oscillating = false;
  bool flat = false;
  double base = 0;    // the base circle's radius (the surface's), mm
  double roller = 0;  // 0: a knife edge, or a flat face
  // Oscillating: +1 when a rise turns the follower counter-clockwise relative to the guide
  // (b then moves away from the cam's centre), -1 when clockwise.
  double sign = 1;
  bool operator==(const Follower&) const = default;
};

// Where the parts are, in one frame (the world's at a pose, or the guide's): the cam's centre a,
// the follower's point b, and, as the follower is: the unit rise direction u along its slot
// (translating), its pivot (oscillating), the unit normal of its flat face pointing away from
// the cam (a flat face).
struct Place {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  Eigen::Vector2d b = Eigen::Vector2d::Zero();
  Eigen::Vector2d along = Eigen::Vector2d::UnitY();
  Eigen::Vector2d pivot = Eigen::Vector2d::Zero();
  Eigen::Vector2d face = Eigen::Vector2d::UnitY();
};

// The contact at a pose where s' = ds/dtheta (per radian of the cam's turn relative to the
// guide, counter-clockwise): the point where the force acts and the common normal there, unit,
// from the cam to the follower (the direction the cam pushes it). With db/ds the follower
// point's motion per unit s relative to the guide (u translating, sign perp(b - pivot)
// oscillating) and perp the turn by +90 degrees, the relative velocity of b to the cam per
// radian is t = s' db/ds - perp(b - a), and the normal is perp(t) (outward on the pitch curve,
// which b runs round clockwise):
//   roller, knife:        n = unit(b - a + s' perp(db/ds)), through b
//   flat, translating:    n = u, at c = b + (s' - cross(b - a, u)) w, w = u turned clockwise
//                         (where the face point's velocity relative to the cam is along it)
//   flat, oscillating:    n = the face's normal, at c = b + lambda perp(n) with
//                         lambda = (cross(b - a, n) - k cross(b - pivot, n)) / (1 - k),
//                         k = sign s' (the follower's turn per radian of the cam's)
// The normal meets the line of the cam's and the follower's pivots (for a translating follower
// the line through a normal to u) at their instant centre: a + s' w, or (a - k pivot) / (1 - k).
struct Contact {
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  Eigen::Vector2d normal = Eigen::Vector2d::UnitY();
};
Contact contact(const Follower& f, const Place& at, double sPrime);

// The contact's change (its point's and normal's derivatives) when the parts move by `move` (each
// Place member's derivative) and s' by dsPrime: contact() differentiated, term by term (a
// reaction's derivative through a cam, linkage/force_sensitivity.h).
Contact contactChange(const Follower& f, const Place& at, const Place& move, double sPrime,
                      double dsPrime);

}  // namespace linkage::cam
