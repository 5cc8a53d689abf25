#include "window/properties_feature.h"

#include <QAction>
#include <QDockWidget>
#include <QEvent>
#include <QLayout>
#include <QLineEdit>
#include <QScrollArea>
#include <QSplitter>

#include "document/document.h"
#include "properties/inspector_panel.h"
#include "properties/properties_panel.h"
#include "tools/toolbox.h"
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
  // A menu's "Edit ..." (a gear's ratio): the field shown, the keyboard in it, its value
  // selected to be typed over.
  // Queued: the rows just made for the selection are shown by their layout first (a hidden
  // field takes no focus).
  connect(
      w.tools().toolbox(), &Toolbox::fieldWanted, this,
      [this](const QString& label) {
        dock->show();
        dock->raise();
        QWidget* f = panel_->field(label);
        if (!f) return;
        scroll_->ensureWidgetVisible(f);
        f->setFocus(Qt::OtherFocusReason);
        if (auto* e = qobject_cast<QLineEdit*>(f)) e->selectAll();
      },
      Qt::QueuedConnection);
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
  split_ = new QSplitter(Qt::Vertical);
  scroll_ = new QScrollArea;
  scroll_->setWidget(panel_);
  scroll_->setWidgetResizable(true);
  scroll_->setFrameShape(QFrame::NoFrame);
  split_->addWidget(scroll_);
  split_->addWidget(inspector_);
  split_->setStretchFactor(0, 3);
  split_->setStretchFactor(1, 2);
  split_->setCollapsible(0, false);
  scroll_->setMinimumHeight(140);
  // Queued: the new rows' layout gives its size once the event loop has run it.
  connect(panel_, &PropertiesPanel::rebuilt, this, &PropertiesFeature::fitForm,
          Qt::QueuedConnection);
  // The rows of a file opened before the window was shown wait for the dock's first height.
  split_->installEventFilter(this);
  return split_;
}

void PropertiesFeature::fitForm() {
  // The form whole when its rows change (up to 60 % of the dock; then it scrolls): it started
  // cut off behind the splitter, its last rows out of sight.
  panel_->layout()->activate();
  const int want = panel_->sizeHint().height() + 2 * scroll_->frameWidth();
  // setSizes() shares the splitter's height less its handle: sizes adding up to more are
  // scaled down, and a form short by a pixel scrolls.
  const int total = split_->height() - split_->handleWidth();
  formPending_ = total <= 0 || !split_->isVisible();
  if (formPending_ || scroll_->height() >= want) return;
  const int form = std::min(want, total * 6 / 10);
  split_->setSizes({form, total - form});
}

bool PropertiesFeature::eventFilter(QObject* o, QEvent* e) {
  if (o == split_ && formPending_ && (e->type() == QEvent::Resize || e->type() == QEvent::Show))
    QMetaObject::invokeMethod(this, &PropertiesFeature::fitForm, Qt::QueuedConnection);
  return WindowFeature::eventFilter(o, e);
}

void PropertiesFeature::updateWork() {
  // A new solver (a file, an edit) starts with the default: ask again what is shown.
  doc_->setAccelerationsWanted(seen_);
  inspector_->refreshMotion();
}

}  // namespace linkage::ui
