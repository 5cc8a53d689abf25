// A form of the Properties panel: rows, each a label and an editor that reads the document
// again after every edit (its getter) and commits what is typed as one undo step (its
// committer). The panel (ui/properties/properties_panel.h) builds the rows; what rows a thing
// has is said by its form's descriptor (ui/properties/), its element kind (ui/elements/) and the
// sections other folders add (the forces' mass and loads, ui/forces/), which include this and
// nothing of the panel.
#pragma once

#include <QCoreApplication>
#include <QString>
#include <QStringList>
#include <functional>

#include "linkage/model.h"

class QWidget;

namespace linkage::ui {

class Document;

class Form {
  Q_DECLARE_TR_FUNCTIONS(Form)

 public:
  virtual Document* document() const = 0;
  // The heading, rich text ("<b>Link</b> crank").
  virtual void setTitle(const QString& html) = 0;
  // Editors that commit on Enter or leaving the field; a refused value turns the field red and
  // puts the old one back, the reason on the message line. A number's label gets its unit
  // ("Length [mm]"); it is shown rounded for people and taken exactly as typed.
  virtual void addText(const QString& label, std::function<QString()> value,
                       std::function<bool(const QString&, QString*)> commit) = 0;
  virtual void addNumber(const QString& label, std::function<double()> value,
                         std::function<bool(double, QString*)> commit, const QString& unit) = 0;
  virtual void addInfo(const QString& label, std::function<QString()> value) = 0;
  // A choice among `items`, set from current() and acting when the user chooses.
  virtual void addChoice(const QString& label, const QStringList& items,
                         std::function<int()> current, std::function<void(int)> chosen) = 0;
  // A choice that edits nothing: which of `items` the rows after it read (the point a distance
  // is measured from). Returns what it holds when asked; the rows are read again as it changes.
  virtual std::function<int()> addSelector(const QString& label, const QStringList& items) = 0;
  virtual void addCheck(const QString& label, const QString& text, std::function<bool()> checked,
                        std::function<bool()> enabled, std::function<void(bool)> clicked) = 0;
  // A button that acts at once (a dialog, typically).
  virtual void addButton(const QString& label, const QString& text,
                         std::function<void()> clicked) = 0;
  // The tooltip of the row `label` (its full label, with the unit).
  virtual void setTip(const QString& label, const QString& tip) = 0;
  // Applies `edit` to a copy of the design as one undo step; false, with `why`, when refused.
  virtual bool change(const QString& text, const std::function<bool(Mechanism&, QString*)>& edit,
                      QString* why) = 0;
  // A warning on the message line (an edit refused where no field is to be marked).
  virtual void warn(const QString& text) = 0;
  // The widget the rows are in: the parent of a dialog a row opens.
  virtual QWidget* widget() = 0;

 protected:
  ~Form() = default;
};

// What a form is for: the one body, point, joint or slot selected; none of them: the mechanism.
struct FormTarget {
  BodyId body;
  PointId point;
  JointId joint;
  SlotId slot;
};

// Rows another folder adds after a form's own (the forces' mass rows on a link's form): added
// to the panel by the feature that plugs that folder into the window
// (ui/window/forces_feature.cpp), so that the panel includes nothing of it.
struct FormSection {
  const char* form;  // the form it joins, by name ("body", "point": ui/properties/forms.h)
  // What its rows are made from: with the form's own, the rows are made anew when it changes.
  QString (*shape)(const Mechanism& m, const FormTarget& t);
  void (*fill)(Form& form, const FormTarget& t);
};

}  // namespace linkage::ui
