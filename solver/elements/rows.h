// The compiled equations of an element: a few rows of the primitives every kind is made of
// (coincident.h, on_line.h, on_circle.h, angles.h, distance3.h, cam_row.h), each over up to
// three bodies. An
// element kind's compile() turns a joint of the model into these (linkage/elements.h); the system
// (system/system.h) evaluates them; the closed-form groups (kinematics/closed_form.h) and the
// structural decomposition (structure/decomposition.h) read them. A new kind made of these
// primitives needs nothing more; one that needs a new primitive adds it here and where rows
// are evaluated.
#pragma once

#include <memory>

#include "elements/body_view.h"

namespace linkage {

struct CamRow;  // elements/cam_row.h

enum class Primitive : unsigned char {
  Coincident,  // 2 rows: s[0] on body[0] and s[1] on body[1] are one point
  OnLine,      // 1 row: s[0] on body[0] on the line of body[1] through s[1] with normal n
  OnCircle,    // 1 row: s[0] on body[0] at distance c[0] from s[1] on body[1]
  Angles,      // 1 row: sum c[k] theta(body[k]) = value + driven phi
  Distance3,   // 1 row: s[0] on body[0] at distance c[0] from s[1] on body[1] in space, each in
               // its plane class's frame[k] at depth[k] (distance3.h)
  Hold,        // 1 row: coordinate col of q held at value (an idle freedom; not an element's)
  Cam,         // 1 row: follower body[0] displaced by s(theta) of cam body[1] turning relative to
               // guide body[2] (cam_row.h); its reaction is the contact's, another row's
};

struct Row {
  Primitive kind = Primitive::Coincident;
  int body[3] = {-1, -1, -1};                // system body indices, -1 for the ground (or unused)
  Vec2 s[2] = {Vec2::Zero(), Vec2::Zero()};  // local vectors, in their bodies' frames
  Vec2 n = Vec2::Zero();                     // OnLine: unit normal, in body[1]'s frame
  double c[3] = {0, 0, 0};                   // Angles: coefficients; OnCircle: c[0] radius
  double value = 0;                          // Angles, Hold: the constant
  double driven = 0;         // Angles: coefficient of the driver angle (sigma on the driver's row)
  int col = -1;              // Hold: the coordinate
  int frame[2] = {0, 0};     // Distance3: each end's plane class (System::frames)
  double depth[2] = {0, 0};  // Distance3: each end's depth along its class's normal
  int row = 0;               // first row in the system's equation list
  int joint = -1;            // index in Mechanism::joints (the driver's: its pin), -1 for a hold
  std::shared_ptr<const CamRow> cam;  // Cam: its follower and motion programme

  int rows() const { return kind == Primitive::Coincident ? 2 : 1; }
  bool isDriver() const { return driven != 0; }
  // The bodies it joins (1 to 3).
  int bodies() const {
    return kind == Primitive::Hold                                              ? 1
           : kind == Primitive::Cam || (kind == Primitive::Angles && c[2] != 0) ? 3
                                                                                : 2;
  }
  // Whether its numbers (positions, directions, constants, a cam's programme) are o's.
  bool sameNumbers(const Row& o) const;
};

}  // namespace linkage
