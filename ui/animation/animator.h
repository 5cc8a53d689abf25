// Plays a document's motion in real time: the crank angle follows the wall clock at the
// driver's rpm times a slow-motion factor (the Wanzer at 240 rpm turns four times a second, too
// fast to watch), whatever the frame rate. A crank that cannot turn fully swings back and forth
// between the limit positions the solver reports, as a hand would move it; at a change point
// (a singular position, where the branches meet) it stops there and says why. While paused
// nothing runs.
#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QTimer>
#include <optional>

namespace linkage::ui {

class Document;

class Animator : public QObject {
  Q_OBJECT

 public:
  explicit Animator(QObject* parent = nullptr);
  void setDocument(Document* doc);

  bool playing() const { return timer_.isActive(); }
  void setPlaying(bool on);
  void toggle() { setPlaying(!playing()); }
  // One increment forward (+1) or back (-1), paused.
  void step(int direction);
  double incrementDeg() const { return increment_; }
  void setIncrementDeg(double deg);
  // 1 is real time, 0.01 a hundred times slower.
  double slowMotion() const { return slow_; }
  void setSlowMotion(double factor);
  // Crank degrees per second of wall clock now.
  double degreesPerSecond() const;
  // Advances by `seconds` of wall clock as a frame would (what tick() does; benchmarks and
  // tests call it directly).
  void advance(double seconds);
  // The limit positions found while swinging (crank degrees), when there are.
  std::optional<double> lowerLimit() const { return low_; }
  std::optional<double> upperLimit() const { return high_; }
  int sweep() const { return sweep_; }

 Q_SIGNALS:
  void playingChanged(bool playing);
  // One sentence for the status bar; `warning` for a stop the user should act on.
  void message(const QString& text, bool warning);

 private:
  void tick();
  void resetLimits();

  QPointer<Document> doc_;
  QTimer timer_;
  QElapsedTimer clock_;
  qint64 lastNs_ = 0;
  double increment_ = 1.0;
  double slow_ = 1.0;
  int sweep_ = 1;  // +1: in the driving direction; -1: back (swinging)
  std::optional<double> low_, high_;
};

}  // namespace linkage::ui
