// The Python model's edits: the editor's typed dimensions (linkage/edits.h), solved as the editor
// solves them (editAtPose at the design's crank angle 0), and its writer.
#include <algorithm>
#include <cmath>

#include "linkage/edits.h"
#include "linkage/io/model_file.h"
#include "linkage/optimize.h"
#include "linkage/sensitivity.h"
#include "py_model.h"

namespace linkage::py {

namespace {

std::vector<PointId> pointsOf(const Mechanism& m, BodyId body) {
  std::vector<PointId> out;
  for (const Point& p : m.points)
    if (p.body == body) out.push_back(p.id);
  return out;
}

// A side's index in setSideLengths' order (|P0P1|, |P1P2|, |P0P2|) from its dimension's name
// (linkage/sensitivity.h: `body.P0-P1`, `body.P1-P2`, `body.P0-P2`); -1 when it names none.
int sideIndex(const Mechanism& m, const Body& b, const std::string& sides) {
  const std::vector<PointId> p = pointsOf(m, b.id);
  if (p.size() != 2 && p.size() != 3) return -1;
  auto name = [&](int i) { return m.point(p[i])->name; };
  if (sides == name(0) + "-" + name(1)) return 0;
  if (p.size() == 3 && sides == name(1) + "-" + name(2)) return 1;
  if (p.size() == 3 && sides == name(0) + "-" + name(2)) return 2;
  return -1;
}

}  // namespace

void Model::commit(Mechanism next) {
  PoseEdit e = editAtPose(base_, std::move(next));
  if (!e.solved) {
    Kinematics trial;
    Status s = trial.load(e.design);
    if (s.ok()) s = Status::badModel("the edited mechanism cannot be solved at crank angle 0");
    throw BadInput(s.message);
  }
  // Loaded afresh, as a command line reads the saved file: every later answer is the same.
  Kinematics fresh;
  raise(fresh.load(e.design));
  design_ = std::move(e.design);
  base_ = std::move(fresh);
}

void Model::setSideLengths(const std::string& body, const std::vector<double>& lengths) {
  Mechanism next = design_;
  std::string why;
  if (!linkage::setSideLengths(next, bodyNamed(body), lengths, &why))
    throw BadInput(body + ": " + why);
  commit(std::move(next));
}

std::vector<double> Model::sideLengths(const std::string& body) const {
  return linkage::sideLengths(design_, bodyNamed(body));
}

void Model::setPoint(const std::string& point, double x, double y) {
  if (!std::isfinite(x) || !std::isfinite(y))
    throw BadInput(point + ": a position must be finite numbers");
  Mechanism next = design_;
  // The points pinned to it are one place in the drawing: they go with it, as in the editor.
  for (PointId q : pinnedTogether(next, pointNamed(point))) next.point(q)->pos = Vec2(x, y);
  commit(std::move(next));
}

void Model::setDimension(const std::string& name, double value) {
  const std::vector<Dimension> dims = linkage::dimensions(design_);
  auto d =
      std::find_if(dims.begin(), dims.end(), [&](const Dimension& x) { return x.name == name; });
  if (d == dims.end())
    throw BadInput("no dimension \"" + name + "\" (Model.dimensions lists them)");
  const size_t dot = name.find('.');
  const Body* b = design_.bodyNamed(name.substr(0, dot));
  if (b && b->ground && (name.ends_with(".x") || name.ends_with(".y"))) {
    const std::string point = name.substr(0, name.size() - 2);
    Vec2 at = design_.point(pointNamed(point))->pos;
    (name.ends_with(".x") ? at.x() : at.y()) = value;
    setPoint(point, at.x(), at.y());
    return;
  }
  const int side = b ? sideIndex(design_, *b, name.substr(dot + 1)) : -1;
  if (side < 0) {
    // Any other dimension (a later point's distances, along and across, a slot's offset and
    // angle, a gear's ratio) set exactly as the optimiser sets it (linkage/optimize.h): nothing
    // pinned to it moves, and the solve closes the joints.
    Mechanism next = design_;
    if (Status s = linkage::setDimension(next, name, value); !s.ok())
      throw BadInput(name + ": " + s.message);
    commit(std::move(next));
    return;
  }
  std::vector<double> lengths = linkage::sideLengths(design_, b->id);
  lengths[static_cast<size_t>(side)] = value;
  setSideLengths(b->name, lengths);
}

void Model::save(const std::string& path) const {
  const WriteResult w = saveMechanismFile(design_, path);
  if (!w.ok) throw BadInput(w.error);
}

}  // namespace linkage::py
