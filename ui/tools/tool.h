// The canvas's tools, as KDE Step's creators and every CAD program have them: one tool is
// active; the view hands it the mouse and keys (after its own zoom and pan); it edits the
// document through undo commands. A tool says in one line what the next click does.
#pragma once

#include <QKeyEvent>
#include <QObject>
#include <QPointF>
#include <functional>

#include "elements/menu_actions.h"
#include "tools/picker.h"

class QMenu;

namespace linkage::ui {

class CanvasScene;
class CanvasView;
class Document;
class Selection;
class ToolOverlay;

// What every tool works with.
struct ToolContext {
  Document* doc = nullptr;
  CanvasScene* scene = nullptr;
  CanvasView* view = nullptr;
  Selection* selection = nullptr;
  ToolOverlay* overlay = nullptr;
  std::function<void(const QString&, bool)> message;  // status bar: text, warning
};

// One mouse event in canvas terms.
struct CanvasMouse {
  Vec2 world = Vec2::Zero();  // mm, as the cursor is
  Pick pick;                  // what is under it
  Snap snap;                  // where a click would put a point
  QPoint viewPos;
  Qt::MouseButton button = Qt::NoButton;
  Qt::MouseButtons buttons;
  Qt::KeyboardModifiers modifiers;
};

class Tool : public QObject {
  Q_OBJECT

 public:
  explicit Tool(ToolContext* ctx) : ctx_(ctx) {}
  // What the next click does, for the status bar.
  virtual QString hint() const = 0;
  // Creation tools snap the cursor to points, slots and the grid.
  virtual bool snaps() const { return true; }
  // Made active or left: unfinished work is dropped.
  virtual void activate() {}
  virtual void deactivate() {}
  virtual void press(const CanvasMouse&) {}
  virtual void move(const CanvasMouse&) {}
  virtual void release(const CanvasMouse&) {}
  virtual void doubleClick(const CanvasMouse&) {}
  // Enter, Esc...: true when used.
  virtual bool key(QKeyEvent*) { return false; }
  // A right click: true when the tool used it (ending a link); else the context menu opens.
  virtual bool rightClick(const CanvasMouse&) { return false; }
  // Made current from a right-click menu, at a thing (the point a link starts at): the tool
  // takes what it starts from; the others ignore it.
  virtual void start(const ToolStart&) {}

 Q_SIGNALS:
  void hintChanged();
  // The tool is done and asks for the select tool (Esc with nothing under way).
  void finished();

 protected:
  ToolContext& ctx() const { return *ctx_; }
  void say(const QString& text, bool warning = false) const {
    if (ctx_->message) ctx_->message(text, warning);
  }

 private:
  ToolContext* ctx_;
};

}  // namespace linkage::ui
