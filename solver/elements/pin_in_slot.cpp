// Pin in a slot: point a of one body runs in a slot of another, relative rotation free.
//
//   file:     {"type": "pin-in-slot", "a": "body.P", "slot": "body.S"}
//   straight slot:  OnLine(a, the slot's line)                           1 equation
//   arc slot:       OnCircle(a, the arc's centre, its radius)            1 equation
//   centre:   on the normal to the slot through the pin (for an arc: the line through the pin
//             and the arc's centre)
//   drawn:    a filled pin in the slot's channel
#include "elements/pin_in_slot.h"

#include "elements/frames.h"
#include "elements/rows.h"
#include "elements/slot_joint.h"

namespace linkage {

namespace {

constexpr const char* kForceColumns[] = {"fx_N", "fy_N"};

bool compile(const Mechanism&, const Joint& j, const Frames& f, std::vector<Row>& rows,
             std::string& why) {
  const PointLocation* a = f.point(j.a);
  const Slot* s = f.slot(j.slot);
  const std::optional<Guide> g = slot_joint::guide(f, j, why);
  if (!g) return false;
  const int sb = f.body(s->body);
  Row r;
  r.body[0] = a->body;
  r.s[0] = a->s;
  r.body[1] = sb;
  if (g->arc) {
    r.kind = Primitive::OnCircle;
    r.s[1] = f.local(sb, g->centre);
    r.c[0] = g->radius;
  } else {
    r.kind = Primitive::OnLine;
    r.s[1] = f.local(sb, g->p0);
    r.n = g->normal;
  }
  rows.push_back(r);
  return true;
}

CentreData centre(const Mechanism& m, const Joint& j) {
  const Slot* s = m.slot(j.slot);
  CentreData c = slot_joint::pair(m, j);
  c.pBody[0] = c.bodies[0];
  c.p[0] = m.point(j.a)->pos;
  const std::optional<Guide> g = guideOf(*s);
  if (g && g->arc) {
    c.rule = CentreRule::LineThrough;
    c.pBody[1] = s->body;
    c.p[1] = g->centre;
  } else {
    c.rule = CentreRule::LineAlong;
    c.nBody = s->body;
    c.n = g ? g->normal : Vec2::UnitY();
  }
  return c;
}

}  // namespace

ElementKind pinInSlotElement(JointType t) {
  return {t,
          "pin-in-slot",
          "joins point \"a\" to a \"slot\"",
          Role::PointOnCurve,
          1,
          slot_joint::kFields,
          slot_joint::noCheck,
          compile,
          centre,
          slot_joint::symbol,
          slot_joint::place,
          kForceColumns,
          nullptr,
          false};
}

}  // namespace linkage
