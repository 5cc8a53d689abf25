#include "window/qt_notes.h"

#include <QString>
#include <QtGlobal>

namespace linkage::ui {

namespace {

QtMessageHandler previous = nullptr;

void handler(QtMsgType type, const QMessageLogContext& context, const QString& text) {
  if (type == QtWarningMsg && (text.startsWith(QLatin1String("QStandardPaths: XDG_RUNTIME_DIR "
                                                             "not set")) ||
                               text == QLatin1String("This plugin does not support "
                                                     "propagateSizeHints()")))
    return;
  if (previous) previous(type, context, text);
}

}  // namespace

void prepareOffscreen() {
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  previous = qInstallMessageHandler(handler);
}

}  // namespace linkage::ui
