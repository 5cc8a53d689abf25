// A slot's curve, what a pin or a block in it keeps to: the straight line through its two ends,
// or the circular arc through its three points (start, a point on the way, end).
//
// Arc: the centre is where the perpendicular bisectors of p0-mid and mid-p1 meet; the arc runs
// from p0 through mid to p1, `sweep` radians (positive counter-clockwise) from the angle `a0` of
// p0 about the centre. Positions along a slot (its travel) are arc lengths from p0.
#pragma once

#include <optional>
#include <string>

#include "linkage/model.h"

namespace linkage {

struct Guide {
  bool arc = false;
  Vec2 p0 = Vec2::Zero(), p1 = Vec2::Zero();
  // Line: unit direction from p0 to p1 and the normal perp(direction).
  Vec2 direction = Vec2::UnitX(), normal = Vec2::UnitY();
  // Arc: centre, radius, the angle of p0 about the centre, signed sweep to p1 through mid.
  Vec2 centre = Vec2::Zero();
  double radius = 0, a0 = 0, sweep = 0;

  double length() const;
  // The unit normal of the curve at (or, for an arc, towards) the sketch point p: the line's
  // normal, or the direction from the centre to p.
  Vec2 normalAt(const Vec2& p) const;
  // The unit tangent at p, in the direction from p0 to p1.
  Vec2 tangentAt(const Vec2& p) const;
  // The point at arc length t from p0 (any t: beyond the ends on the curve's continuation).
  Vec2 at(double t) const;
  // Arc length from p0 of the point of the curve (its continuation included) nearest to p:
  // for an arc, in (-(2 pi r - |sweep| r) / 2, |sweep| r + the same], so that a point beyond
  // either end is measured from that end.
  double along(const Vec2& p) const;
  // The point of the slot (between its ends) nearest to p, and its distance.
  Vec2 nearest(const Vec2& p) const;
  double distance(const Vec2& p) const { return (nearest(p) - p).norm(); }
  // The point of the whole line or circle nearest to p (a snap onto the slot's curve).
  Vec2 project(const Vec2& p) const;
};

// The curve of a slot as drawn; nullopt with `why` when it has none: two ends in one place, or
// three points on one line (or so nearly that the radius exceeds 1e12 mm).
std::optional<Guide> guideOf(const Slot& s, std::string* why = nullptr);

// Whether a slot has a curve where it lies, with `why` when not: the ground's ends written with
// z (a machine in space) in the world, so that a slot along z or an arc in a plane square to the
// drawing is sound though its x, y alone are not; any other slot as guideOf reads it.
bool soundSlot(const Slot& s, std::string* why = nullptr);

// The circle through three points: false when they are on one line.
bool circleThrough(const Vec2& a, const Vec2& b, const Vec2& c, Vec2& centre, double& radius);

}  // namespace linkage
