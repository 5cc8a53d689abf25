// The canvas's tools with their actions (toolbar, menu, shortcut, status tip), the one that is
// active, and the routing of the canvas's mouse and keys to it (after the view's own zoom and
// pan). Also the commands on the selection: Delete, Flip assembly, and the right-click menus.
#pragma once

#include <QActionGroup>
#include <QObject>
#include <functional>
#include <memory>
#include <vector>

#include "elements/menu_actions.h"
#include "tools/tool.h"

class QMenu;

namespace linkage::ui {

class PickPointTool;

class Toolbox : public QObject, public MenuActions {
  Q_OBJECT

 public:
  Toolbox(ToolContext ctx, QWidget* actionParent);
  ~Toolbox() override;

  // The tool actions in toolbar order (objectName "tool:select", "tool:link", ...).
  const std::vector<QAction*>& toolActions() const { return actions_; }
  // A tool's action by the tool's name ("select", "link", ...; the element kinds' tools come
  // from their table, ui/elements/, made by the tools registered by name,
  // tools/tool_registry.h), or nullptr.
  QAction* toolAction(const QString& name) const;
  QAction* deleteAction() const { return delete_; }
  QAction* flipAction() const { return flip_; }
  QAction* snapAction() const { return snap_; }
  Tool* tool() const { return current_; }
  void setTool(const QString& name);  // "select", "link", ...
  QString hint() const;
  // Deletes the selection and what depends on it (one undo step).
  void deleteSelection();
  // The menu a right click at `e` opens (what can be done with what is there).
  QMenu* contextMenu(const CanvasMouse& e, QWidget* parent);

  // What the element kinds' menus (ui/elements/) act through (elements/menu_actions.h).
  Document* document() const override { return ctx_.doc; }
  void editWith(const QString& text,
                const std::function<bool(Mechanism&, std::string&)>& change) override;
  void startTool(const QString& name, const ToolStart& from) override;
  void editField(JointId joint, const QString& label) override;

  // The next click on a point of the canvas gives that point to `picked` (tools/
  // pick_point_tool.h), then the select tool is back; Esc or another tool calls `cancelled`.
  // No tool button is checked meanwhile; the status bar says what to click.
  void pickPoint(const QString& purpose, std::function<void(PointId)> picked,
                 std::function<void()> cancelled);
  bool picking() const;

 Q_SIGNALS:
  void hintChanged(const QString& hint);
  void fieldWanted(const QString& label);

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  CanvasMouse mouseAt(const QPoint& viewPos, Qt::MouseButton button, Qt::MouseButtons buttons,
                      Qt::KeyboardModifiers mods) const;
  void add(const QString& name, const QString& text, const QKeySequence& key, const QString& tip,
           Tool* tool);
  void updateCommands();
  template <class Make>
  void makeCommands(Make make);
  void pointMenu(QMenu& menu, const Point& point, const Vec2& at);
  void bodyMenu(QMenu& menu, const Body& body, const Vec2& at);
  void jointMenu(QMenu& menu, const Joint& joint);

  ToolContext ctx_;
  std::vector<std::unique_ptr<Tool>> tools_;
  std::unique_ptr<PickPointTool> picker_;
  std::vector<QAction*> actions_;
  QActionGroup* group_;
  Tool* current_ = nullptr;
  QAction* delete_ = nullptr;
  QAction* flip_ = nullptr;
  QAction* snap_ = nullptr;
};

}  // namespace linkage::ui
