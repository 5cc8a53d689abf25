// What the force figures share (the forces panel's and the balance dialog's): axes against the
// crank angle over one turn, and the polar diagram of the shaking force (fy against fx, the
// classic picture of an unbalanced machine) on axes of equal scales, so that a circle is drawn
// as a circle and the diagram's shape can be read off.
#pragma once

#include <QColor>
#include <QString>
#include <vector>

#include "linkage/model.h"

class QCustomPlot;
class QCPAbstractPlottable;
class QCPAxisRect;
class QCPCurve;
class QCPGraph;
class QCPLayoutGrid;
class QCPRange;

namespace linkage::ui {

namespace forceColours {
inline const QColor kX{31, 119, 180}, kY{214, 39, 40}, kZ{44, 150, 44}, kNorm{90, 90, 90},
    kPolar{31, 119, 180}, kBefore{150, 150, 150}, kAfter{31, 119, 180}, kNote{150, 20, 20};
}

// A rect of the plot's layout with the crank angle from 0 to 360 on x (setCrankAxis,
// figures/crank_figure.h) and `yLabel` on y.
QCPAxisRect* addCrankRect(QCustomPlot* plot, const QString& crankLabel, const QString& yLabel);
// A curve of values against the crank angles (the same length), pen of `colour`.
QCPGraph* addCurve(QCPAxisRect* rect, const std::vector<double>& deg,
                   const std::vector<double>& values, const QColor& colour, const QString& name,
                   Qt::PenStyle style = Qt::SolidLine);
// y's range padded around the graphs' values in the rect, zero in view, at least
// +-minHalfRange: curves that are rounding of zero (1e-14 N) are drawn flat on the zero line,
// not blown up into noise.
void fitValues(QCPAxisRect* rect, double minHalfRange);
// The largest finite |value| (0 for none).
double peakOf(const std::vector<double>& v);
double peakOf(const std::vector<Vec2>& v);
double peakOf(const std::vector<Vec3>& v);
// A line across the rect at y = 0 and (polar) at x = 0: where the force changes sign.
void addZeroLines(QCPAxisRect* rect, bool vertical);
// A legend of the graphs and curves given: beside the rect, in column 1 of `cell` (the grid
// holding the rect in its column 0: the legend hides no curve), or without a cell in the corner
// of the rect its curves leave emptiest (the axes' ranges set first).
void addLegend(QCPAxisRect* rect, const std::vector<QCPAbstractPlottable*>& items,
               QCPLayoutGrid* cell = nullptr);
// A grid in grid's cell (row, column) holding `rect` in its column 0, for a legend beside it.
QCPLayoutGrid* addPlotCell(QCPLayoutGrid* grid, int row, int column, QCPAxisRect* rect);
// A sentence in the rect in place of curves (the rect's value axis shows no numbers).
void addRectNote(QCPAxisRect* rect, const QString& text);
// A bold title in a cell of a layout grid (above a plot).
void addTitle(QCPLayoutGrid* grid, int row, int column, const QString& text);

// The polar diagram of forces (N): fx on x, fy on y; the axes' ranges are set by
// fitEqualScales. (Items such as addZeroLines' go on a rect once it is in the layout.)
QCPAxisRect* addPolarRect(QCustomPlot* plot);
QCPCurve* addPolarCurve(QCPAxisRect* rect, const std::vector<Vec2>& f, const QColor& colour,
                        const QString& name, double width = 1.6);
// The box of the polar curves' points (with the origin, so the diagram's offset shows).
void polarBox(QCPAxisRect* rect, QCPRange& x, QCPRange& y);
// Sets the rect's ranges so that a newton is as long on x as on y and the box shows whole,
// centred: true when a range changed. Needs the rect laid out (QCustomPlot::afterLayout).
bool fitEqualScales(QCPAxisRect* rect);

}  // namespace linkage::ui
