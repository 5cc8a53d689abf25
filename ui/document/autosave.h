// No work lost: a copy of each open document's unsaved work in the application's data folder
// (QStandardPaths::AppDataLocation/autosave), written every 30 s of unsaved work and when the
// window loses focus, atomically (linkage/io/atomic_file.h) and on a thread of its own, so that
// a frame never waits for the disk. The copy goes when the work is saved, discarded or the
// window closes; one left behind by an editor that stopped (a crash, kill -9) is offered for
// recovery at the next start: its name, when it was saved and what it differs in from its file.
// A recovered design opens as an unsaved edit of its file (one undo step back to the file), so
// that the user's file is only written when they save.
#pragma once

#include <QDateTime>
#include <QObject>
#include <QPointer>
#include <QThreadPool>
#include <QTimer>
#include <functional>
#include <memory>
#include <vector>

#include "linkage/model.h"

class QLockFile;
class QWidget;

namespace linkage::ui {

class Document;

class Autosaver : public QObject {
  Q_OBJECT

 public:
  explicit Autosaver(Document* doc, QObject* parent = nullptr);
  // Removes this document's copy (the window closed: its work was saved or let go) once the
  // writes under way are done.
  ~Autosaver() override;

  // Writes the copy now if there are unsaved changes it does not hold yet (the window lost
  // focus; the timer ran out).
  void saveNow();
  // Seconds of unsaved work between copies (30).
  void setInterval(int seconds);
  // Waits for the writes under way (tests).
  void waitForWrites();
  // This document's copy (it exists only while there is unsaved work).
  QString copyPath() const;
  static QString folder();

 private:
  void changed();
  void discard();

  QPointer<Document> doc_;
  QTimer timer_;
  QThreadPool pool_;  // one thread: writes and removals in the order they were asked
  QString id_;
  bool pending_ = false;  // changes the copy does not hold yet
  bool written_ = false;  // a copy is on disk
  std::unique_ptr<QLockFile> lock_;
};

// A copy left by an editor that is no longer running.
struct Recovery {
  QString copy;   // the design's file in the autosave folder
  QString path;   // the file it was opened from, or empty (untitled)
  QString title;  // its name as the window showed it
  QDateTime saved;
  Mechanism design;
  QString difference;  // from the file, in words ("" when the file is gone or was never saved)
};
std::vector<Recovery> findRecoveries();
// Removes a copy (recovered or discarded).
void removeRecovery(const Recovery& r);
// For each copy found: Recover (`open` is called with it, then the copy is removed), Discard, or
// Keep (asked again at the next start).
void offerRecovery(QWidget* parent, const std::function<void(const Recovery&)>& open);

}  // namespace linkage::ui
