#include "window/window_feature.h"

#include <QAction>
#include <QChildEvent>
#include <QComboBox>
#include <QDockWidget>
#include <QKeySequence>
#include <QLabel>
#include <QMainWindow>

namespace linkage::ui {

namespace {

// A dock's texts are as long as a user makes them (a mechanism's name, a body's, a file's path,
// a reason naming them): none may set the window's minimum width, or a 250-character name
// widens the window past the screen for good. Its labels and choices may be narrower than their
// text: a label wraps where it can and is cut at the dock's edge where it cannot (the dock can
// be dragged wider to read it); a choice shows what fits. Where there is room they keep their
// natural width. Widgets added later (rows made anew for a selection) are fitted when polished.
class NarrowTexts : public QObject {
 public:
  using QObject::QObject;
  void adopt(QWidget* w) {
    w->installEventFilter(this);
    fit(w);
    for (QWidget* c : w->findChildren<QWidget*>()) {
      c->installEventFilter(this);
      fit(c);
    }
  }
  bool eventFilter(QObject* watched, QEvent* e) override {
    if (e->type() == QEvent::ChildPolished)
      if (auto* c = qobject_cast<QWidget*>(static_cast<QChildEvent*>(e)->child())) adopt(c);
    return QObject::eventFilter(watched, e);
  }

 private:
  static void fit(QWidget* w) {
    // A minimum set on purpose stays.
    if (w->minimumWidth() > 0) return;
    if (auto* l = qobject_cast<QLabel*>(w)) {
      l->setMinimumWidth(1);
    } else if (auto* c = qobject_cast<QComboBox*>(w)) {
      c->setMinimumWidth(c->fontMetrics().averageCharWidth() * 8 + 24);
    }
  }
};

}  // namespace

QAction* makeAction(QWidget* w, const QString& name, const QString& text, const QKeySequence& key,
                    const QString& tip) {
  auto* a = new QAction(text, w);
  a->setObjectName(name);
  if (!key.isEmpty()) a->setShortcut(key);
  a->setStatusTip(tip);
  a->setToolTip(key.isEmpty() ? text
                              : QStringLiteral("%1 (%2)").arg(text).arg(
                                    key.toString(QKeySequence::NativeText)));
  a->setToolTip(a->toolTip().remove('&'));
  w->addAction(a);
  return a;
}

QAction* makeToggle(QWidget* w, const QString& name, const QString& text, const QKeySequence& key,
                    const QString& tip) {
  QAction* a = makeAction(w, name, text, key, tip);
  a->setCheckable(true);
  return a;
}

QDockWidget* addDock(QMainWindow* w, const QString& name, const QString& title, QWidget* contents,
                     Qt::DockWidgetArea area) {
  auto* d = new QDockWidget(title, w);
  d->setObjectName(name);
  d->setWidget(contents);
  (new NarrowTexts(d))->adopt(contents);
  // A side panel keeps the width its rows were laid out for (their texts gave it: 314 px at
  // the default font), now that no text sets it.
  if (area & (Qt::LeftDockWidgetArea | Qt::RightDockWidgetArea) && contents->minimumWidth() == 0)
    contents->setMinimumWidth(contents->fontMetrics().averageCharWidth() * 45);
  w->addDockWidget(area, d);
  return d;
}

QAction* raisingToggle(QDockWidget* dock, const QString& name, const QKeySequence& key,
                       const QString& tip) {
  QAction* show = dock->toggleViewAction();
  show->setObjectName(name);
  if (!key.isEmpty()) show->setShortcut(key);
  show->setStatusTip(tip);
  QObject::connect(
      show, &QAction::triggered, dock,
      [dock](bool on) {
        if (on) dock->raise();
      },
      Qt::QueuedConnection);
  return show;
}

}  // namespace linkage::ui
