// File > Export > Animation: the mechanism moving, as an animated GIF or a numbered PNG
// sequence, at a chosen size, frame count and speed. The frames come from a renderer the
// caller supplies (the canvas draws the mechanism at a crank angle), so this knows nothing of
// how the mechanism is drawn.
#pragma once

#include <QImage>
#include <QSize>
#include <QString>
#include <QStringList>
#include <functional>

namespace linkage::ui {

// The picture of the mechanism at a crank angle (degrees from the start), at a size.
using FrameRenderer = std::function<QImage(double crankDeg, QSize size)>;

struct AnimationSpec {
  enum class Format { Gif, PngSequence };
  Format format = Format::Gif;
  // The .gif; for a PNG sequence the name the frames are numbered from: "dir/run.png" gives
  // dir/run_0001.png, dir/run_0002.png, ...
  QString path;
  QSize size{640, 480};
  int frames = 72;
  double revs = 1;      // turns of the crank over the frames
  double startDeg = 0;  // crank angle of the first frame
  double fps = 25;      // playback rate; a GIF stores whole hundredths of a second per frame
};

// Crank angle of frame i: the frames cover [start, start + 360 revs) evenly, the last one step
// short of the first again, so a loop is seamless.
double frameAngle(const AnimationSpec& spec, int i);
// The playback rate at which the mechanism turns `speed` times as fast as its driver's rpm.
double framesPerSecondFor(int frames, double revs, double rpm, double speed);
// The GIF delay of a frame, hundredths of a second (2 ... 100).
int gifDelay(double fps);
// The file names of a PNG sequence.
QStringList pngSequenceNames(const QString& path, int frames);

// Renders and writes every frame. `progress(done, total)` may cancel by returning false (no
// GIF is written then; PNG frames already written stay). On failure `error` says why.
bool exportAnimation(const AnimationSpec& spec, const FrameRenderer& render, QString* error,
                     const std::function<bool(int, int)>& progress = {});

}  // namespace linkage::ui
