// Exact numbers for the selection: names (editable, unique), a point's coordinates (or its
// distance and angle from another point of its link), a bar's length and angle (editing them
// moves its second point), a triangle plate's three sides, a slot's ends, a joint's type, the
// driver's rpm, direction and start angle, whether a point is an output; the mechanism's own
// name and driver when nothing is selected. Millimetres and degrees, in the drawing's
// coordinates (the sketch, at crank angle -start), typed values taken exactly (never snapped)
// and shown as typed; values of arithmetic are shown rounded for people (shownText), the model
// and the file keeping every digit. Every change is one undo step.
#pragma once

#include <QPointer>
#include <QWidget>
#include <functional>
#include <optional>
#include <vector>

#include "linkage/model.h"

class QComboBox;
class QFormLayout;
class QLabel;
class QLineEdit;

namespace linkage::ui {

class Document;
class Selection;

class PropertiesPanel : public QWidget {
  Q_OBJECT

 public:
  explicit PropertiesPanel(QWidget* parent = nullptr);
  void setDocument(Document* doc, Selection* selection);
  // The field with this label (for tests and scripts), or nullptr.
  QWidget* field(const QString& label) const;
  // The label of a field (the inverse of field()), or empty.
  QString labelOf(const QWidget* editor) const;
  QString title() const;

  // What the element kinds' forms (ui/elements/) build their rows with.
  Document* document() const { return doc_; }
  // Editors that commit on Enter or leaving the field; a refused value turns the field red and
  // puts the old one back.
  void addText(const QString& label, std::function<QString()> value,
               std::function<bool(const QString&, QString*)> commit);
  void addNumber(const QString& label, std::function<double()> value,
                 std::function<bool(double, QString*)> commit, const QString& unit);
  void addInfo(const QString& label, std::function<QString()> value);
  // A choice (its items already in `box`), set from current() and acting on activation.
  void addChoice(const QString& label, QComboBox* box, std::function<int()> current,
                 std::function<void(int)> activated);
  void addCheck(const QString& label, const QString& text, std::function<bool()> checked,
                std::function<bool()> enabled, std::function<void(bool)> clicked);
  // Applies a change to a copy of the design as one undo step.
  bool change(const QString& text, const std::function<bool(Mechanism&, QString*)>& edit,
              QString* why);
  // The driver's speed, direction and start angle.
  void fillDriver();
  // The message line now shows `text`: a field refused with another message is no longer red.
  void messageShown(const QString& text);
  // The field last marked red for a refused value, while it is.
  QWidget* refusedField() const { return refused_; }
  // A button that acts at once (a dialog, typically).
  void addButton(const QString& label, const QString& text, std::function<void()> clicked);

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
  void fillMechanism();
  void fillBody(BodyId id);
  void fillPoint(PointId id);
  // A triangle's three sides; a point's distance and angle from another of its link.
  void fillTriangle(BodyId id);
  void fillPolar(PointId id);
  // A body's mass, centre of mass, moment of inertia, counterweights (dynamics_forms.cpp); the
  // loads on a body (torques) or at a point (forces).
  void fillMass(BodyId id);
  void fillLoads(BodyId body, PointId point);
  void fillLoad(LoadId id, int number);
  void estimateMass(BodyId id);
  void fillJoint(JointId id);
  void fillSlot(SlotId id);
  void fillSlotShape(SlotId id);
  void fillSlotEnds(SlotId id);
  void fillArc(SlotId id);
  bool setSlot(SlotId id, const Vec2& p0, const std::optional<Vec2>& mid, const Vec2& p1,
               QString* why);

  QPointer<Document> doc_;
  Selection* selection_ = nullptr;
  QLabel* title_;
  QFormLayout* form_;
  std::vector<Row> rows_;
  QString shape_;  // what the rows are for: rebuilt when it changes, refreshed otherwise
  QPointer<QWidget> refused_;
  QString refusal_;  // the message that says why
};

// What of the loads and counterweights a form's rows depend on (rows are made anew when it
// changes): the loads on `body` (torques) or at `point`, and the body's counterweights.
QString loadsShape(const Mechanism& m, BodyId body, PointId point);

}  // namespace linkage::ui
