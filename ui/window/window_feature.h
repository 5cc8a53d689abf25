// What a feature of the main window is (the instant centres, the plots, the forces, ...): an
// object the window makes once, which makes the feature's actions (each with its shortcut and
// status tip), puts them in the menus and toolbars (WindowLayout), adds its docks, and keeps
// typed handles to them for the rest of the program and the tests. The window calls it back
// for what every feature may have: icons in the palette's colours and its remembered settings.
#pragma once

#include <QObject>
#include <QString>

class QAction;
class QDockWidget;
class QKeySequence;
class QMainWindow;
class QPalette;
class QSettings;
class QWidget;

namespace linkage::ui {

class WindowFeature : public QObject {
 public:
  explicit WindowFeature(QObject* parent) : QObject(parent) {}
  // The toolbar and menu icons, again when the palette changes (the dark palette).
  virtual void applyIcons(const QPalette&) {}
  // The feature's settings, in the group "view" of the window's QSettings.
  virtual void readSettings(const QSettings&) {}
  virtual void writeSettings(QSettings&) const {}
};

// An action of the window `w` (so that its shortcut works anywhere in it), with the object name
// `name` (for QSettings and tests), its shortcut in its tool tip.
QAction* makeAction(QWidget* w, const QString& name, const QString& text, const QKeySequence& key,
                    const QString& tip);
// A checkable one.
QAction* makeToggle(QWidget* w, const QString& name, const QString& text, const QKeySequence& key,
                    const QString& tip);

// A dock of the window `w` in `area`, named `name` (saveState keeps its place by it).
QDockWidget* addDock(QMainWindow* w, const QString& name, const QString& title, QWidget* contents,
                     Qt::DockWidgetArea area);
// A hidden dock's View-menu action, with its shortcut and status tip: asked for, the dock comes
// to the front of its tabs (once the layout has taken it back).
QAction* raisingToggle(QDockWidget* dock, const QString& name, const QKeySequence& key,
                       const QString& tip);

}  // namespace linkage::ui
