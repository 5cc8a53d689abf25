// Opening and saving: files, examples, recovered work; the watch on the file; the prompt for
// unsaved changes.
#include <QApplication>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFileSystemWatcher>
#include <QMessageBox>
#include <QTimer>

#include "canvas/canvas_view.h"
#include "document/autosave.h"
#include "document/commands.h"
#include "document/document.h"
#include "document/file_folder.h"
#include "linkage/io/model_file.h"
#include "linkage/io/model_lookup.h"
#include "window/file_feature.h"
#include "window/main_window.h"
#include "window/message_strip.h"

namespace linkage::ui {

bool MainWindow::openFile(const QString& path, QString* error) {
  QString why;
  if (!doc_->open(path, &why)) {
    if (error)
      *error = why;
    else
      QMessageBox::critical(this, tr("Cannot Open"), why);
    return false;
  }
  FileFeature::addRecent(QFileInfo(path).absoluteFilePath());
  watchFile();
  view_->fitToMechanism();
  return true;
}

bool MainWindow::openExample(const QString& name, QString* error) {
  const std::optional<std::string> path =
      resolveModel(name.toStdString(), QApplication::applicationFilePath().toStdString());
  LoadResult r = path ? loadMechanismFile(*path) : LoadResult{};
  if (!r.mechanism) {
    const QString why =
        path ? QString::fromStdString(r.error) : tr("no example named \"%1\"").arg(name);
    if (error)
      *error = why;
    else
      QMessageBox::critical(this, tr("Cannot Open"), why);
    return false;
  }
  doc_->setContents(std::move(*r.mechanism), QString(), name);
  view_->fitToMechanism();
  return true;
}

bool MainWindow::openNameOrPath(const QString& arg, QString* error) {
  if (QFileInfo::exists(arg)) return openFile(arg, error);
  return openExample(arg, error);
}

void MainWindow::openRecovered(const Recovery& r) {
  // The file as it is (or nothing, when there is none), then the recovered design as one edit:
  // unsaved, and undone back to the file.
  LoadResult file = r.path.isEmpty() ? LoadResult{} : loadMechanismFile(r.path.toStdString());
  if (file.mechanism) {
    doc_->setContents(std::move(*file.mechanism), r.path);
  } else {
    Mechanism none;
    none.name = r.design.name;
    none.addBody("ground", true);
    doc_->setContents(std::move(none), QString(), r.title);
  }
  watchFile();
  editDesign(doc_, tr("Recover unsaved work"), r.design);
  view_->fitToMechanism();
  autosave_->saveNow();
}

namespace {
QByteArray contentsOf(const QString& path) {
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}
}  // namespace

void MainWindow::watchFile() {
  if (!watcher_) {
    watcher_ = new QFileSystemWatcher(this);
    // Queued: a program writing the file in steps has finished by the time it is read.
    connect(watcher_, &QFileSystemWatcher::fileChanged, this,
            [this] { QTimer::singleShot(200, this, &MainWindow::fileChangedOnDisk); });
  }
  if (!watched_.isEmpty()) watcher_->removePath(watched_);
  // What is on disk is what the document was read from or written to: no longer different.
  strip_->setNotice(QString());
  watched_ = doc_->filePath();
  onDisk_ = watched_.isEmpty() ? QByteArray() : contentsOf(watched_);
  if (!watched_.isEmpty()) watcher_->addPath(watched_);
}

void MainWindow::fileChangedOnDisk() {
  if (watched_.isEmpty() || watched_ != doc_->filePath() || asking_) return;
  // A file replaced by a rename (as editors and this program save) is watched anew.
  if (!watcher_->files().contains(watched_) && QFileInfo::exists(watched_))
    watcher_->addPath(watched_);
  const QByteArray now = contentsOf(watched_);
  if (now == onDisk_ || !QFileInfo::exists(watched_)) return;
  asking_ = true;
  const auto answer = QMessageBox::question(
      this, tr("File Changed"),
      tr("\"%1\" was changed on disk by another program.%2 Reload it?")
          .arg(QFileInfo(watched_).fileName(),
               doc_->isModified() ? tr(" Reloading it drops the changes made here.") : QString()),
      QMessageBox::Yes | QMessageBox::No, QMessageBox::Yes);
  asking_ = false;
  if (answer == QMessageBox::Yes) {
    QString why;
    if (!openFile(watched_, &why)) QMessageBox::critical(this, tr("Cannot Reload"), why);
  } else {
    onDisk_ = now;  // asked once for this change
    // True until the file is saved over, reloaded or another is opened (watchFile): not a
    // message that the next selection clears.
    strip_->setNotice(tr("%1 differs from the file on disk").arg(doc_->displayName()));
  }
}

bool MainWindow::maybeSave() {
  if (!doc_->isModified()) return true;
  const auto answer = QMessageBox::warning(
      this, tr("Unsaved Changes"),
      tr("\"%1\" has changes that are not saved. Save them?").arg(doc_->displayName()),
      QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
  if (answer == QMessageBox::Save) return save();
  return answer == QMessageBox::Discard;
}

bool MainWindow::save() {
  if (doc_->filePath().isEmpty()) return saveAs();
  QString why;
  if (!doc_->save(doc_->filePath(), &why)) {
    QMessageBox::critical(this, tr("Cannot Save"), why);
    return false;
  }
  watchFile();
  return true;
}

bool MainWindow::saveAs() {
  QString start = doc_->filePath();
  if (start.isEmpty())
    start = QDir(fileFolder())
                .filePath(doc_->displayName().replace(' ', '-') + QStringLiteral(".linkage.json"));
  QFileDialog dialog(this, tr("Save Mechanism As"), start,
                     tr("Mechanisms (*.linkage.json);;All files (*)"));
  dialog.setAcceptMode(QFileDialog::AcceptSave);
  dialog.setDefaultSuffix(QStringLiteral("linkage.json"));
  if (dialog.exec() != QDialog::Accepted || dialog.selectedFiles().isEmpty()) return false;
  const QString path = dialog.selectedFiles().first();
  QString why;
  if (!doc_->save(path, &why)) {
    QMessageBox::critical(this, tr("Cannot Save"), why);
    return false;
  }
  FileFeature::addRecent(QFileInfo(path).absoluteFilePath());
  watchFile();
  return true;
}

QString MainWindow::fileFolder() const {
  return ui::fileFolder(doc_);
}

}  // namespace linkage::ui
