#include "export/animation_export.h"

#include <QBuffer>
#include <QFileInfo>
#include <algorithm>
#include <cmath>

#include "export/gif_writer.h"
#include "linkage/io/atomic_file.h"

namespace linkage::ui {

namespace {

bool fail(QString* error, const QString& text) {
  if (error) *error = text;
  return false;
}

// At most this many frames, evenly spread, choose the GIF's palette.
constexpr int kPaletteSamples = 12;

bool writeFile(const QString& path, const QByteArray& bytes, QString* error) {
  const WriteResult w = writeFileAtomically(path.toStdString(), bytes.toStdString());
  return w.ok || fail(error, QString::fromStdString(w.error));
}

QImage renderFrame(const FrameRenderer& render, const AnimationSpec& spec, int i, QString* error) {
  QImage img = render(frameAngle(spec, i), spec.size);
  if (img.isNull()) {
    fail(error, QString("frame %1 could not be drawn").arg(i + 1));
    return {};
  }
  if (img.size() != spec.size)
    img = img.scaled(spec.size, Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
  return img;
}

}  // namespace

double frameAngle(const AnimationSpec& spec, int i) {
  return spec.startDeg + 360.0 * spec.revs * static_cast<double>(i) / spec.frames;
}

double framesPerSecondFor(int frames, double revs, double rpm, double speed) {
  // One revolution takes 60 / rpm seconds; the frames cover `revs` of them.
  const double seconds = revs * 60.0 / (rpm * speed);
  return frames / seconds;
}

int gifDelay(double fps) {
  return std::clamp(static_cast<int>(std::lround(100.0 / fps)), 2, 100);
}

QStringList pngSequenceNames(const QString& path, int frames) {
  const QFileInfo info(path);
  QString base = info.completeBaseName();
  const QString dir = info.path();
  const int digits = std::max(4, static_cast<int>(QString::number(frames).size()));
  QStringList names;
  for (int i = 1; i <= frames; ++i)
    names << QString("%1/%2_%3.png").arg(dir, base).arg(i, digits, 10, QChar('0'));
  return names;
}

bool exportAnimation(const AnimationSpec& spec, const FrameRenderer& render, QString* error,
                     const std::function<bool(int, int)>& progress) {
  if (spec.frames < 1 || spec.frames > 100000)
    return fail(error, "The frame count must be from 1 to 100000.");
  if (spec.size.width() < 16 || spec.size.height() < 16 || spec.size.width() > 8192 ||
      spec.size.height() > 8192)
    return fail(error, "The frame size must be from 16 to 8192 pixels each way.");
  if (!(spec.revs > 0) || !(spec.fps > 0))
    return fail(error, "Revolutions and speed must be positive.");
  if (spec.path.isEmpty()) return fail(error, "No file name.");
  if (!render) return fail(error, "Nothing draws the frames.");
  auto step = [&](int done) { return !progress || progress(done, spec.frames); };

  if (spec.format == AnimationSpec::Format::PngSequence) {
    const QStringList names = pngSequenceNames(spec.path, spec.frames);
    for (int i = 0; i < spec.frames; ++i) {
      const QImage img = renderFrame(render, spec, i, error);
      if (img.isNull()) return false;
      QBuffer buffer;
      buffer.open(QIODevice::WriteOnly);
      if (!img.save(&buffer, "PNG")) return fail(error, QString("frame %1: PNG").arg(i + 1));
      if (!writeFile(names[i], buffer.data(), error)) return false;
      if (!step(i + 1)) return fail(error, "Cancelled.");
    }
    return true;
  }

  std::vector<QImage> samples;
  const int n = std::min(spec.frames, kPaletteSamples);
  for (int k = 0; k < n; ++k) {
    const QImage img = renderFrame(render, spec, k * spec.frames / n, error);
    if (img.isNull()) return false;
    samples.push_back(img);
  }
  GifWriter gif(spec.size, Palette::medianCut(samples), gifDelay(spec.fps));
  samples.clear();
  for (int i = 0; i < spec.frames; ++i) {
    const QImage img = renderFrame(render, spec, i, error);
    if (img.isNull() || !gif.addFrame(img, error)) return false;
    if (!step(i + 1)) return fail(error, "Cancelled.");
  }
  QByteArray bytes;
  return gif.finish(&bytes, error) && writeFile(spec.path, bytes, error);
}

}  // namespace linkage::ui
