#include "figures/figure_export.h"

#include <QBuffer>
#include <QFileInfo>
#include <QPageLayout>
#include <QPdfWriter>
#include <QSvgGenerator>

#include "figures/qcp.h"
#include "linkage/io/atomic_file.h"

namespace linkage::ui {

namespace {

bool fail(QString* error, const QString& text) {
  if (error) *error = text;
  return false;
}

// Draws the plot at w x h logical pixels on a vector device, text as text.
bool drawVector(QCustomPlot* plot, QPaintDevice* device, int w, int h) {
  QCPPainter painter;
  if (!painter.begin(device)) return false;
  painter.setMode(QCPPainter::pmVectorized);
  painter.setMode(QCPPainter::pmNoCaching);
  painter.setWindow(0, 0, w, h);
  plot->toPainter(&painter, w, h);
  return painter.end();
}

}  // namespace

QStringList plotFormats() {
  return {"png", "pdf", "svg"};
}

bool exportPlot(QCustomPlot* plot, const QString& path, QSize size, QString* error) {
  const QString suffix = QFileInfo(path).suffix().toLower();
  if (!plotFormats().contains(suffix))
    return fail(error, QString("%1: unknown format \"%2\" (png, pdf or svg)").arg(path, suffix));
  if (size.width() < 50 || size.height() < 50 || size.width() > 20000 || size.height() > 20000)
    return fail(error, QString("%1: size %2 x %3 is not between 50 and 20000 pixels")
                           .arg(path)
                           .arg(size.width())
                           .arg(size.height()));
  const int w = size.width(), h = size.height();
  QBuffer buffer;
  buffer.open(QIODevice::WriteOnly);
  bool drawn = false;
  if (suffix == "png") {
    drawn = plot->toPixmap(w, h, 1.0).save(&buffer, "PNG");
  } else if (suffix == "pdf") {
    QPdfWriter pdf(&buffer);
    pdf.setCreator("linkage");
    pdf.setTitle(QFileInfo(path).completeBaseName());
    pdf.setResolution(plot->logicalDpiX());
    QPageLayout page(QPageSize(QSizeF(w, h), QPageSize::Point, QString(), QPageSize::ExactMatch),
                     QPageLayout::Portrait, QMarginsF(0, 0, 0, 0));
    page.setMode(QPageLayout::FullPageMode);
    pdf.setPageLayout(page);
    drawn = drawVector(plot, &pdf, w, h);
  } else {
    QSvgGenerator svg;
    svg.setOutputDevice(&buffer);
    svg.setSize(size);
    svg.setViewBox(QRect(0, 0, w, h));
    svg.setResolution(plot->logicalDpiX());
    svg.setTitle(QFileInfo(path).completeBaseName());
    drawn = drawVector(plot, &svg, w, h);
  }
  plot->replot();  // the layout back at the widget's own size
  if (!drawn || buffer.data().isEmpty())
    return fail(error, QString("%1: the %2 could not be drawn").arg(path, suffix.toUpper()));
  const WriteResult wr = writeFileAtomically(path.toStdString(), buffer.data().toStdString());
  if (!wr.ok) return fail(error, QString::fromStdString(wr.error));
  return true;
}

}  // namespace linkage::ui
