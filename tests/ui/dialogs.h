// Answering the modal dialogs a test provokes (message boxes, file dialogs), as a user would.
#pragma once

#include <QAbstractButton>
#include <QApplication>
#include <QMessageBox>
#include <QTimer>
#include <functional>

namespace linkage::ui::test {

// Waits (in the event loop) for the next modal dialog and hands it to `act`; records its text.
struct DialogAnswer {
  QString text;
  bool seen = false;
  void expect(std::function<void(QWidget*)> act) {
    auto* timer = new QTimer;
    timer->setInterval(10);
    int* left = new int(300);
    QObject::connect(timer, &QTimer::timeout, [this, timer, left, act] {
      QWidget* w = QApplication::activeModalWidget();
      if (w || --*left <= 0) {
        timer->stop();
        timer->deleteLater();
        delete left;
        if (!w) return;
        seen = true;
        if (auto* box = qobject_cast<QMessageBox*>(w)) text = box->text();
        act(w);
      }
    });
    timer->start();
  }
  // Presses a standard button of the next message box.
  void press(QMessageBox::StandardButton b) {
    expect([b](QWidget* w) {
      if (auto* box = qobject_cast<QMessageBox*>(w)) box->button(b)->click();
    });
  }
};

}  // namespace linkage::ui::test
