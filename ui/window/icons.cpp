#include "window/icons.h"

#include <QFile>
#include <QPainter>
#include <QSvgRenderer>

// The icons are compiled into the static library: their registration must be asked for.
static void registerIcons() {
  static const bool done = [] {
    Q_INIT_RESOURCE(icons);
    return true;
  }();
  (void)done;
}

namespace linkage::ui {

QIcon themedIcon(const QString& name, const QPalette& palette) {
  registerIcons();
  QFile f(QStringLiteral(":/icons/%1.svg").arg(name));
  if (!f.open(QIODevice::ReadOnly)) return QIcon();
  QByteArray svg = f.readAll();
  QIcon icon;
  const std::pair<QIcon::Mode, QPalette::ColorGroup> modes[] = {
      {QIcon::Normal, QPalette::Active}, {QIcon::Disabled, QPalette::Disabled}};
  for (const auto& [mode, group] : modes) {
    const QByteArray colour = palette.color(group, QPalette::ButtonText).name().toLatin1();
    QSvgRenderer r(QByteArray(svg).replace("currentColor", colour));
    for (int size : {16, 22, 24, 32, 48}) {
      QPixmap pm(size, size);
      pm.fill(Qt::transparent);
      QPainter p(&pm);
      r.render(&p);
      p.end();
      icon.addPixmap(pm, mode);
    }
  }
  return icon;
}

}  // namespace linkage::ui
