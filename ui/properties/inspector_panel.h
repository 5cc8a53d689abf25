// The inspector: what the mechanism is (name, file, structure, degrees of freedom, how it is
// solved, the solver's notes and any failure, with its place) and where its output points are
// now: position, velocity and acceleration, exact, following the animation while visible; for a
// point the driver does not determine, or a design not solved, no numbers but the reason. A
// machine in space (linkage/space.h): x, y, z in the world and their rates (the headers say
// so), as `linkage-cli analyze` gives them.
#pragma once

#include <QPointer>
#include <QWidget>

class QLabel;
class QTableWidget;

namespace linkage::ui {

class Document;

class InspectorPanel : public QWidget {
  Q_OBJECT

 public:
  explicit InspectorPanel(QWidget* parent = nullptr);
  void setDocument(Document* doc);
  // Moves the readout to the current pose (when visible).
  void refreshMotion();
  QTableWidget* motionTable() const { return motion_; }
  QString summaryText() const;
  // Why some outputs show no numbers (not solved, not determined by the driver), or empty.
  QString noteText() const;

 protected:
  void showEvent(QShowEvent* e) override;

 private:
  void refreshSummary();
  // The headers for a planar machine, or for one in space.
  void setHeaders(bool inSpace);

  QPointer<Document> doc_;
  QLabel* summary_;
  QTableWidget* motion_;
  QLabel* note_;
  int inSpace_ = -1;  // the headers shown: -1 none yet
};

}  // namespace linkage::ui
