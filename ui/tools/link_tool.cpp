#include "tools/link_tool.h"

#include "canvas/canvas_scene.h"
#include "document/commands.h"
#include "document/document.h"
#include "tools/tool_overlay.h"
#include "tools/tool_registry.h"

namespace linkage::ui {

namespace {
[[maybe_unused]] const bool registered = registerTool(
    "link", [](ToolContext* ctx, std::optional<JointType>) -> Tool* { return new LinkTool(ctx); });
}  // namespace

QString LinkTool::hint() const {
  if (vertices_.empty())
    return tr("Link: click where it starts (on a point of another link: a pin there)");
  return tr("Link: click its next point; Enter, double-click or right-click ends it (%1 so far); "
            "Esc cancels")
      .arg(vertices_.size());
}

void LinkTool::deactivate() {
  cancel();
}

void LinkTool::showPath(std::optional<Vec2> cursor) {
  std::vector<Vec2> at;
  for (const LinkVertex& v : vertices_) at.push_back(v.at);
  ctx().overlay->setPath(at, cursor);
}

void LinkTool::press(const CanvasMouse& e) {
  if (e.button != Qt::LeftButton) return;
  LinkVertex v;
  v.at = e.snap.at;
  if (e.snap.kind == Snap::Kind::Point) {
    // A second click on a point already in this link is no new point.
    for (const LinkVertex& w : vertices_)
      if (w.pinTo == e.snap.point) return;
    v.pinTo = e.snap.point;
  }
  if (!vertices_.empty() && (vertices_.back().at - v.at).norm() < 1e-9) return;
  vertices_.push_back(v);
  showPath(e.snap.at);
  emit hintChanged();
}

void LinkTool::startAt(const LinkVertex& v) {
  vertices_ = {v};
  showPath(v.at);
  emit hintChanged();
}

void LinkTool::move(const CanvasMouse& e) {
  if (!vertices_.empty()) showPath(e.snap.at);
}

void LinkTool::doubleClick(const CanvasMouse&) {
  // The press of the double click added its point already. A double click that is only the
  // first point (two quick clicks at one place, the first of them for something else) does
  // not end the link.
  if (vertices_.size() >= 2) finish();
}

bool LinkTool::key(QKeyEvent* e) {
  if (e->key() == Qt::Key_Return || e->key() == Qt::Key_Enter) {
    finish();
    return true;
  }
  if (e->key() == Qt::Key_Escape && drawing()) {
    cancel();
    say(tr("Link cancelled"));
    return true;
  }
  return false;
}

bool LinkTool::rightClick(const CanvasMouse&) {
  if (!drawing()) return false;
  finish();
  return true;
}

void LinkTool::cancel() {
  vertices_.clear();
  ctx().overlay->clearPreview();
  emit hintChanged();
}

void LinkTool::finish() {
  if (vertices_.size() < 2) {
    if (!vertices_.empty()) say(tr("A link needs two points: click another, or Esc"), true);
    return;
  }
  Document* doc = ctx().doc;
  Mechanism m = doc->design();
  std::string why;
  // Into the plane the canvas shows (a machine in space is drawn one plane at a time).
  const BodyId b = addLink(m, vertices_, &why, ctx().scene->shownPlane());
  if (!b) {
    say(QString::fromStdString(why), true);
    cancel();
    return;
  }
  const QString name = QString::fromStdString(m.body(b)->name);
  cancel();
  commitEdit(doc, tr("Add link %1").arg(name), std::move(m));
  say(tr("Added %1").arg(name));
}

}  // namespace linkage::ui
