// Analysis > Parameter Study: vary one dimension of the document's design and measure every
// variant, as `linkage-cli study` does (linkage/study.h): a point moved along a line by t (DX,
// DY) or turned about a centre by t DEG, t from A to B in N values; the stroke, peaks and
// swings of a measured point and bodies, each transmission angle's extremes, and whether the
// crank still turns fully. It runs in worker threads (the window stays responsive) with
// progress and Cancel; shows the table (the CLI's columns), any measure against t, and the
// family of the point's paths coloured by t; exports the table as CSV (the CLI's text).
// Not modal: one per window, kept with its last results while the window is open.
#pragma once

#include <QDialog>
#include <QPointer>

#include "linkage/study.h"

class QComboBox;
class QFormLayout;
class QHBoxLayout;
class QLabel;
class QLineEdit;
class QListWidget;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTableView;

namespace linkage::ui {

class Document;
class StudyPlots;
class StudyRunner;
class StudyTableModel;

class StudyDialog : public QDialog {
  Q_OBJECT

 public:
  explicit StudyDialog(Document* doc, QWidget* parent = nullptr);
  ~StudyDialog() override;

  // The spec the form describes for the document's design; false with the reason (naming
  // the field) when it cannot run.
  bool readSpec(StudySpec& spec, QString* why) const;
  // Starts a run of the form's spec (the Run button); false with the reason shown otherwise.
  bool run();
  void cancel();
  // Writes the table as `linkage-cli study` does; false with the reason.
  bool exportCsv(const QString& path, QString* error) const;

  // The form, the results and the run, for tests and tools.
  QComboBox* moveBox() const { return move_; }
  QComboBox* kindBox() const { return kind_; }
  QLineEdit* byEdit() const { return by_; }
  QLineEdit* aboutEdit() const { return about_; }
  QLineEdit* angleEdit() const { return angle_; }
  QLineEdit* fromEdit() const { return from_; }
  QLineEdit* toEdit() const { return to_; }
  QSpinBox* valuesBox() const { return values_; }
  QComboBox* pointBox() const { return point_; }
  QLineEdit* directionEdit() const { return direction_; }
  QListWidget* bodiesList() const { return bodies_; }
  QSpinBox* stepsBox() const { return steps_; }
  QPushButton* runButton() const { return runButton_; }
  QPushButton* cancelButton() const { return cancelButton_; }
  QProgressBar* progressBar() const { return progress_; }
  QString statusText() const;
  QTableView* table() const { return table_; }
  StudyTableModel* model() const { return model_; }
  StudyPlots* plots() const { return plots_; }
  StudyRunner* runner() const { return runner_; }

 Q_SIGNALS:
  // A run ended (finished, cancelled or failed) and the results show it.
  void runEnded();

 protected:
  void closeEvent(QCloseEvent* e) override;

 private:
  // The dialog's parts: the fields, their form, the run's buttons, the side with those, the
  // progress and the status, and the side with the table and the plots.
  void buildForm();
  void createFields();
  QFormLayout* fieldsForm();
  QHBoxLayout* runButtons();
  QWidget* formSide(QFormLayout* form, QHBoxLayout* buttons);
  QWidget* resultsSide();
  void offerPoints();
  void kindChanged();
  void finished();
  void setRunning(bool on);
  void showStatus(const QString& text, bool warning);

  QPointer<Document> doc_;
  StudyRunner* runner_;
  StudyTableModel* model_;
  QComboBox *move_, *kind_, *point_;
  QLineEdit *by_, *about_, *angle_, *from_, *to_, *direction_;
  QSpinBox *values_, *steps_;
  QListWidget* bodies_;
  QPushButton *runButton_, *cancelButton_, *exportButton_;
  QProgressBar* progress_;
  QLabel* status_;
  QTableView* table_;
  StudyPlots* plots_;
};

}  // namespace linkage::ui
