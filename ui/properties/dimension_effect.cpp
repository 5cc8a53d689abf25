#include "properties/dimension_effect.h"

#include <QStringList>

#include "document/document.h"
#include "linkage/sensitivity.h"

namespace linkage::ui {

QString dimensionEffect(const Document& doc, BodyId body) {
  const Mechanism& m = doc.design();
  if (m.outputs.empty() || !doc.solved()) return {};
  const Body* b = m.body(body);
  if (!b) return {};
  const std::string prefix = b->name + ".";
  std::vector<Dimension> own;
  for (Dimension& d : dimensions(m))
    if (d.name.rfind(prefix, 0) == 0) own.push_back(std::move(d));
  if (own.empty()) return {};
  const Kinematics& k = doc.kinematics();
  Sensitivity s;
  if (Status st = s.prepare(k, own); !st.ok())
    return QObject::tr("not yet: %1").arg(QString::fromStdString(st.message));
  if (!s.at(k).ok()) return QObject::tr("unbounded here (a dead point)");
  const PointId p = m.outputs.front();
  QStringList lines;
  for (size_t i = 0; i < own.size(); ++i) {
    const Vec2 v = s.point(k, p, static_cast<int>(i));
    const QString unit = own[i].unit == Dimension::Unit::Mm    ? QObject::tr("mm")
                         : own[i].unit == Dimension::Unit::Deg ? QObject::tr("degree")
                                                               : QObject::tr("unit");
    lines << QObject::tr("%1: x %2, y %3 mm per %4")
                 .arg(QString::fromStdString(own[i].name.substr(prefix.size())))
                 .arg(v.x(), 0, 'f', 4)
                 .arg(v.y(), 0, 'f', 4)
                 .arg(unit);
  }
  return QObject::tr("%1 moves, here, by\n%2")
      .arg(QString::fromStdString(m.pointLabel(p)), lines.join(QLatin1Char('\n')));
}

}  // namespace linkage::ui
