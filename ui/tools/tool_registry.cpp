#include "tools/tool_registry.h"

#include <map>

namespace linkage::ui {

namespace {
// A function's static: made before the first registration, whatever the files' order.
std::map<QString, ToolMaker>& makers() {
  static std::map<QString, ToolMaker> all;
  return all;
}
}  // namespace

bool registerTool(const char* name, ToolMaker make) {
  makers()[QString::fromLatin1(name)] = make;
  return true;
}

Tool* makeTool(const QString& name, ToolContext* ctx, std::optional<JointType> kind) {
  const auto it = makers().find(name);
  return it == makers().end() ? nullptr : it->second(ctx, kind);
}

}  // namespace linkage::ui
