#include "window/message_strip.h"

#include <QAbstractScrollArea>
#include <QEvent>
#include <QLabel>
#include <QPainter>

namespace linkage::ui {

namespace {

constexpr int kMargin = 6, kSpacing = 1;

QLabel* line(QWidget* parent, const char* name) {
  auto* l = new QLabel(parent);
  l->setAttribute(Qt::WA_TransparentForMouseEvents);
  l->setObjectName(QString::fromLatin1(name));
  l->setTextFormat(Qt::PlainText);
  l->setWordWrap(true);
  // Wrapped anywhere if need be: a 300-digit number is cut into lines, not left past the edge.
  l->setAlignment(Qt::AlignLeft | Qt::AlignTop);
  l->hide();
  return l;
}

}  // namespace

MessageStrip::MessageStrip(QWidget* canvas) : QWidget(canvas), canvas_(canvas) {
  setAttribute(Qt::WA_TransparentForMouseEvents);
  hint_ = line(this, "hint");
  problem_ = line(this, "problem");
  notice_ = line(this, "notice");
  message_ = line(this, "message");
  canvas_->installEventFilter(this);
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
  return hint_->text();
}

QString MessageStrip::problem() const {
  return problem_->isHidden() ? QString() : problem_->text();
}

QString MessageStrip::notice() const {
  return notice_->isHidden() ? QString() : notice_->text();
}

QString MessageStrip::message() const {
  return message_->isHidden() ? QString() : message_->text();
}

void MessageStrip::setLine(QLabel* l, const QString& text) {
  l->setText(text);
  l->setVisible(!text.isEmpty());
  place();
}

void MessageStrip::place() {
  // The lines stacked from the canvas's bottom edge up, each as tall as its text at the
  // canvas's width.
  const int width = canvas_->width(), inner = std::max(1, width - 2 * kMargin);
  int y = kMargin / 2;
  for (QLabel* l : {hint_, problem_, notice_, message_}) {
    if (l->isHidden()) continue;
    const int h = std::max(l->heightForWidth(inner), l->fontMetrics().height());
    l->setGeometry(kMargin, y, inner, h);
    y += h + kSpacing;
  }
  const int height = y + kMargin / 2;
  const QRect was = isHidden() ? QRect() : geometry();
  setGeometry(0, canvas_->height() - height, width, height);
  setVisible(y > kMargin / 2);
  raise();
  // The canvas's labels keep out from under the strip: placed again above its new top.
  if ((isHidden() ? QRect() : geometry()) != was)
    if (auto* view = qobject_cast<QAbstractScrollArea*>(canvas_)) view->viewport()->update();
}

bool MessageStrip::eventFilter(QObject* watched, QEvent* e) {
  if (watched == canvas_ && e->type() == QEvent::Resize) place();
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
  paint(problem_, red);
  paint(notice_, red);
  paint(message_, warning_ ? red : text);
  // The hint quieter: the text colour a little towards the paper.
  const QColor base = palette().color(QPalette::Base);
  paint(hint_, QColor::fromRgbF(0.6f * text.redF() + 0.4f * base.redF(),
                                0.6f * text.greenF() + 0.4f * base.greenF(),
                                0.6f * text.blueF() + 0.4f * base.blueF()));
}

}  // namespace linkage::ui
