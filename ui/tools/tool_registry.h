// The tools by name, each registered by its own file (registerTool at static initialisation:
// the library is linked whole, ui/CMakeLists.txt): the toolbox makes its own tools and the
// element kinds' (ToolSpec::maker, ui/elements/element_ui.h) from here, so that tools/ lists no
// kind and ui/elements/ includes no tool.
#pragma once

#include <QString>
#include <optional>

#include "linkage/model.h"

namespace linkage::ui {

class Tool;
struct ToolContext;

// `kind`: the element kind whose tool is made (one tool serves the slot joints: a slider
// block or a pin in a slot); none for the toolbox's own tools.
using ToolMaker = Tool* (*)(ToolContext* ctx, std::optional<JointType> kind);

// Registers `make` as `name`; true (to initialise a static with).
bool registerTool(const char* name, ToolMaker make);
// A new tool made by the maker registered as `name`, or nullptr when there is none.
Tool* makeTool(const QString& name, ToolContext* ctx, std::optional<JointType> kind = std::nullopt);

}  // namespace linkage::ui
