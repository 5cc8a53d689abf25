#include "window/window_feature.h"

#include <QAction>
#include <QDockWidget>
#include <QKeySequence>
#include <QMainWindow>

namespace linkage::ui {

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
