#include "window/animation_feature.h"

#include <QAction>
#include <QComboBox>
#include <QSettings>

#include "animation/animator.h"
#include "animation/crank_bar.h"
#include "canvas/canvas_view.h"
#include "document/document.h"
#include "window/icons.h"
#include "window/main_window.h"
#include "window/message_strip.h"
#include "window/window_layout.h"

namespace linkage::ui {

AnimationFeature::AnimationFeature(MainWindow& w, WindowLayout& layout) : WindowFeature(&w), w_(w) {
  makeActions();
  crankBar_ = new CrankBar(w.animator());
  crankBar_->setDocument(w.document());
  connect(w.animator(), &Animator::playingChanged, this, &AnimationFeature::showPlaying);
  connect(w.canvas(), &CanvasView::spaceTapped, play, &QAction::trigger);
  const std::pair<Slot, QAction*> menu[] = {{Slot::AnimationPlay, play},
                                            {Slot::AnimationStepBack, stepBack},
                                            {Slot::AnimationStepForward, stepForward},
                                            {Slot::AnimationToStart, toStart},
                                            {Slot::AnimationSlower, slower},
                                            {Slot::AnimationFaster, faster},
                                            {Slot::AnimationBarPlay, play},
                                            {Slot::AnimationBarStepBack, stepBack},
                                            {Slot::AnimationBarStepForward, stepForward},
                                            {Slot::AnimationBarToStart, toStart}};
  for (const auto& [slot, a] : menu) layout.add(slot, a);
  layout.addWidget(Slot::AnimationBarCrank, crankBar_);
}

void AnimationFeature::makeActions() {
  Animator* animator = w_.animator();
  Document* doc = w_.document();
  play = makeToggle(&w_, "play", tr("&Play"), QKeySequence(tr("Space")),
                    tr("Play or pause the animation"));
  connect(play, &QAction::triggered, this, [this, animator](bool on) {
    animator->setPlaying(on);
    // A refused start leaves the button unchecked (checked, the next press would pause).
    play->setChecked(animator->playing());
  });
  stepForward = makeAction(&w_, "stepForward", tr("Step &Forward"), QKeySequence(tr("Right")),
                           tr("Turn the crank one increment forward"));
  connect(stepForward, &QAction::triggered, animator, [animator] { animator->step(+1); });
  stepBack = makeAction(&w_, "stepBack", tr("Step &Back"), QKeySequence(tr("Left")),
                        tr("Turn the crank one increment back"));
  connect(stepBack, &QAction::triggered, animator, [animator] { animator->step(-1); });
  toStart = makeAction(&w_, "toStart", tr("Back to &Start"), QKeySequence(tr("Home")),
                       tr("Turn the crank back to angle 0"));
  connect(toStart, &QAction::triggered, this, [animator, doc] {
    animator->setPlaying(false);
    if (doc->solved()) doc->setCrankDeg(0);
  });
  slower =
      makeAction(&w_, "slower", tr("S&lower"), QKeySequence(tr("[")), tr("Slower slow motion"));
  connect(slower, &QAction::triggered, this,
          [this] { crankBar_->setSpeedIndex(crankBar_->speedBox()->currentIndex() + 1); });
  faster = makeAction(&w_, "faster", tr("F&aster"), QKeySequence(tr("]")),
                      tr("Faster slow motion, up to real time"));
  connect(faster, &QAction::triggered, this,
          [this] { crankBar_->setSpeedIndex(crankBar_->speedBox()->currentIndex() - 1); });
}

void AnimationFeature::showPlaying(bool on) {
  play->setChecked(on);
  play->setText(on ? tr("&Pause") : tr("&Play"));
  play->setIcon(themedIcon(on ? QStringLiteral("pause") : QStringLiteral("play"), w_.palette()));
  if (on) w_.messageStrip()->setMessage(QString(), false);
}

void AnimationFeature::applyIcons(const QPalette& p) {
  stepForward->setIcon(themedIcon(QStringLiteral("step-forward"), p));
  stepBack->setIcon(themedIcon(QStringLiteral("step-back"), p));
  toStart->setIcon(themedIcon(QStringLiteral("to-start"), p));
  play->setIcon(
      themedIcon(w_.animator()->playing() ? QStringLiteral("pause") : QStringLiteral("play"), p));
}

void AnimationFeature::readSettings(const QSettings& s) {
  crankBar_->setSpeedIndex(s.value(QStringLiteral("speed"), 3).toInt());
  w_.animator()->setIncrementDeg(s.value(QStringLiteral("increment"), 1.0).toDouble());
}

void AnimationFeature::writeSettings(QSettings& s) const {
  s.setValue(QStringLiteral("increment"), w_.animator()->incrementDeg());
}

}  // namespace linkage::ui
