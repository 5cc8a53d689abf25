// Over the bottom of the canvas: what the next click does (the tool's hint), what is wrong
// with the design while it is (red), what stays true of the document until it changes (red: the
// file on disk differs from it), and the last message of an action (a result, or a warning in
// red). Each line wraps, at words or, for a word longer than the line (a path, a 300-digit
// number), anywhere, so that a message is read whole however narrow the window; past a few lines
// (one each where the canvas is low) it ends in an ellipsis, and the whole text is the strip's
// tooltip. It lies over the drawing rather than beside it, so that the canvas never moves under
// the mouse when a message comes or goes, and no message widens the window. The mouse goes
// through it to the canvas. An empty line is hidden.
#pragma once

#include <QWidget>

class QLabel;

namespace linkage::ui {

class MessageStrip : public QWidget {
  Q_OBJECT

 public:
  // Laid over the bottom of `canvas`, following its size.
  explicit MessageStrip(QWidget* canvas);
  void setHint(const QString& text);
  void setProblem(const QString& text);
  // Kept until set again (not cleared with the message): it goes when it stops being true.
  void setNotice(const QString& text);
  void setMessage(const QString& text, bool warning);
  void clearMessage() { setMessage(QString(), false); }
  // The whole texts, however they are shown.
  QString hint() const;
  QString problem() const;
  QString notice() const;
  QString message() const;
  // What the strip shows at a point of the canvas (its lines, whole), "" off the strip: its
  // tooltip there.
  QString toolTipAt(const QPoint& canvasPos) const;
  // Lines of at most `width` pixels in font `f`, broken at words or, within a word longer than a
  // line, anywhere; at most `maxLines`, the last ending in an ellipsis when the text goes on.
  static QStringList lines(const QString& text, const QFont& f, int width, int maxLines,
                           bool* elided = nullptr);

 Q_SIGNALS:
  // The message line changed (empty: cleared); what it explained (a field marked red) goes
  // with it.
  void messageChanged(const QString& text);

 protected:
  bool eventFilter(QObject* watched, QEvent* e) override;
  void changeEvent(QEvent* e) override;
  void paintEvent(QPaintEvent* e) override;

 private:
  struct Line {
    QLabel* label;
    QString text;  // whole; the label shows it laid out
    bool elided = false;
  };
  void setLine(Line& l, const QString& text);
  // Lays the lines out for the canvas's width, as many rows each as fit; returns the height.
  int layOut(int maxRows);
  void place();
  void colour();

  QWidget* canvas_;
  Line hint_, problem_, notice_, message_;
  bool warning_ = false;
};

}  // namespace linkage::ui
