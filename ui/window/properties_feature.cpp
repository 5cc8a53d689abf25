#include "window/properties_feature.h"

#include <QAction>
#include <QDockWidget>
#include <QLayout>
#include <QScrollArea>
#include <QSplitter>

#include "document/document.h"
#include "properties/inspector_panel.h"
#include "properties/properties_panel.h"
#include "window/main_window.h"
#include "window/message_strip.h"
#include "window/tools_feature.h"
#include "window/window_layout.h"

namespace linkage::ui {

PropertiesFeature::PropertiesFeature(MainWindow& w, WindowLayout& layout)
    : WindowFeature(&w), doc_(w.document()) {
  panel_ = new PropertiesPanel;
  inspector_ = new InspectorPanel;
  dock = addDock(&w, "properties", tr("Properties"), makeSplit(), Qt::RightDockWidgetArea);
  layout.add(Slot::ViewPropertiesDock, dock->toggleViewAction());
  inspector_->setDocument(doc_);
  panel_->setDocument(doc_, w.tools().selection());
  MessageStrip* strip = w.messageStrip();
  connect(panel_, &PropertiesPanel::message, strip, &MessageStrip::setMessage);
  connect(strip, &MessageStrip::messageChanged, panel_, &PropertiesPanel::messageShown);
  connect(doc_, &Document::designChanged, this, &PropertiesFeature::updateWork);
  connect(doc_, &Document::poseChanged, inspector_, &InspectorPanel::refreshMotion);
  // Work only while seen: a dock's visibility says so (a tab behind another is moved off the
  // window but its widget stays "visible"). Queued: a dock reports its visibility before its
  // contents have changed theirs.
  connect(dock, &QDockWidget::visibilityChanged, this, [this](bool seen) { seen_ = seen; });
  connect(dock, &QDockWidget::visibilityChanged, this, &PropertiesFeature::updateWork,
          Qt::QueuedConnection);
}

QWidget* PropertiesFeature::makeSplit() {
  auto* split = new QSplitter(Qt::Vertical);
  auto* scroll = new QScrollArea;
  scroll->setWidget(panel_);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  split->addWidget(scroll);
  split->addWidget(inspector_);
  split->setStretchFactor(0, 3);
  split->setStretchFactor(1, 2);
  split->setCollapsible(0, false);
  scroll->setMinimumHeight(140);
  // The form whole when its rows change (up to 60 % of the dock; then it scrolls): it started
  // cut off behind the splitter, its last rows out of sight.
  // Queued: the new rows' layout gives its size once the event loop has run it.
  connect(
      panel_, &PropertiesPanel::rebuilt, this,
      [split, scroll, this] {
        panel_->layout()->activate();
        const int want = panel_->sizeHint().height() + 2 * scroll->frameWidth();
        const int total = split->height();
        if (total <= 0 || scroll->height() >= want) return;
        const int form = std::min(want, total * 6 / 10);
        split->setSizes({form, total - form});
      },
      Qt::QueuedConnection);
  return split;
}

void PropertiesFeature::updateWork() {
  // A new solver (a file, an edit) starts with the default: ask again what is shown.
  doc_->setAccelerationsWanted(seen_);
  inspector_->refreshMotion();
}

}  // namespace linkage::ui
