// linkage-plot --cycle-diagram, run by `linkage-cli timing --out`: the cycle (timing) diagram
// as a figure (linkage/timing.h). One row per output over the machine cycle, normalised to its
// stroke, with its dead centres marked; each window shaded in its output's row and named; the
// overlaps of conflicting windows in red across every row. linkage-cli has already checked
// the arguments and written the CSV; this draws what the same arguments give.
#include <QApplication>
#include <iostream>

#include "cli_common.h"
#include "cli_parser.h"
#include "export/figure_export.h"
#include "linkage/timing.h"
#include "plots/qcp.h"

namespace linkage::cli {

namespace {

constexpr double kRowPitch = 1.4;  // a row's height: the curve's 1, and the gap

// The arguments of `linkage-cli timing`, as it passes them (checked there already).
struct Options {
  std::string model, out;
  std::vector<std::string> windows, conflicts;
  int steps = 360;
};

struct FigureArgs {
  std::vector<CycleWindow> windows;
  std::vector<std::pair<std::string, std::string>> conflicts;
};

// The windows and conflicts on m; nullopt when they do not parse.
std::optional<FigureArgs> readArgs(const Mechanism& m, const Options& o) {
  FigureArgs a;
  for (const std::string& w : o.windows) {
    std::string why;
    std::optional<CycleWindow> x = parseWindow(m, w, &why);
    if (!x) {
      error("--window " + w + ": " + why);
      return std::nullopt;
    }
    a.windows.push_back(*x);
  }
  for (const std::string& c : o.conflicts)
    if (c.find(',') != std::string::npos)
      a.conflicts.emplace_back(c.substr(0, c.find(',')), c.substr(c.find(',') + 1));
  return a;
}

QColor rowColour(int i) {
  static const QColor c[] = {QColor(31, 119, 180), QColor(44, 160, 44),  QColor(148, 103, 189),
                             QColor(255, 127, 14), QColor(23, 190, 207), QColor(140, 86, 75)};
  return c[i % 6];
}

// Shades [from, to] (wrapping past 360 drawn as two pieces) between heights lo and hi.
void shade(QCustomPlot& p, const AngleInterval& i, double lo, double hi, QColor fill) {
  auto rect = [&](double a, double b) {
    auto* r = new QCPItemRect(&p);
    r->topLeft->setCoords(a, hi);
    r->bottomRight->setCoords(b, lo);
    r->setPen(Qt::NoPen);
    r->setBrush(fill);
    r->setLayer("background");
  };
  rect(i.fromDeg, std::min(i.toDeg, 360.0));
  if (i.toDeg > 360) rect(0, i.toDeg - 360);
}

void label(QCustomPlot& p, double x, double y, const QString& text) {
  auto* t = new QCPItemText(&p);
  t->position->setCoords(x, y);
  t->setText(text);
  t->setFont(QFont(p.font().family(), 8));
}

void drawRows(QCustomPlot& p, const CycleDiagram& d, QCPAxisTickerText& ticks) {
  for (size_t r = 0; r < d.rows.size(); ++r) {
    const CycleRow& row = d.rows[r];
    const double base = kRowPitch * static_cast<double>(d.rows.size() - 1 - r);
    QVector<double> x, y;
    for (size_t i = 0; i < row.value.size(); ++i) {
      x << row.crankDeg[i];
      y << base + row.normalised[i];
    }
    QCPGraph* g = p.addGraph();
    g->setData(x, y, true);
    g->setPen(QPen(rowColour(static_cast<int>(r)), 1.5));
    QCPGraph* dots = p.addGraph();
    dots->setLineStyle(QCPGraph::lsNone);
    dots->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, Qt::black, 5));
    const double span = row.max > row.min ? row.max - row.min : 1;
    for (const LocalExtreme& e : row.extremes)
      dots->addData(e.crankDeg, base + (e.value - row.min) / span);
    for (const AngleInterval& w : row.dwells) shade(p, w, base, base + 1, QColor(0, 0, 0, 25));
    ticks.addTick(base + 0.5, QString::fromStdString(row.output.name));
  }
}

void drawWindows(QCustomPlot& p, const CycleDiagram& d, const std::vector<CycleWindow>& ws) {
  for (size_t w = 0; w < ws.size(); ++w) {
    size_t r = 0;
    while (d.rows[r].output.name != ws[w].output.name) ++r;
    const double base = kRowPitch * static_cast<double>(d.rows.size() - 1 - r);
    QColor fill = rowColour(static_cast<int>(r));
    fill.setAlpha(50);
    for (const AngleInterval& i : d.windows[w].intervals) {
      shade(p, i, base - 0.15, base + 1.15, fill);
      // A wrapping interval is drawn in two pieces: its name on the longer.
      const bool wraps = i.toDeg > 360, atEnd = 360 - i.fromDeg >= i.toDeg - 360;
      const double mid = !wraps  ? 0.5 * (i.fromDeg + i.toDeg)
                         : atEnd ? 0.5 * (i.fromDeg + 360)
                                 : 0.5 * (i.toDeg - 360);
      label(p, mid, base + 1.07, QString::fromStdString(ws[w].name));
    }
  }
  const double top = kRowPitch * static_cast<double>(d.rows.size());
  for (const Conflict& c : d.conflicts)
    for (const AngleInterval& i : c.overlaps) shade(p, i, -0.3, top - 0.2, QColor(214, 39, 40, 60));
}

int cycleFigure(const Options& o) {
  std::optional<Mechanism> m = openDrivenModel(o.model);
  if (!m) return kBadInput;
  std::optional<FigureArgs> a = readArgs(*m, o);
  if (!a) return kBadInput;
  Kinematics k;
  if (int e = prepare(k, *m); e != kOk) return e;
  CycleOptions opt;
  opt.steps = o.steps;
  const CycleDiagram d = cycleDiagram(k, {}, a->windows, a->conflicts, opt);
  if (!d.status.ok()) {
    error(d.status.message);
    return exitFor(d.status);
  }
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  static int qtArgc = 1;
  static char qtName[] = "linkage-cli";
  static char* qtArgv[] = {qtName, nullptr};
  QApplication app(qtArgc, qtArgv);
  QCustomPlot p;
  auto ticks = QSharedPointer<QCPAxisTickerText>::create();
  drawRows(p, d, *ticks);
  drawWindows(p, d, a->windows);
  p.yAxis->setTicker(ticks);
  p.yAxis->setRange(-0.3, kRowPitch * static_cast<double>(d.rows.size()) - 0.2);
  p.xAxis->setRange(0, 360);
  p.xAxis->setLabel("crank angle of the main shaft (deg)");
  auto xt = QSharedPointer<QCPAxisTickerFixed>::create();
  xt->setTickStep(30);
  p.xAxis->setTicker(xt);
  p.plotLayout()->insertRow(0);
  p.plotLayout()->addElement(
      0, 0, new QCPTextElement(&p, QString::fromStdString(m->name) + ": cycle diagram"));
  const QSize size(900, 160 + 110 * static_cast<int>(d.rows.size()));
  p.resize(size);
  QString err;
  if (!ui::exportPlot(&p, QString::fromStdString(o.out), size, &err)) {
    error(err.toStdString());
    return kFailure;
  }
  return kOk;
}

}  // namespace

Command cycleDiagramCommand(Parser& parser) {
  auto o = std::make_shared<Options>();
  CLI::App& c =
      parser.command("cycle-diagram",
                     "usage: linkage-plot cycle-diagram --model MODEL --out FIG "
                     "[--window NAME=EXPR ...] [--conflict N1,N2 ...] [--steps N]\n\n"
                     "Run by 'linkage-cli timing --out': see linkage-cli timing --help.\n");
  required(addText(c, "--model", o->model));
  required(addFigureFile(c, "--out", o->out));
  addTexts(c, "--window", o->windows);
  addTexts(c, "--conflict", o->conflicts);
  addWhole(c, "--steps", o->steps, 4, 1'000'000);
  return {&c, [o] { return cycleFigure(*o); }};
}

}  // namespace linkage::cli
