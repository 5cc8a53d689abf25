// Pin (revolute joint): point a of one body and point b of another are one point at all times.
//
//   file:     {"type": "pin", "a": "body.P", "b": "body.Q"}
//   rows:     Coincident(a on its body, b on its body)                      2 equations
//   centre:   at the pin (a primary centre)
//   drawn:    a pin at its point; a ground pivot (hatched) when one side is the ground
#include "elements/pin.h"

#include "elements/frames.h"
#include "elements/rows.h"

namespace linkage {

namespace {

constexpr const char* kForceColumns[] = {"fx_N", "fy_N"};

constexpr FieldSpec kFields[] = {{"a", FieldType::Point, 0, true},
                                 {"b", FieldType::Point, 1, true}};

std::string check(const Mechanism&, const Joint&, const char*&) {
  return {};
}

bool compile(const Mechanism&, const Joint& j, const Frames& f, std::vector<Row>& rows,
             std::string&) {
  const PointLocation *a = f.point(j.a), *b = f.point(j.b);
  Row r;
  r.kind = Primitive::Coincident;
  r.body[0] = a->body;
  r.s[0] = a->s;
  r.body[1] = b->body;
  r.s[1] = b->s;
  rows.push_back(r);
  return true;
}

CentreData centre(const Mechanism& m, const Joint& j) {
  const Point *a = m.point(j.a), *b = m.point(j.b);
  CentreData c;
  c.rule = CentreRule::AtPoint;
  c.bodies[0] = c.pBody[0] = a->body;
  c.bodies[1] = b->body;
  c.p[0] = a->pos;
  return c;
}

void symbol(const Mechanism& m, const Joint& j, JointSymbol& s) {
  const Point *a = m.point(j.a), *b = m.point(j.b);
  s.bodies[0] = a ? a->body : BodyId{};
  s.bodies[1] = b ? b->body : BodyId{};
  const Body* g = m.ground();
  s.groundPivot = g && (s.bodies[0] == g->id || s.bodies[1] == g->id);
}

void place(const Mechanism&, const Joint& j, const Pose& pose, JointSymbol& s) {
  s.at = pose.point(j.a);
}

}  // namespace

ElementKind pinElement(JointType t) {
  return {t,
          "pin",
          "joins points \"a\" and \"b\"",
          Role::Revolute,
          2,
          kFields,
          check,
          compile,
          centre,
          symbol,
          place,
          kForceColumns,
          nullptr,
          false};
}

}  // namespace linkage
