// Slider (prismatic joint): a block, the body of point a, runs in a slot of another body.
//
//   file:     {"type": "slider", "a": "block.P", "slot": "body.S"}
//   straight slot:  OnLine(a, the slot's line) + Angles(theta_block - theta_slot = 0)
//                   2 equations: the block keeps its drawn angle to the slot
//   arc slot:       Coincident(the block's point C', the arc's centre C)     2 equations
//                   a block in a curved guide keeps its angle to the arc's radius: it turns
//                   about C with the radius, so the point of the block at C (C' = a moved
//                   along the radius by the radius: C itself when a is drawn on the arc) stays
//                   at C. A drawing with a off the arc is assembled onto it.
//   centre:   straight: at infinity normal to the slot; arc: at the arc's centre
//   drawn:    the block's body as a block on its slot, along the slot (its tangent on an arc)
#include "elements/slider.h"

#include "elements/frames.h"
#include "elements/rows.h"
#include "elements/slot_joint.h"

namespace linkage {

namespace {

constexpr const char* kColumns[] = {"fx_N", "fy_N", "m_Nm"};

bool compile(const Mechanism&, const Joint& j, const Frames& f, std::vector<Row>& rows,
             std::string& why) {
  const PointLocation* a = f.point(j.a);
  const Slot* s = f.slot(j.slot);
  const std::optional<Guide> g = slot_joint::guide(f, j, why);
  if (!g) return false;
  const int sb = f.body(s->body);
  Row r;
  r.body[0] = a->body;
  r.body[1] = sb;
  if (g->arc) {
    const Vec2 p = f.position(j.a), d = p - g->centre;
    if (!(d.norm() > 1e-9 * g->radius)) {
      why = "the block's point is at the centre of its arc slot: it has no radius to keep";
      return false;
    }
    r.kind = Primitive::Coincident;
    r.s[0] = f.local(a->body, p - g->radius * d.normalized());
    r.s[1] = f.local(sb, g->centre);
    rows.push_back(r);
    return true;
  }
  r.kind = Primitive::OnLine;
  r.s[0] = a->s;
  r.s[1] = f.local(sb, g->p0);
  r.n = g->normal;
  rows.push_back(r);
  Row angle;
  angle.kind = Primitive::Angles;
  angle.body[0] = a->body;
  angle.body[1] = sb;
  angle.c[0] = 1;  // both bodies are at angle 0 as drawn: the drawn relative angle is 0
  angle.c[1] = -1;
  rows.push_back(angle);
  return true;
}

CentreData centre(const Mechanism& m, const Joint& j) {
  const Slot* s = m.slot(j.slot);
  CentreData c = slot_joint::pair(m, j);
  const std::optional<Guide> g = guideOf(*s);
  if (g && g->arc) {
    c.rule = CentreRule::AtPoint;
    c.pBody[0] = s->body;
    c.p[0] = g->centre;
  } else {
    c.rule = CentreRule::AtInfinity;
    c.nBody = s->body;
    c.n = g ? g->normal : Vec2::UnitY();
  }
  return c;
}

}  // namespace

ElementKind sliderElement(JointType t) {
  return {t,
          "slider",
          "joins point \"a\" to a \"slot\"",
          Role::Prismatic,
          2,
          slot_joint::kFields,
          slot_joint::noCheck,
          compile,
          centre,
          slot_joint::symbol,
          slot_joint::place,
          kColumns,
          nullptr,
          false};
}

}  // namespace linkage
