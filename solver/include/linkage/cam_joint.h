// A cam joint as its file and the drawing say (../shared/specs/model-format.md, "Cams";
// elements/cam.cpp): the bodies it joins and the one that guides the follower, the follower's
// kind, its geometry as drawn and its motion programme. What the cam's rows, its centre, its
// drawing and its profile read; the file's checks are those of camJoint().
#pragma once

#include <optional>
#include <string>

#include "linkage/cam.h"
#include "linkage/model.h"

namespace linkage {

struct CamJoint {
  BodyId cam;             // the body of a
  BodyId follower;        // the body of b
  BodyId guide;           // the body the cam is pinned to at a; the follower's joint is to it too
  JointId followerJoint;  // that joint: a slider (translating) or a pin (oscillating)
  cam::Follower kind;
  cam::Place drawn;  // as drawn (the sketch's coordinates): centre a, b, u or pivot, face
  // A translating follower's offset: e = (b - a) . w, w = u turned 90 degrees clockwise.
  double offset = 0;
  cam::Program program;  // s in mm, or in radians for an oscillating follower
};

// The cam joint j of m read and checked against the spec (its references resolve); nullopt
// with why and the field at fault ("base_mm", "motion[2].law", ...) when it is not one.
std::optional<CamJoint> camJoint(const Mechanism& m, const Joint& j, std::string* why = nullptr,
                                 std::string* where = nullptr);

// The same with base and roller not checked against the drawing (the follower need not be at
// its lowest position): what an editor reads to size a cam for a follower as it is drawn
// (linkage/cam_edits.h).
std::optional<CamJoint> camJointAsDrawn(const Mechanism& m, const Joint& j,
                                        std::string* why = nullptr, std::string* where = nullptr);

// The cam's angle theta (radians, counter-clockwise from the drawing) from the rotations of the
// cam's body and the guide's at a pose.
inline double camAngle(const Rot& cam, const Rot& guide) {
  return std::atan2(guide.c * cam.s - guide.s * cam.c, guide.c * cam.c + guide.s * cam.s);
}

}  // namespace linkage
