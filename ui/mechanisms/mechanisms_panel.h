// The Mechanisms dock (issue 18): each mechanism of the machine (linkage/mechanisms.h, the parts
// that move together once the main shaft's angle is given) with its name, a check box that
// shows or hides it and a colour swatch. Renaming (edit the name in place), colouring
// (QColorDialog) and hiding are undoable edits of the design, kept in its file ("mechanisms");
// selecting a row selects its bodies on the canvas.
#pragma once

#include <QColor>
#include <QPointer>
#include <QStringList>
#include <QWidget>
#include <vector>

#include "linkage/mechanisms.h"

class QAction;
class QTreeWidget;
class QTreeWidgetItem;

namespace linkage::ui {

class Document;
class Selection;

class MechanismsPanel : public QWidget {
  Q_OBJECT

 public:
  explicit MechanismsPanel(QWidget* parent = nullptr);
  void setDocument(Document* doc, Selection* selection);
  QTreeWidget* list() const { return list_; }

  // One undo step each, by row (the order of linkage/mechanisms.h); false for a row that is not
  // there or an edit that changes nothing.
  bool rename(int row, const QString& name);
  // An invalid colour: the bodies' own colours again.
  bool setColour(int row, const QColor& colour);
  bool setHidden(int row, bool hidden);
  // For LINKAGE_PROBE (ui/window/probe.h): a line per row, "mechanism NAME: shown|hidden X Y
  // check CX CY", X Y the screen centre of its name and CX CY of its check box.
  QStringList probeLines() const;
  // Asks for the current row's colour (QColorDialog) and sets it.
  void chooseColour();

 private:
  void refill();
  std::vector<SubMechanism> current() const;
  void itemChanged(QTreeWidgetItem* item, int column);
  void selectBodies();
  bool edit(int row, const QString& text, const QString& name, const QString& colour, bool hidden);

  QPointer<Document> doc_;
  QPointer<Selection> selection_;
  QTreeWidget* list_;
  QAction *colour_, *noColour_;
  bool filling_ = false;
};

}  // namespace linkage::ui
