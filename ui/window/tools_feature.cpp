#include "window/tools_feature.h"

#include <QAction>

#include "canvas/canvas_scene.h"
#include "elements/element_ui.h"
#include "tools/selection.h"
#include "tools/tool_overlay.h"
#include "tools/toolbox.h"
#include "window/icons.h"
#include "window/main_window.h"
#include "window/message_strip.h"
#include "window/window_layout.h"

namespace linkage::ui {

ToolsFeature::ToolsFeature(MainWindow& w, WindowLayout& layout) : WindowFeature(&w) {
  CanvasScene* scene = w.scene();
  selection_ = new Selection;
  selection_->setParent(this);
  overlay_ = new ToolOverlay(scene->context(), scene, selection_);
  scene->addOverlay(overlay_);
  connect(selection_, &Selection::changed, this, [this] { overlay_->update(); });
  ToolContext ctx;
  ctx.doc = w.document();
  ctx.scene = scene;
  ctx.view = w.canvas();
  ctx.selection = selection_;
  ctx.overlay = overlay_;
  MessageStrip* strip = w.messageStrip();
  ctx.message = [strip](const QString& text, bool warning) { strip->setMessage(text, warning); };
  toolbox_ = new Toolbox(ctx, &w);
  for (QAction* a : toolbox_->toolActions()) {
    layout.add(Slot::ToolsTools, a);
    layout.add(Slot::ToolsBarTools, a);
  }
  layout.add(Slot::ToolsSnap, toolbox_->snapAction());
  layout.add(Slot::EditDelete, toolbox_->deleteAction());
  layout.add(Slot::EditFlip, toolbox_->flipAction());
  layout.add(Slot::ToolsBarDelete, toolbox_->deleteAction());
  layout.add(Slot::ToolsBarFlip, toolbox_->flipAction());
}

void ToolsFeature::applyIcons(const QPalette& p) {
  // A drawing tool's icon is named after it (tool-link.svg); the element kinds' tools bring
  // their own (ui/elements/element_ui.h).
  for (QAction* a : toolbox_->toolActions())
    a->setIcon(themedIcon(QStringLiteral("tool-") + a->data().toString(), p));
  for (const ElementUi* k : elementUis())
    if (k->tool.maker)
      if (QAction* a = toolbox_->toolAction(QString::fromLatin1(k->tool.name)))
        a->setIcon(themedIcon(QString::fromLatin1(k->tool.icon), p));
  toolbox_->deleteAction()->setIcon(themedIcon(QStringLiteral("delete"), p));
  toolbox_->flipAction()->setIcon(themedIcon(QStringLiteral("flip"), p));
}

}  // namespace linkage::ui
