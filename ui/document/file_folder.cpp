#include "document/file_folder.h"

#include <QDir>
#include <QFileInfo>
#include <QSettings>

#include "document/document.h"

namespace linkage::ui {

namespace {
const char* kLastFolderKey = "lastFolder";
}

QString lastFolder() {
  return QSettings().value(kLastFolderKey).toString();
}

void setLastFolder(const QString& folder) {
  QSettings().setValue(kLastFolderKey, folder);
}

QString fileFolder(const Document* d) {
  if (d && !d->filePath().isEmpty()) return QFileInfo(d->filePath()).absolutePath();
  const QString last = lastFolder();
  return !last.isEmpty() && QFileInfo(last).isDir() ? last : QDir::homePath();
}

QString suggestedFile(const Document* d, const QString& suffix) {
  QString base = d ? d->displayName() : QStringLiteral("linkage");
  base.remove(QStringLiteral(".linkage.json"));
  return QDir(fileFolder(d)).filePath(base + suffix);
}

}  // namespace linkage::ui
