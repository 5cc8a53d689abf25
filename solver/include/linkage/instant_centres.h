// Instant centres of velocity of a planar mechanism at one position, found as the textbook finds
// them: primary centres from the joints, secondary centres by Kennedy's theorem (the three
// centres of any three bodies lie on one line) with the circle-diagram method, and each one
// checked against the centre computed from the solved body velocities.
//
// Numbering is the textbook's: the ground is 1, the other bodies follow in file order, or carry
// their own `number` (docs/instant-centres.md). Centres are kept in homogeneous coordinates so
// that a centre at infinity (a slider, two bodies translating relative to each other) is an
// ordinary value and parallel lines meet at infinity rather than in a division by zero.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

#include "linkage/elements.h"
#include "linkage/kinematics.h"
#include "linkage/space.h"

namespace linkage {

struct System;  // the compiled mechanism (internal)

// How a centre was found. Velocity: Kennedy's lines do not fix it at this position (too few
// lines, or the lines coincide), so it is taken from the solved velocities, and said so.
enum class CentreStatus : unsigned char { Primary, Kennedy, Velocity };
const char* toString(CentreStatus s);  // "primary", "kennedy", "velocity"

// Why Kennedy did not give a Velocity centre.
enum class KennedyFailure : unsigned char {
  None,
  TooFewLines,    // fewer than two lines through the pair were ever known
  LinesCoincide,  // two or more lines, but they coincide (to within what positions resolve)
};
const char* toString(KennedyFailure f);

// One line a centre IC(i, j) was found from: the line through IC(i, k) and IC(k, j) (k is the
// textbook number of the third body), or, with k = 0, the line a joint between i and j gives by
// itself (a pin in a slot: the normal to the slot through the pin; joint = its id).
struct CentreLine {
  int k = 0;
  JointId joint;
};

// The numeric rules (docs/instant-centres.md explains them). Lengths are relative to the
// mechanism size L (System::size) about the middle of the drawing, where a homogeneous centre
// (x, y, w) is a unit 3-vector; "chordal" differences are |a x b| of two such vectors, which is
// the distance over L for nearby finite points and the sine of the angle between directions for
// centres at infinity.
struct CentreTolerances {
  // Relative accuracy of the positions and velocities the kinematic core delivers (its Newton
  // closes the joints to 1e-13 L).
  static constexpr double inputAccuracy = 1e-13;
  // A Primary or Kennedy centre farther than this from the velocity-derived one is reported
  // (chordal; 1e-9 L for finite centres within L of the middle), or farther than the two
  // derivations' own first-order bounds where those are larger (lines meeting at a small angle,
  // a slow relative motion).
  static constexpr double check = 1e-9;
  // A centre with |w| <= infinity * |(x, y)| is at infinity: more than 1e10 L away, where
  // positions known to 1e-13 L no longer fix a distance.
  static constexpr double infinity = 1e-10;
  // Relative motion slower than this, against the fastest body, is no relative motion: the
  // velocity-derived centre of that pair is undetermined.
  static constexpr double noMotion = 1e-12;
  // Kennedy takes a centre from the two lines that fix it best, judged by the first-order error
  // bound of their meeting point in units of inputAccuracy. Above `coincident` the lines (or
  // the two centres a line would pass through) coincide to within what the positions resolve:
  // 1e7 x 1e-13 = 1e-6 L. Meetings above `preferred` (lines at a small angle) are taken only
  // when a pass finds nothing better, so that a later pass can offer better lines first.
  static constexpr double preferred = 1e3;
  static constexpr double coincident = 1e7;
};

struct InstantCentre {
  int i = 0, j = 0;     // textbook numbers, i < j
  BodyId bodyI, bodyJ;  // the ground's id for number 1
  // (x_mm, y_mm, 1) for a point; (dx, dy, 0) with a unit direction for a centre at infinity
  // (unoriented; written with dx > 0, or pointing up when vertical); (0, 0, 0) when undetermined.
  Eigen::Vector3d h = Eigen::Vector3d::Zero();
  CentreStatus status = CentreStatus::Velocity;
  // False when no centre exists at this instant: the two bodies do not move relative to each
  // other (joints that hold them together, or a pause in their relative motion, where every
  // point is a centre), or Kennedy failed at a position without velocities (singular).
  bool determined = false;
  JointId joint;                    // Primary: the joint that gives it
  std::array<CentreLine, 2> lines;  // Kennedy, or Primary from two pin-in-slot lines
  int round = 0;                    // Kennedy: pass of the circle-diagram iteration, from 1
  KennedyFailure kennedyFailure = KennedyFailure::None;  // Velocity: why Kennedy did not
  double errorBound = 0;  // Primary/Kennedy: first-order bound, in units of inputAccuracy
  // A machine in space: the two bodies move in planes that are not parallel, where no instant
  // centre exists (never determined). Else the centre is in the frame of plane class
  // `planeClass` (InstantCentres::classes; 0, the drawing plane's, for a planar machine).
  bool across = false;
  int planeClass = 0;

  // The centre of the solved velocities (same convention as h), whatever the status.
  Eigen::Vector3d fromVelocity = Eigen::Vector3d::Zero();
  bool velocityDetermined = false;
  // Primary/Kennedy against fromVelocity: checked unless either side is undetermined.
  bool checked = false;
  bool euclidean = false;  // both finite: difference and tolerance in mm; else chordal
  double difference = 0, tolerance = 0;

  bool atInfinity() const { return determined && h.z() == 0; }
  Vec2 point() const { return Vec2(h.x(), h.y()); }      // finite centres
  Vec2 direction() const { return Vec2(h.x(), h.y()); }  // centres at infinity
};

struct CentreDisagreement {
  int i = 0, j = 0;
  bool euclidean = false;  // mm, else chordal
  double difference = 0, tolerance = 0;
};

struct InstantCentres {
  Status status;  // BadModel when there is no mechanism or its numbering cannot be used
  // Kinematics::revision() of the mechanism the centres are of: what a velocity chain checks.
  std::uint64_t revision = 0;
  double crankDeg = 0;
  double size = 1;                     // L, mm
  bool velocitiesValid = false;        // false at a singular position: no velocity-derived centres
  std::vector<BodyId> bodies;          // in textbook order: bodies[0] is the ground
  std::vector<int> numbers;            // textbook number of bodies[t], ascending, numbers[0] = 1
  std::vector<InstantCentre> centres;  // one per pair, (i, j) ascending
  std::vector<CentreDisagreement> disagreements;
  // The plane classes (linkage/space.h) whose frames the centres are in: one, the drawing
  // plane's, for a planar machine.
  PlaneClasses classes;
  int kennedyRounds = 0;  // circle-diagram rounds that found something

  const InstantCentre* find(int i, int j) const;  // numbers in either order; nullptr if unknown
  int numberOf(BodyId b) const;                   // 0 when unknown
  BodyId bodyNumbered(int n) const;               // none when unknown
};

// Textbook numbers of a mechanism's bodies: the ground is 1 (its own `number`, if any, must be
// 1); bodies with a `number` keep it (>= 2, unique); the others take the smallest unused numbers
// from 2 in file order. BadModel naming the body when that is impossible.
Status textbookNumbers(const Mechanism& m, std::vector<BodyId>& bodies, std::vector<int>& numbers);

// Reusable: prepare() once per mechanism (numbering, which joints give which centres), then
// compute() at every position without allocating. compute() on a Kinematics whose revision()
// is not the one prepared (another mechanism, or an edit since) fails with BadModel and clears
// the centres: prepare() again.
class InstantCentreSolver {
 public:
  Status prepare(const Kinematics& k);
  // All centres at k's current position; k must hold the mechanism prepare() saw.
  const InstantCentres& compute(const Kinematics& k);
  const InstantCentres& result() const { return out_; }

 private:
  struct Primary {  // what a joint says of the centre (its kind's CentreData), in body frames
    CentreRule rule = CentreRule::AtPoint;
    int joint = -1;
    int pBody[2] = {-1, -1};  // system body indices, -1 ground
    Vec2 p[2] = {Vec2::Zero(), Vec2::Zero()};
    int nBody = -1;
    Vec2 n = Vec2::Zero();
    double ratio = 0;
    // PoseLine (a cam's common normal): the line at this pose, world mm, from its kind; `valid`
    // false where it has none.
    Vec2 at = Vec2::Zero(), along = Vec2::UnitX();
    bool valid = true;
  };
  struct Work {  // per pair, scaled homogeneous (unit 3-vectors); what Kennedy reads first
    Eigen::Vector3d h;
    double err = 0;
    int found = -1;  // round found in: 0 primary, >= 1 Kennedy, -1 not (yet)
    bool rigid = false, hasLine = false, exact = false, velDetermined = false, across = false;
    Eigen::Vector3d line, vel;
    Eigen::Vector3d mm;  // a joint's own point or slot normal, as given (public convention)
    double lineErr = 0;
    double velNorm = 0;  // relative motion against the fastest body's
    int lineJoint = -1;
    int firstPrimary = 0, primaryCount = 0;  // range in primaries_
  };
  struct Candidate {  // a line, not normalised: the error bound of its unit form is err / norm
    Eigen::Vector3d line;
    double norm, err;
    CentreLine from;
  };

  int pair(int a, int b) const;  // a != b, textbook indices
  std::vector<std::pair<int, Primary>> primaries(const Mechanism& m, const System& sys) const;
  void planeClassesOf(const Mechanism& m, const System& sys);
  [[gnu::always_inline]] inline Eigen::Vector3d scaled(const Vec2& p) const;
  Eigen::Vector3d toPublic(const Eigen::Vector3d& h) const;
  [[gnu::always_inline]] inline Vec2 global(int body, const Vec2& s) const;  // system index
  [[gnu::always_inline]] inline Vec2 turn(int body, const Vec2& v) const;
  // (Inlined into primaryCentres, which runs for every pair at every frame.)
  [[gnu::always_inline]] inline Eigen::Vector3d primaryLine(const Primary& pr) const;
  [[gnu::always_inline]] inline void primaryPoint(const Primary& pr, Eigen::Vector3d& h,
                                                  Eigen::Vector3d& mm, double& err) const;
  void poseLines(const Kinematics& k);
  void primaryCentres();
  void kennedy();
  bool kennedyPass(int round, double limit);
  void velocityCentres(const Kinematics& k);
  void finish();

  int n_ = 0;
  std::uint64_t revision_ = 0;
  std::vector<JointId> jointIds_;   // Mechanism::joints order
  std::vector<int> sysIndex_;       // textbook index -> system body index (-1 ground)
  std::vector<int> textbookOf_;     // system body index + 1 -> textbook index
  std::vector<int> classOf_;        // textbook index -> plane class (-1 ground: every class)
  std::vector<Mechanism> flat_;     // in space: the mechanism as each class's frame sees it
  std::vector<Primary> primaries_;  // grouped by pair
  std::vector<Work> work_;
  std::vector<Candidate> cand_;
  std::vector<int> pairIndex_;  // n * a + b -> pair
  struct Open {
    int pair, a, b;
  };
  std::vector<Open> open_;    // pairs Kennedy has yet to find
  std::vector<Vec2> origin_;  // per textbook index: frame position at this position
  std::vector<double> cos_, sin_;
  std::vector<Eigen::Vector3d> twist_;  // per textbook index: (v at centre_ / L, omega) per rad
  Vec2 centre_ = Vec2::Zero();
  double L_ = 1;
  InstantCentres out_;
};

// One-off: numbering and all centres at k's current position.
InstantCentres computeInstantCentres(const Kinematics& k);

}  // namespace linkage
