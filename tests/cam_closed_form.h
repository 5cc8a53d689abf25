// A cam's followers in closed form over std::complex, for the cam sensitivity tests (complex
// step, tests/complex_step.h): the displacement s from the laws' normalised shapes, linear in
// the rises, and a translating follower's point where its slot's line meets the circle of base +
// roller about the cam's centre (a flat face: at base along the slot from the foot of O), then s
// along the line.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "cam_fixtures.h"
#include "complex_step.h"
#include "linkage/cam.h"
#include "linkage/cam_joint.h"
#include "linkage/guide.h"
#include "linkage/io/model_file.h"

namespace linkage::test {

inline constexpr double kCamDeg = M_PI / 180;

inline Mechanism parsed(const std::string& text) {
  LoadResult r = parseMechanism(text);
  EXPECT_TRUE(r.mechanism) << r.error;
  return r.mechanism ? std::move(*r.mechanism) : Mechanism{};
}

inline CVec rot(C t, CVec a) {
  return {std::cos(t) * a.x - std::sin(t) * a.y, std::sin(t) * a.x + std::cos(t) * a.y};
}

// s, s', s'' at theta (radians) of segments with rises h (times `scale`).
struct Law {
  C s, v, a;
};
inline Law law(const std::vector<cam::Segment>& segs, const std::vector<C>& h, double scale,
               double theta) {
  double from = 0;
  Law out{0, 0, 0};
  for (size_t k = 0; k < segs.size(); ++k) {
    const double to = segs[k].toDeg * kCamDeg;
    if (theta >= to) {
      out.s += scale * h[k];
      from = to;
      continue;
    }
    if (segs[k].law) {
      const double beta = to - from;
      const cam::Normalised n = cam::evaluate(*segs[k].law, (theta - from) / beta);
      out.s += scale * h[k] * n.s;
      out.v = scale * h[k] * n.v / beta;
      out.a = scale * h[k] * n.a / (beta * beta);
    }
    break;
  }
  return out;
}

// The follower's point (position, and rates per radian of the cam) in the dimensions' terms.
struct PV {
  CVec p, v, a;
};
using Values = std::map<std::string, C>;

inline std::vector<cam::Segment> segmentsOf(const Mechanism& m) {
  for (const Joint& j : m.joints)
    if (std::optional<CamJoint> c = camJoint(m, j)) return c->program.segments();
  ADD_FAILURE() << "no cam";
  return {};
}

inline Values withRises(Values v, const std::vector<cam::Segment>& segs, const std::string& pre) {
  for (size_t k = 0; k < segs.size(); ++k) v[pre + "h" + std::to_string(k)] = segs[k].rise;
  return v;
}

// The translating follower of m (TranslatingCam's, flat or not): its dimensions' values (the
// slot's offset and angle as steps from the drawing) and R, dR/dtheta, d2R/dtheta2 at
// values["theta"] (radians of the cam), with the slot's direction.
struct TranslatingForm {
  Values values;
  std::string pre;  // the cam's dimensions' prefix
  std::function<PV(const Values&)> at;
  std::function<CVec(const Values&)> along;
};

inline TranslatingForm translatingForm(const Mechanism& m, const TranslatingCam& spec) {
  const std::vector<cam::Segment> segs = segmentsOf(m);
  const Slot& slot = m.slots.front();
  const Vec2 n = guideOf(slot)->normal, p0 = slot.p0;
  TranslatingForm out;
  const std::string pre = out.pre = "cam:follower.R.";
  out.values = withRises({{"ground.O.x", 0},
                          {"ground.O.y", 0},
                          {"ground.guide.offset", 0},
                          {"ground.guide.angle", 0},
                          {pre + "base", spec.base},
                          {pre + "roller", spec.roller}},
                         segs, pre);
  out.along = [](const Values& x) {
    return rot(x.at("ground.guide.angle") * kCamDeg, CVec{C(0), C(1)});
  };
  const bool flat = spec.flat;
  out.at = [=](const Values& x) -> PV {
    const CVec O{x.at("ground.O.x"), x.at("ground.O.y")};
    const C off = x.at("ground.guide.offset");
    const CVec P0 = CVec{p0.x(), p0.y()} + off * CVec{n.x(), n.y()};
    const CVec d = rot(x.at("ground.guide.angle") * kCamDeg, CVec{C(0), C(1)});
    const CVec D = P0 - O;
    const C r = x.at(pre + "base") + x.at(pre + "roller"), dd = dot(D, d);
    const C t = flat ? r - dd : -dd + std::sqrt(dd * dd - dot(D, D) + r * r);
    std::vector<C> h(segs.size());
    for (size_t k = 0; k < h.size(); ++k) h[k] = x.at(pre + "h" + std::to_string(k));
    const Law s = law(segs, h, 1, x.at("theta").real());
    return {P0 + (t + s.s) * d, s.v * d, s.a * d};
  };
  return out;
}

}  // namespace linkage::test
