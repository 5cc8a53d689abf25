// What an element kind's right-click menu entries act through (ElementUi::jointMenu, bodyMenu,
// pointMenu): the document, an edit as one undo step, a tool started at a thing, a Properties
// field to type in. The toolbox (ui/tools/toolbox.h) implements it, so that a kind's files
// include no tool.
#pragma once

#include <QCoreApplication>
#include <QString>
#include <functional>
#include <string>

#include "linkage/model.h"

namespace linkage::ui {

class Document;

// Where a tool started from a menu begins: at a point (a slot joint's point, a link's first
// point), on a body (the first of a gear pair, the body a slot is cut in), at a place (mm).
struct ToolStart {
  // Initialised, so that a start naming one of them (.point = p) leaves the other unset
  // without a missing-initialiser warning.
  PointId point{};
  BodyId body{};
  Vec2 at = Vec2::Zero();
};

class MenuActions {
  Q_DECLARE_TR_FUNCTIONS(MenuActions)

 public:
  virtual Document* document() const = 0;
  // An edit of a copy of the design made as one undo step (drawn where the mechanism is now),
  // or refused with the reason on the status bar.
  virtual void editWith(const QString& text,
                        const std::function<bool(Mechanism&, std::string&)>& change) = 0;
  // The tool named `name` (a ToolSpec's) made current and started at `from`.
  virtual void startTool(const QString& name, const ToolStart& from) = 0;
  // Selects `joint` alone and asks for its Properties field named `label`, the keyboard in it
  // (a gear's "Edit Ratio..." on its menu).
  virtual void editField(JointId joint, const QString& label) = 0;

 protected:
  ~MenuActions() = default;
};

}  // namespace linkage::ui
