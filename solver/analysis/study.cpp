// Parameter studies: see linkage/study.h.
#include "linkage/study.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>

#include "analysis/study_variant.h"
#include "linkage/elements.h"

namespace linkage {

namespace {

// The diagonal of the drawing's bounding box.
double drawingSize(const Mechanism& m) {
  Vec2 lo = Vec2::Constant(INFINITY), hi = Vec2::Constant(-INFINITY);
  auto add = [&](const Vec2& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  };
  for (const Point& p : m.points) add(p.pos);
  for (const Slot& s : m.slots) add(s.p0), add(s.p1);
  return m.points.empty() ? 1 : std::max((hi - lo).norm(), 1e-300);
}

}  // namespace

std::vector<PointId> movedTogether(const Mechanism& m, PointId p) {
  const Point* start = m.point(p);
  if (!start) return {};
  const double tol = 1e-9 * drawingSize(m);
  std::vector<PointId> found{p};
  for (size_t i = 0; i < found.size(); ++i) {
    const Point* at = m.point(found[i]);
    for (const Joint& j : m.joints) {
      if (kindOf(j).role != Role::Revolute || (j.a != found[i] && j.b != found[i])) continue;
      const PointId other = j.a == found[i] ? j.b : j.a;
      const Point* o = m.point(other);
      if (!o || (o->pos - at->pos).norm() > tol) continue;
      if (std::find(found.begin(), found.end(), other) == found.end()) found.push_back(other);
    }
  }
  std::vector<PointId> ordered;
  for (const Point& q : m.points)
    if (std::find(found.begin(), found.end(), q.id) != found.end()) ordered.push_back(q.id);
  return ordered;
}

Status movePoint(Mechanism& m, const PointMove& mv, double t) {
  if (!m.contains(mv.point))
    return Status::failure(StatusCode::BadModel, "the point to move is not in the mechanism");
  const bool line = mv.kind == PointMove::Kind::Line;
  if (!std::isfinite(t) ||
      (line ? !mv.by.allFinite() : !mv.centre.allFinite() || !std::isfinite(mv.angleDeg)))
    return Status::failure(StatusCode::BadModel, "the move is not given by finite numbers");
  const Rot turn = Rot::of(t * mv.angleDeg * M_PI / 180);
  for (PointId id : movedTogether(m, mv.point)) {
    Point* p = m.point(id);
    p->pos = line ? Vec2(p->pos + t * mv.by) : Vec2(mv.centre + turn * (p->pos - mv.centre));
  }
  return Status::success();
}

namespace {

// What a spec that cannot run is missing, or "" (then `dir` is the stroke's direction).
std::string specProblem(const Mechanism& m, const StudySpec& spec, Vec2& dir) {
  if (!m.driver) return "the mechanism has no driver";
  if (!m.contains(spec.move.point)) return "the point to move is not in the mechanism";
  if (!m.contains(spec.point)) return "the point to measure is not in the mechanism";
  for (BodyId b : spec.bodies)
    if (!m.contains(b)) return "a body to measure is not in the mechanism";
  if (spec.values < 1) return "a study needs at least one value of t";
  if (spec.steps < 4) return "a study needs at least 4 steps per turn";
  if (!std::isfinite(spec.from) || !std::isfinite(spec.to)) return "t is not finite";
  Mechanism probe = m;
  if (Status s = movePoint(probe, spec.move, spec.from); !s.ok()) return s.message;
  dir = spec.direction.value_or(defaultDirection(m, spec.point));
  if (!dir.allFinite() || dir.norm() == 0) return "the direction is not a finite non-zero vector";
  return "";
}

}  // namespace

Study runStudy(const Mechanism& m, const StudySpec& spec, const StudyControl& control) {
  Study out;
  Vec2 dir;
  if (std::string why = specProblem(m, spec, dir); !why.empty()) {
    out.status = Status::failure(StatusCode::BadModel, why);
    return out;
  }
  out.joints = transmissionJoints(m);
  out.rows.resize(spec.values);
  for (int i = 0; i < spec.values; ++i)
    out.rows[i].t =
        spec.values == 1 ? spec.from : spec.from + (spec.to - spec.from) * i / (spec.values - 1);
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  out.threads = std::min(spec.threads > 0 ? spec.threads : cores, spec.values);
  std::atomic<int> next{0}, done{0};
  std::vector<char> computed(spec.values, 0);
  // A variant taken is computed: the rows computed are the first ones, whenever a cancel comes.
  auto work = [&] {
    while (!(control.cancel && *control.cancel)) {
      const int i = next++;
      if (i >= spec.values) break;
      Mechanism moved = m;
      const double t = out.rows[i].t;
      movePoint(moved, spec.move, t);
      out.rows[i] = measureVariant(moved, spec, dir, out.joints);
      out.rows[i].t = t;
      computed[i] = 1;
      if (control.progress) control.progress(++done, spec.values);
    }
  };
  std::vector<std::thread> pool;
  for (int k = 1; k < out.threads; ++k) pool.emplace_back(work);
  work();
  for (std::thread& th : pool) th.join();
  if (done < spec.values) {
    out.cancelled = true;
    std::vector<StudyRow> kept;
    for (int i = 0; i < spec.values; ++i)
      if (computed[i]) kept.push_back(std::move(out.rows[i]));
    out.rows = std::move(kept);
  }
  return out;
}

}  // namespace linkage
