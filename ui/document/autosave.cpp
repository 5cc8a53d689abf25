#include "document/autosave.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLockFile>
#include <QMessageBox>
#include <QPushButton>
#include <QStandardPaths>
#include <QUndoStack>
#include <atomic>

#include "document/document.h"
#include "linkage/io/atomic_file.h"
#include "linkage/io/model_file.h"

namespace linkage::ui {

namespace {

constexpr int kIntervalSeconds = 30;

QString uniqueId() {
  static std::atomic<int> counter{0};
  return QStringLiteral("%1-%2-%3")
      .arg(QCoreApplication::applicationPid())
      .arg(QDateTime::currentMSecsSinceEpoch())
      .arg(counter++);
}

// The three files of a copy: the design, what it was (meta) and the lock its editor holds.
QString designFile(const QString& id) {
  return Autosaver::folder() + QStringLiteral("/%1.linkage.json").arg(id);
}
QString metaFile(const QString& id) {
  return Autosaver::folder() + QStringLiteral("/%1.meta.json").arg(id);
}
QString lockFile(const QString& id) {
  return Autosaver::folder() + QStringLiteral("/%1.lock").arg(id);
}

void removeFiles(const QString& id) {
  for (const QString& f : {designFile(id), metaFile(id)}) QFile::remove(f);
}

QString at(const Vec2& p) {
  return QStringLiteral("(%1, %2)").arg(p.x(), 0, 'g', 6).arg(p.y(), 0, 'g', 6);
}

// What the copy changed of the file, in words a user recognises: points by name, moved, added
// or removed; joints and the driver; at most a few, then how many more.
QString describeChanges(const Mechanism& file, const Mechanism& copy) {
  QStringList said;
  auto label = [](const Mechanism& m, PointId p) {
    return QString::fromStdString(m.pointLabel(p));
  };
  for (const Point& p : copy.points) {
    const std::optional<PointId> q = file.findPoint(copy.pointLabel(p.id));
    if (!q)
      said << QStringLiteral("%1 added").arg(label(copy, p.id));
    else if (file.point(*q)->pos != p.pos)
      said << QStringLiteral("%1 moved from %2 to %3")
                  .arg(label(copy, p.id), at(file.point(*q)->pos), at(p.pos));
  }
  for (const Point& p : file.points)
    if (!copy.findPoint(file.pointLabel(p.id)))
      said << QStringLiteral("%1 removed").arg(label(file, p.id));
  if (file.joints.size() != copy.joints.size())
    said << QStringLiteral("%1 joints instead of %2")
                .arg(copy.joints.size())
                .arg(file.joints.size());
  const std::string rest = mechanismDifference(file, copy);
  if (said.isEmpty() && !rest.empty()) said << QString::fromStdString(rest);
  if (said.size() > 4) {
    const qsizetype more = said.size() - 3;
    said = said.mid(0, 3);
    said << QStringLiteral("%1 more").arg(more);
  }
  return said.join(QStringLiteral("; "));
}

}  // namespace

QString Autosaver::folder() {
  return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) +
         QStringLiteral("/autosave");
}

Autosaver::Autosaver(Document* doc, QObject* parent) : QObject(parent), doc_(doc) {
  pool_.setMaxThreadCount(1);
  id_ = uniqueId();
  timer_.setSingleShot(true);
  timer_.setInterval(kIntervalSeconds * 1000);
  connect(&timer_, &QTimer::timeout, this, &Autosaver::saveNow);
  connect(doc->undoStack(), &QUndoStack::indexChanged, this, &Autosaver::changed);
  // Saved, or a new file or example in the window: no unsaved work any more.
  connect(doc->undoStack(), &QUndoStack::cleanChanged, this, [this](bool clean) {
    if (clean) discard();
  });
  connect(doc, &Document::fileStateChanged, this, [this] {
    if (doc_ && !doc_->isModified()) discard();
  });
}

Autosaver::~Autosaver() {
  timer_.stop();
  discard();
  pool_.waitForDone();
  lock_.reset();
  QFile::remove(lockFile(id_));
}

void Autosaver::setInterval(int seconds) {
  timer_.setInterval(seconds * 1000);
}

void Autosaver::waitForWrites() {
  pool_.waitForDone();
}

QString Autosaver::copyPath() const {
  return designFile(id_);
}

void Autosaver::changed() {
  if (!doc_ || !doc_->isModified()) return;
  pending_ = true;
  if (!timer_.isActive()) timer_.start();
}

void Autosaver::saveNow() {
  timer_.stop();
  if (!doc_ || !pending_ || !doc_->isModified()) return;
  pending_ = false;
  if (!lock_) {
    QDir().mkpath(folder());
    lock_ = std::make_unique<QLockFile>(lockFile(id_));
    lock_->setStaleLockTime(0);
    lock_->tryLock(0);
  }
  // The copy of the design is taken here; turning it into text and writing it, on the pool's
  // thread. The meta last: a copy is offered only once its design is whole.
  QJsonObject meta;
  meta[QStringLiteral("path")] = doc_->filePath();
  meta[QStringLiteral("title")] = doc_->displayName();
  meta[QStringLiteral("saved")] = QDateTime::currentDateTime().toString(Qt::ISODate);
  const QByteArray metaText = QJsonDocument(meta).toJson();
  written_ = true;
  pool_.start([design = doc_->design(), metaText, id = id_] {
    if (!saveMechanismFile(design, designFile(id).toStdString()).ok) return;
    writeFileAtomically(metaFile(id).toStdString(), metaText.toStdString());
  });
}

void Autosaver::discard() {
  timer_.stop();
  pending_ = false;
  if (!written_) return;
  written_ = false;
  pool_.start([id = id_] { removeFiles(id); });
}

std::vector<Recovery> findRecoveries() {
  std::vector<Recovery> found;
  const QDir dir(Autosaver::folder());
  for (const QString& name : dir.entryList({QStringLiteral("*.meta.json")}, QDir::Files)) {
    const QString id = name.left(name.size() - int(strlen(".meta.json")));
    // A copy whose editor runs still holds its lock; one whose editor stopped does not.
    QLockFile lock(lockFile(id));
    lock.setStaleLockTime(0);
    if (!lock.tryLock(0)) continue;
    lock.unlock();
    QFile metaIn(metaFile(id));
    if (!metaIn.open(QIODevice::ReadOnly)) continue;
    const QJsonObject meta = QJsonDocument::fromJson(metaIn.readAll()).object();
    LoadResult r = loadMechanismFile(designFile(id).toStdString());
    if (!r.mechanism) continue;
    Recovery rec;
    rec.copy = designFile(id);
    rec.path = meta.value(QStringLiteral("path")).toString();
    rec.title = meta.value(QStringLiteral("title")).toString();
    rec.saved = QDateTime::fromString(meta.value(QStringLiteral("saved")).toString(), Qt::ISODate);
    rec.design = std::move(*r.mechanism);
    if (!rec.path.isEmpty())
      if (LoadResult file = loadMechanismFile(rec.path.toStdString()); file.mechanism)
        rec.difference = describeChanges(*file.mechanism, rec.design);
    found.push_back(std::move(rec));
  }
  return found;
}

void removeRecovery(const Recovery& r) {
  const QString id = QFileInfo(r.copy).fileName().remove(QStringLiteral(".linkage.json"));
  removeFiles(id);
  QFile::remove(lockFile(id));
}

void offerRecovery(QWidget* parent, const std::function<void(const Recovery&)>& open) {
  for (const Recovery& r : findRecoveries()) {
    QString text =
        QCoreApplication::translate("linkage",
                                    "Unsaved work on \"%1\" was kept when the editor stopped "
                                    "(saved automatically at %2).")
            .arg(r.title, QLocale().toString(r.saved, QLocale::ShortFormat));
    QString detail;
    if (r.path.isEmpty())
      detail = QCoreApplication::translate("linkage", "It was never saved to a file.");
    else if (!QFileInfo::exists(r.path))
      detail = QCoreApplication::translate("linkage", "Its file %1 is gone.").arg(r.path);
    else
      detail = QCoreApplication::translate("linkage", "It differs from %1 in: %2")
                   .arg(r.path, r.difference.isEmpty() ? QStringLiteral("nothing") : r.difference);
    QMessageBox box(QMessageBox::Question,
                    QCoreApplication::translate("linkage", "Recover Unsaved Work"), text,
                    QMessageBox::NoButton, parent);
    box.setInformativeText(detail +
                           QCoreApplication::translate("linkage",
                                                       "\n\nRecovered, it opens unsaved: your file "
                                                       "is only written when you save."));
    QPushButton* recover =
        box.addButton(QCoreApplication::translate("linkage", "&Recover"), QMessageBox::AcceptRole);
    QPushButton* discard = box.addButton(QMessageBox::Discard);
    box.addButton(QCoreApplication::translate("linkage", "&Keep for Later"),
                  QMessageBox::RejectRole);
    box.setDefaultButton(recover);
    box.exec();
    if (box.clickedButton() == recover) {
      open(r);
      removeRecovery(r);
    } else if (box.clickedButton() == discard) {
      removeRecovery(r);
    }
  }
}

}  // namespace linkage::ui
