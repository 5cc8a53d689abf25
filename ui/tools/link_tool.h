// Link (L): each click adds a point to a new link; a click on a point of another body pins the
// link there. Enter, a double click or a right click ends it (two points make a bar, three or
// more a plate); Esc drops it.
#pragma once

#include <vector>

#include "linkage/edits.h"
#include "tools/tool.h"

namespace linkage::ui {

class LinkTool : public Tool {
  Q_OBJECT

 public:
  using Tool::Tool;
  QString hint() const override;
  void deactivate() override;
  void press(const CanvasMouse& e) override;
  void move(const CanvasMouse& e) override;
  void doubleClick(const CanvasMouse& e) override;
  bool key(QKeyEvent* e) override;
  bool rightClick(const CanvasMouse& e) override;
  bool drawing() const { return !vertices_.empty(); }
  // Starts a link at a point (the context menu's "attach a link here").
  void startAt(const LinkVertex& v);
  void start(const ToolStart& s) override { startAt(LinkVertex{s.at, s.point}); }

 private:
  void finish();
  void cancel();
  void showPath(std::optional<Vec2> cursor);

  std::vector<LinkVertex> vertices_;
};

}  // namespace linkage::ui
