// Ball rod: a rod with a ball joint at each end keeps point a of one body and point b of another
// at their drawn distance in space, whatever planes the bodies move in (linkage/space.h). It
// has no mass and no body of its own.
//
//   file:     {"type": "ball-rod", "a": "crank.B", "b": "rocker.C"}
//   rows:     Distance3(a on its body, b on its body, l = |a - b| as drawn, in the world)
//                                                                            1 equation
//   centre:   on the line through a and b, for bodies of parallel planes (the rod's shadow on
//             them is a link); none between planes that are not parallel
//   drawn:    a rod between two balls
#include "elements/ball_rod.h"

#include "elements/frames.h"
#include "elements/rows.h"
#include "linkage/space.h"

namespace linkage {

namespace {

constexpr const char* kForceColumns[] = {"axial_N"};

constexpr FieldSpec kFields[] = {{"a", FieldType::Point, 0, true},
                                 {"b", FieldType::Point, 1, true}};

double drawnLength(const Mechanism& m, const Joint& j) {
  return (worldOf(m, *m.point(j.a)) - worldOf(m, *m.point(j.b))).norm();
}

std::string check(const Mechanism& m, const Joint& j, const char*& where) {
  const Point *a = m.point(j.a), *b = m.point(j.b);
  const Body* g = m.ground();
  where = "b";
  if (a->body == b->body) return "both ends are on one body: a rod joins two";
  if (g && a->body == g->id && b->body == g->id) return "both ends are on the ground";
  if (!(drawnLength(m, j) >= 1e-9))
    return "the ends are closer than 1e-9 mm: a rod of no length keeps nothing";
  return {};
}

bool compile(const Mechanism& m, const Joint& j, const Frames& f, std::vector<Row>& rows,
             std::string&) {
  const Frames::InSpace a = f.inSpace(j.a), b = f.inSpace(j.b);
  Row r;
  r.kind = Primitive::Distance3;
  r.body[0] = a.body;
  r.s[0] = a.s;
  r.frame[0] = a.frame;
  r.depth[0] = a.depth;
  r.body[1] = b.body;
  r.s[1] = b.s;
  r.frame[1] = b.frame;
  r.depth[1] = b.depth;
  r.c[0] = drawnLength(m, j);
  rows.push_back(r);
  return true;
}

CentreData centre(const Mechanism& m, const Joint& j) {
  const Point *a = m.point(j.a), *b = m.point(j.b);
  CentreData c;
  c.rule = CentreRule::LineThrough;
  c.bodies[0] = c.pBody[0] = a->body;
  c.bodies[1] = c.pBody[1] = b->body;
  c.p[0] = a->pos;
  c.p[1] = b->pos;
  return c;
}

void symbol(const Mechanism& m, const Joint& j, JointSymbol& s) {
  const Point *a = m.point(j.a), *b = m.point(j.b);
  s.bodies[0] = a ? a->body : BodyId{};
  s.bodies[1] = b ? b->body : BodyId{};
}

void place(const Mechanism&, const Joint& j, const Pose& pose, JointSymbol& s) {
  s.at = pose.point(j.a);
  s.at2 = pose.point(j.b);
}

}  // namespace

ElementKind ballRodElement(JointType t) {
  return {t,
          "ball-rod",
          "keeps points \"a\" and \"b\" at their distance",
          Role::Distance,
          1,
          kFields,
          check,
          compile,
          centre,
          symbol,
          place,
          kForceColumns,
          nullptr,
          true};
}

}  // namespace linkage
