// What a window's design checks look at, shared by the canvas overlays (extreme positions,
// transmission arcs) and the design-checks panel: the transmission band, remembered in QSettings
// ("design/bandLo", "design/bandHi") like the view's toggles, and the subject of the limit
// positions: a point along a direction, or a body's angle. The subject is kept by name
// ("body.point", a body's name), so that it survives edits and undo; where the mechanism has no
// such point or body, the first output point along its default direction is used.
#pragma once

#include <QObject>
#include <QString>
#include <optional>

#include "linkage/limits.h"
#include "linkage/transmission.h"

namespace linkage::ui {

struct LimitSubject {
  QString point;                  // "body.point", or empty
  QString body;                   // a body's name (its angle), when point is empty
  std::optional<Vec2> direction;  // of a point; none: defaultDirection
  bool operator==(const LimitSubject&) const = default;
};

class DesignChoices : public QObject {
  Q_OBJECT

 public:
  explicit DesignChoices(QObject* parent = nullptr);
  ~DesignChoices() override;

  const TransmissionBand& band() const { return band_; }
  // Refused (false, nothing changed) unless 0 <= lo < hi <= 180. Every window's choices follow.
  bool setBand(const TransmissionBand& b);
  bool outside(double muDeg) const { return muDeg < band_.lo || muDeg > band_.hi; }

  const LimitSubject& subject() const { return subject_; }
  void setSubject(const LimitSubject& s);

  // The measure on m: the subject where m has it, else m's first output point along its
  // default direction; none when m has neither (or a direction is not a non-zero vector).
  std::optional<LimitMeasure> measure(const Mechanism& m) const;
  // What measure(m) follows, in words: "needlebar.G along (0, 1)", "lever angle".
  QString describe(const Mechanism& m) const;

 Q_SIGNALS:
  void bandChanged();
  void subjectChanged();

 private:
  TransmissionBand band_;
  LimitSubject subject_;
};

}  // namespace linkage::ui
