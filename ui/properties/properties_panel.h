// Exact numbers for the selection: names (editable, unique), a point's coordinates (or its
// distance and angle from another point of its link), a bar's length and angle (editing them
// moves its second point), a triangle plate's three sides, a slot's ends, a joint's type, the
// driver's rpm, direction and start angle, whether a point is an output; the mechanism's own
// name and driver when nothing is selected. Millimetres and degrees, in the drawing's
// coordinates (the sketch, at crank angle -start), typed values taken exactly (never snapped)
// and shown as typed; values of arithmetic are shown rounded for people (shownText), the model
// and the file keeping every digit. Every change is one undo step.
//
// The panel is a form builder (forms/form.h): which rows a selection has is said by the form
// descriptors (forms.h, one file each) and the sections other folders add (addSection).
#pragma once

#include <QPointer>
#include <QWidget>
#include <functional>
#include <vector>

#include "forms/form.h"

class QFormLayout;
class QLabel;

namespace linkage::ui {

class Document;
class Selection;

class PropertiesPanel : public QWidget, public Form {
  Q_OBJECT

 public:
  explicit PropertiesPanel(QWidget* parent = nullptr);
  void setDocument(Document* doc, Selection* selection);
  // Rows another folder adds after a form's own (the forces' mass and loads), in the order
  // added; the rows are made anew.
  void addSection(const FormSection& section);
  // The field with this label (for tests and scripts), or nullptr.
  QWidget* field(const QString& label) const;
  // The label of a field (the inverse of field()), or empty.
  QString labelOf(const QWidget* editor) const;
  QString title() const;
  // The message line now shows `text`: a field refused with another message is no longer red.
  void messageShown(const QString& text);
  // The field last marked red for a refused value, while it is.
  QWidget* refusedField() const { return refused_; }

  // The rows the forms are made of (forms/form.h).
  Document* document() const override { return doc_; }
  void setTitle(const QString& html) override;
  void addText(const QString& label, std::function<QString()> value,
               std::function<bool(const QString&, QString*)> commit) override;
  void addNumber(const QString& label, std::function<double()> value,
                 std::function<bool(double, QString*)> commit, const QString& unit) override;
  void addInfo(const QString& label, std::function<QString()> value) override;
  void addChoice(const QString& label, const QStringList& items, std::function<int()> current,
                 std::function<void(int)> chosen) override;
  std::function<int()> addSelector(const QString& label, const QStringList& items) override;
  void addCheck(const QString& label, const QString& text, std::function<bool()> checked,
                std::function<bool()> enabled, std::function<void(bool)> clicked) override;
  void addButton(const QString& label, const QString& text, std::function<void()> clicked) override;
  void setTip(const QString& label, const QString& tip) override;
  bool change(const QString& text, const std::function<bool(Mechanism&, QString*)>& edit,
              QString* why) override;
  void warn(const QString& text) override { emit message(text, true); }
  QWidget* widget() override { return this; }

 Q_SIGNALS:
  void message(const QString& text, bool warning);
  // The rows were made anew (another kind of selection): their height may have changed.
  void rebuilt();

 private:
  struct Row {
    QString label;
    QWidget* editor;
    std::function<void()> refresh;
  };
  void rebuild();
  void refresh();
  void clearRows();
  // The one thing selected (none: the mechanism).
  FormTarget target() const;

  QPointer<Document> doc_;
  Selection* selection_ = nullptr;
  QLabel* title_;
  QFormLayout* form_;
  std::vector<Row> rows_;
  std::vector<FormSection> sections_;
  QString shape_;  // what the rows are for: rebuilt when it changes, refreshed otherwise
  QPointer<QWidget> refused_;
  QString refusal_;  // the message that says why
};

}  // namespace linkage::ui
