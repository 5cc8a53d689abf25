#include "window/message_strip.h"

#include <QAbstractScrollArea>
#include <QEvent>
#include <QHelpEvent>
#include <QLabel>
#include <QPainter>
#include <QTextLayout>
#include <QToolTip>

namespace linkage::ui {

namespace {

constexpr int kMargin = 6, kSpacing = 1;
constexpr int kMostRows = 3;  // of each line, before it is elided

QLabel* line(QWidget* parent, const char* name) {
  auto* l = new QLabel(parent);
  l->setAttribute(Qt::WA_TransparentForMouseEvents);
  l->setObjectName(QString::fromLatin1(name));
  l->setTextFormat(Qt::PlainText);
  // Its rows are laid out by the strip (lines()): at words, or anywhere within a word longer
  // than the line (a 300-digit number is cut into rows, not left past the edge).
  l->setAlignment(Qt::AlignLeft | Qt::AlignTop);
  l->hide();
  return l;
}

}  // namespace

MessageStrip::MessageStrip(QWidget* canvas) : QWidget(canvas), canvas_(canvas) {
  setAttribute(Qt::WA_TransparentForMouseEvents);
  hint_.label = line(this, "hint");
  problem_.label = line(this, "problem");
  notice_.label = line(this, "notice");
  message_.label = line(this, "message");
  canvas_->installEventFilter(this);
  // The mouse goes through the strip: the canvas's tooltip there is the strip's.
  if (auto* view = qobject_cast<QAbstractScrollArea*>(canvas_))
    view->viewport()->installEventFilter(this);
  colour();
  place();
}

void MessageStrip::setHint(const QString& text) {
  setLine(hint_, text);
}

void MessageStrip::setProblem(const QString& text) {
  setLine(problem_, text);
}

void MessageStrip::setNotice(const QString& text) {
  setLine(notice_, text);
}

void MessageStrip::setMessage(const QString& text, bool warning) {
  const bool changed = text != message();
  warning_ = warning;
  colour();
  setLine(message_, text);
  if (changed) Q_EMIT messageChanged(text);
}

QString MessageStrip::hint() const {
  return hint_.text;
}

QString MessageStrip::problem() const {
  return problem_.text;
}

QString MessageStrip::notice() const {
  return notice_.text;
}

QString MessageStrip::message() const {
  return message_.text;
}

QString MessageStrip::toolTipAt(const QPoint& canvasPos) const {
  if (isHidden() || !geometry().contains(canvasPos)) return {};
  QStringList whole;
  for (const Line* l : {&hint_, &problem_, &notice_, &message_})
    if (!l->text.isEmpty()) whole << l->text;
  return whole.join(QLatin1Char('\n'));
}

QStringList MessageStrip::lines(const QString& text, const QFont& f, int width, int maxLines,
                                bool* elided) {
  QStringList out;
  if (elided) *elided = false;
  QTextLayout layout(text, f);
  QTextOption o;
  o.setWrapMode(QTextOption::WrapAtWordBoundaryOrAnywhere);
  layout.setTextOption(o);
  layout.beginLayout();
  for (QTextLine l = layout.createLine(); l.isValid(); l = layout.createLine()) {
    l.setLineWidth(width);
    if (out.size() == maxLines - 1 && l.textStart() + l.textLength() < text.size()) {
      // The last row shown: the rest of the text elided into it.
      out << QFontMetrics(f).elidedText(text.mid(l.textStart()).simplified(), Qt::ElideRight,
                                        width);
      if (elided) *elided = true;
      break;
    }
    out << text.mid(l.textStart(), l.textLength()).trimmed();
  }
  layout.endLayout();
  return out;
}

void MessageStrip::setLine(Line& l, const QString& text) {
  l.text = text;
  l.label->setVisible(!text.isEmpty());
  place();
}

int MessageStrip::layOut(int maxRows) {
  const int inner = std::max(1, canvas_->width() - 2 * kMargin);
  int y = kMargin / 2;
  for (Line* l : {&hint_, &problem_, &notice_, &message_}) {
    if (l->text.isEmpty()) continue;
    const QStringList rows = lines(l->text, l->label->font(), inner, maxRows, &l->elided);
    l->label->setText(rows.join(QLatin1Char('\n')));
    const int h = std::max<int>(rows.size(), 1) * l->label->fontMetrics().lineSpacing();
    l->label->setGeometry(kMargin, y, inner, h);
    y += h + kSpacing;
  }
  return y + kMargin / 2;
}

void MessageStrip::place() {
  // The lines stacked from the canvas's bottom edge up, each as tall as its text at the
  // canvas's width: three rows each, or one each where that would cover more than half the
  // canvas (a low canvas under tall docks: the first rows were cut off above it).
  int height = layOut(kMostRows);
  if (height > canvas_->height() / 2) height = layOut(1);
  const bool any = height > kMargin;
  const QRect was = isHidden() ? QRect() : geometry();
  setGeometry(0, canvas_->height() - height, canvas_->width(), height);
  setVisible(any);
  raise();
  // The canvas's labels keep out from under the strip: placed again above its new top.
  if ((isHidden() ? QRect() : geometry()) != was)
    if (auto* view = qobject_cast<QAbstractScrollArea*>(canvas_)) view->viewport()->update();
}

bool MessageStrip::eventFilter(QObject* watched, QEvent* e) {
  if (watched == canvas_ && e->type() == QEvent::Resize) place();
  if (e->type() == QEvent::ToolTip && watched != canvas_) {
    auto* help = static_cast<QHelpEvent*>(e);
    const QPoint at = static_cast<QWidget*>(watched)->mapTo(canvas_, help->pos());
    if (const QString text = toolTipAt(at); !text.isEmpty()) {
      QToolTip::showText(help->globalPos(), text, canvas_);
      return true;
    }
  }
  return QWidget::eventFilter(watched, e);
}

void MessageStrip::paintEvent(QPaintEvent*) {
  // The canvas's paper, a little see-through: the drawing shows it is under the text.
  QPainter p(this);
  QColor paper = palette().color(QPalette::Base);
  paper.setAlpha(225);
  p.fillRect(rect(), paper);
}

void MessageStrip::changeEvent(QEvent* e) {
  if (e->type() == QEvent::PaletteChange) colour();
  if (e->type() == QEvent::FontChange) place();
  QWidget::changeEvent(e);
}

void MessageStrip::colour() {
  // Red that reads on the light palette and on the dark one.
  const bool dark = palette().color(QPalette::Base).lightness() < 128;
  const QColor red = dark ? QColor(255, 110, 100) : QColor(190, 30, 20);
  const QColor text = palette().color(QPalette::Text);
  auto paint = [](QLabel* l, const QColor& c) {
    // Both roles: a label on the canvas takes the canvas's foreground role (Text).
    QPalette p = l->palette();
    p.setColor(QPalette::WindowText, c);
    p.setColor(QPalette::Text, c);
    l->setPalette(p);
  };
  paint(problem_.label, red);
  paint(notice_.label, red);
  paint(message_.label, warning_ ? red : text);
  // The hint quieter: the text colour a little towards the paper.
  const QColor base = palette().color(QPalette::Base);
  paint(hint_.label, QColor::fromRgbF(0.6f * text.redF() + 0.4f * base.redF(),
                                      0.6f * text.greenF() + 0.4f * base.greenF(),
                                      0.6f * text.blueF() + 0.4f * base.blueF()));
}

}  // namespace linkage::ui
