// Over the bottom of the canvas: what the next click does (the tool's hint), what is wrong
// with the design while it is (red), what stays true of the document until it changes (red: the
// file on disk differs from it), and the last message of an action (a result, or a warning in
// red). Each line wraps, so that a message is read whole however long it is and however
// narrow the window; it lies over the drawing rather than beside it, so that the canvas never
// moves under the mouse when a message comes or goes, and no message widens the window. The
// mouse goes through it to the canvas. An empty line is hidden.
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
  QString hint() const;
  QString problem() const;
  QString notice() const;
  QString message() const;

 Q_SIGNALS:
  // The message line changed (empty: cleared); what it explained (a field marked red) goes
  // with it.
  void messageChanged(const QString& text);

 protected:
  bool eventFilter(QObject* watched, QEvent* e) override;
  void changeEvent(QEvent* e) override;
  void paintEvent(QPaintEvent* e) override;

 private:
  void setLine(QLabel* l, const QString& text);
  void place();
  void colour();

  QWidget* canvas_;
  QLabel *hint_, *problem_, *notice_, *message_;
  bool warning_ = false;
};

}  // namespace linkage::ui
