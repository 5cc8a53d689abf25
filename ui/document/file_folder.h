// Where the file dialogs open (issue 19): beside the document's file, else in the folder a file
// was last opened or saved in (QSettings "lastFolder"), else the home folder; and the name an
// export suggests there. One place for every dialog of the window and of its docks.
#pragma once

#include <QString>

namespace linkage::ui {

class Document;

QString fileFolder(const Document* d);
QString lastFolder();
// A file was opened or saved there.
void setLastFolder(const QString& folder);
// In fileFolder(d), named after the mechanism's file or title with `suffix` appended
// ("wanzer-forces.svg" for "-forces.svg").
QString suggestedFile(const Document* d, const QString& suffix);

}  // namespace linkage::ui
