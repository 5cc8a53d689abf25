// A plot written to a file by the path's suffix: .png (raster), .pdf and .svg (vector: lines
// and text stay lines and text). The file is replaced atomically; on failure `error` names the
// path and the reason and nothing is written.
#pragma once

#include <QSize>
#include <QString>

class QCustomPlot;

namespace linkage::ui {

// `size` in pixels (PDF: the page in points, text sized as on the screen, as QCustomPlot's own
// savePdf does). The plot's layout is computed for that size while it is drawn.
bool exportPlot(QCustomPlot* plot, const QString& path, QSize size, QString* error);

// The suffixes exportPlot knows, for file dialogs: "png", "pdf", "svg".
QStringList plotFormats();

}  // namespace linkage::ui
