#include "forces/force_rows.h"

#include <QRegularExpression>
#include <cmath>

#include "document/shown_numbers.h"
#include "linkage/io/numbers.h"

namespace linkage::ui {

std::vector<FormSection> forceSections() {
  return {massRows(), loadRows("body"), loadRows("point")};
}

std::optional<Vec2> parsePair(const QString& text) {
  const QStringList parts =
      text.split(QRegularExpression(QStringLiteral("[,;\\s]+")), Qt::SkipEmptyParts);
  if (parts.size() != 2) return std::nullopt;
  const auto x = parseNumber(parts[0].toStdString()), y = parseNumber(parts[1].toStdString());
  if (!x || !y || !std::isfinite(*x) || !std::isfinite(*y)) return std::nullopt;
  return Vec2(*x, *y);
}

QString pairText(const Vec2& v) {
  const double scale = std::hypot(v.x(), v.y());
  return shownText(cleaned(v.x(), scale)) + QStringLiteral(", ") + shownText(cleaned(v.y(), scale));
}

}  // namespace linkage::ui
