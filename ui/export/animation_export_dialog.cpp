#include "export/animation_export_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressDialog>
#include <QPushButton>
#include <QRadioButton>
#include <QSpinBox>

namespace linkage::ui {

AnimationExportDialog::AnimationExportDialog(double rpm, QWidget* parent)
    : QDialog(parent), rpm_(rpm > 0 ? rpm : 60) {
  setWindowTitle("Export animation");
  auto* form = new QFormLayout(this);
  format_ = new QComboBox;
  format_->addItems({"Animated GIF", "PNG sequence"});
  form->addRow("Format", format_);

  auto* sizeRow = new QHBoxLayout;
  width_ = new QSpinBox;
  height_ = new QSpinBox;
  for (QSpinBox* s : {width_, height_}) {
    s->setRange(16, 8192);
    s->setSuffix(" px");
  }
  width_->setValue(640);
  height_->setValue(480);
  sizeRow->addWidget(width_);
  sizeRow->addWidget(new QLabel(QString::fromUtf8("×")));
  sizeRow->addWidget(height_);
  form->addRow("Size", sizeRow);

  frames_ = new QSpinBox;
  frames_->setRange(1, 100000);
  frames_->setValue(72);
  form->addRow("Frames", frames_);
  revs_ = new QDoubleSpinBox;
  revs_->setRange(0.01, 1000);
  revs_->setValue(1);
  revs_->setSuffix(" rev");
  form->addRow("Crank turns", revs_);

  byFps_ = new QRadioButton("Frames per second");
  bySpeed_ = new QRadioButton("Speed factor");
  fps_ = new QDoubleSpinBox;
  fps_->setRange(1, 50);
  fps_->setValue(25);
  speed_ = new QDoubleSpinBox;
  speed_->setRange(0.001, 1000);
  speed_->setDecimals(3);
  speed_->setValue(1);
  speed_->setSuffix(QString::fromUtf8(" × real speed"));
  byFps_->setChecked(true);
  form->addRow(byFps_, fps_);
  form->addRow(bySpeed_, speed_);
  speedText_ = new QLabel;
  speedText_->setWordWrap(true);
  form->addRow(speedText_);

  auto* fileRow = new QHBoxLayout;
  path_ = new QLineEdit;
  auto* browse = new QPushButton(QString::fromUtf8("Browse…"));
  fileRow->addWidget(path_, 1);
  fileRow->addWidget(browse);
  form->addRow("File", fileRow);

  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
  form->addRow(buttons);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(browse, &QPushButton::clicked, this, &AnimationExportDialog::browse);
  auto update = [this] { updateSpeedText(); };
  for (QSpinBox* s : {frames_, width_, height_}) connect(s, &QSpinBox::valueChanged, this, update);
  for (QDoubleSpinBox* s : {revs_, fps_, speed_})
    connect(s, &QDoubleSpinBox::valueChanged, this, update);
  connect(byFps_, &QRadioButton::toggled, this, update);
  connect(path_, &QLineEdit::textChanged, this, update);
  updateSpeedText();
}

AnimationSpec AnimationExportDialog::spec() const {
  AnimationSpec s;
  s.format = format_->currentIndex() == 0 ? AnimationSpec::Format::Gif
                                          : AnimationSpec::Format::PngSequence;
  s.path = path_->text();
  s.size = QSize(width_->value(), height_->value());
  s.frames = frames_->value();
  s.revs = revs_->value();
  s.fps = byFps_->isChecked() ? fps_->value()
                              : framesPerSecondFor(s.frames, s.revs, rpm_, speed_->value());
  return s;
}

void AnimationExportDialog::setSpec(const AnimationSpec& s) {
  format_->setCurrentIndex(s.format == AnimationSpec::Format::Gif ? 0 : 1);
  path_->setText(s.path);
  width_->setValue(s.size.width());
  height_->setValue(s.size.height());
  frames_->setValue(s.frames);
  revs_->setValue(s.revs);
  fps_->setValue(s.fps);
  byFps_->setChecked(true);
}

void AnimationExportDialog::updateSpeedText() {
  fps_->setEnabled(byFps_->isChecked());
  speed_->setEnabled(bySpeed_->isChecked());
  const AnimationSpec s = spec();
  const double real = framesPerSecondFor(s.frames, s.revs, rpm_, 1.0);
  const double seconds = s.frames / s.fps;
  QString text = QString::fromUtf8("%1 fps: %2 s, %3× the mechanism's %4 rpm.")
                     .arg(s.fps, 0, 'g', 4)
                     .arg(seconds, 0, 'g', 4)
                     .arg(s.fps / real, 0, 'g', 4)
                     .arg(rpm_, 0, 'g', 6);
  if (s.format == AnimationSpec::Format::Gif)
    text += QString(" A GIF stores whole hundredths of a second per frame: %1/100 s.")
                .arg(gifDelay(s.fps));
  else if (!s.path.isEmpty())
    text += QString(" Files %1 ...").arg(pngSequenceNames(s.path, s.frames).value(0));
  if (s.fps > 50) text += " More than 50 fps: GIF players slow it down.";
  speedText_->setText(text);
}

void AnimationExportDialog::browse() {
  const bool gif = format_->currentIndex() == 0;
  const QString f = QFileDialog::getSaveFileName(this, "Export animation", path_->text(),
                                                 gif ? "GIF (*.gif)" : "PNG (*.png)");
  if (!f.isEmpty()) path_->setText(f);
}

bool AnimationExportDialog::run(QWidget* parent, double rpm, const FrameRenderer& render,
                                QString* error) {
  if (error) error->clear();
  AnimationExportDialog dialog(rpm, parent);
  if (dialog.exec() != QDialog::Accepted) return false;
  const AnimationSpec s = dialog.spec();
  QProgressDialog progress("Rendering frames...", "Cancel", 0, s.frames, parent);
  progress.setWindowModality(Qt::WindowModal);
  progress.setMinimumDuration(300);
  return exportAnimation(s, render, error, [&progress](int done, int total) {
    progress.setMaximum(total);
    progress.setValue(done);
    return !progress.wasCanceled();
  });
}

}  // namespace linkage::ui
