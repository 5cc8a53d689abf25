// What the editor does with each element kind (linkage/elements.h), registered in one table
// (element_ui.cpp) in JointType order: the canvas item that draws a joint of the kind, the tool
// that makes one, its rows in the properties panel and its entries in the right-click menus.
// The canvas, the toolbox and the panel ask this table; nothing else branches on the kind.
// docs/solver.md lists the files a kind takes.
#pragma once

#include <QString>
#include <span>

#include "linkage/drawing.h"
#include "linkage/elements.h"

class QMenu;

namespace linkage::ui {

struct CanvasContext;
class JointItem;
class MenuActions;
class Form;

struct ToolSpec {
  const char* name;  // the action is "tool:<name>"
  const char* text;  // menu text (translated in the "Toolbox" context)
  const char* key;   // its shortcut
  const char* tip;   // status tip
  const char* icon;  // resources/icons/<icon>.svg
  // The tool it is made with, by its registered name (ui/tools/tool_registry.h): "gear",
  // "slotJoint" (told the kind); nullptr: the toolbox's own tools make it (a pin: link, ground).
  const char* maker;
};

struct ElementUi {
  JointType type;
  const char* describe;  // for people, in menus and the panel: "slider (the block keeps ...)"
  // The item for a joint's symbol (placed at each pose by the scene); `d` for body numbers.
  JointItem* (*item)(const CanvasContext* ctx, const JointSymbol& s, const Drawing& d);
  ToolSpec tool;
  // Its rows on a joint's Properties form, after the title (forms/form.h).
  void (*form)(Form& panel, JointId id);
  // Its entries on a joint's right-click menu, acting through the toolbox (menu_actions.h).
  void (*jointMenu)(MenuActions& box, QMenu& menu, const Joint& j);
  // Entries on a moving body's and on a point's right-click menus (nullptr: none).
  void (*bodyMenu)(MenuActions& box, QMenu& menu, BodyId body);
  void (*pointMenu)(MenuActions& box, QMenu& menu, PointId point);
};

const ElementUi& elementUi(JointType t);
std::span<const ElementUi* const> elementUis();
QString describe(JointType t);

// Shared by the kinds' files: the textbook number of a body in a drawing (0 when unknown); a
// "Type" choice among the kinds that read the same fields (a slider and a pin in a slot change
// into each other) in the panel and in a joint's menu; the point's coordinates, moving every
// point pinned to it.
int bodyNumber(const Drawing& d, BodyId b);
void addTypeChoice(Form& panel, JointId id);
void addTypeMenu(MenuActions& box, QMenu& menu, const Joint& j);
void addPointPlace(Form& panel, PointId a);
// A point's menu entry that starts a slot joint's tool at the point ("... in a Slot Here").
void addSlotJointStart(MenuActions& box, QMenu& menu, PointId p, const char* tool,
                       const char* text);
// A slot joint's panel rows: its type, its point's place.
void slotJointForm(Form& panel, JointId id);

}  // namespace linkage::ui
