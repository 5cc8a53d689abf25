// What every editor test includes: readable failure messages for Qt types.
#pragma once

#include <QString>
#include <ostream>

inline void PrintTo(const QString& s, std::ostream* os) {
  *os << '"' << s.toStdString() << '"';
}
// `EXPECT_...(...) << someQString` in a failure message.
inline std::ostream& operator<<(std::ostream& os, const QString& s) {
  return os << s.toStdString();
}

#include <QWidget>

// With LINKAGE_TEST_SHOTS=DIR set, a test leaves a picture of a widget there, to look at.
inline void shot(QWidget* w, const char* name) {
  const QByteArray dir = qgetenv("LINKAGE_TEST_SHOTS");
  if (!dir.isEmpty()) w->grab().save(QString::fromLocal8Bit(dir) + "/" + name + ".png");
}
