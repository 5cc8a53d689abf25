#include "export/gif_writer.h"

#include <gif_lib.h>

#include <QPainter>
#include <algorithm>

namespace linkage::ui {

namespace {

int appendBytes(GifFileType* gif, const GifByteType* data, int length) {
  static_cast<QByteArray*>(gif->UserData)->append(reinterpret_cast<const char*>(data), length);
  return length;
}

QImage opaque(const QImage& frame) {
  if (!frame.hasAlphaChannel()) return frame.convertToFormat(QImage::Format_RGB32);
  QImage out(frame.size(), QImage::Format_RGB32);
  out.fill(Qt::white);
  QPainter p(&out);
  p.drawImage(0, 0, frame);
  return out;
}

}  // namespace

GifWriter::GifWriter(QSize size, Palette palette, int delayCentiseconds)
    : size_(size), palette_(std::move(palette)), delay_(std::max(2, delayCentiseconds)) {
  int err = 0;
  gif_ = EGifOpen(&bytes_, appendBytes, &err);
  if (!gif_) {
    failed_ = true;
    return;
  }
  EGifSetGifVersion(gif_, true);  // GIF89a: delays and the loop extension
  // The colour table's size is a power of two; unused entries are black.
  int bits = 1;
  while ((1 << bits) < static_cast<int>(palette_.colours().size())) ++bits;
  std::vector<GifColorType> colours(size_t(1) << bits, GifColorType{0, 0, 0});
  for (size_t i = 0; i < palette_.colours().size(); ++i) {
    const QRgb c = palette_.colours()[i];
    colours[i] = GifColorType{GifByteType(qRed(c)), GifByteType(qGreen(c)), GifByteType(qBlue(c))};
  }
  ColorMapObject* map = GifMakeMapObject(1 << bits, colours.data());
  const int ok = map ? EGifPutScreenDesc(gif_, size.width(), size.height(), 8, 0, map) : GIF_ERROR;
  GifFreeMapObject(map);
  // Loop forever: application extension NETSCAPE2.0, sub-block {1, loop count 0 (LE)}.
  const GifByteType loop[3] = {1, 0, 0};
  if (ok == GIF_ERROR || EGifPutExtensionLeader(gif_, APPLICATION_EXT_FUNC_CODE) == GIF_ERROR ||
      EGifPutExtensionBlock(gif_, 11, "NETSCAPE2.0") == GIF_ERROR ||
      EGifPutExtensionBlock(gif_, 3, loop) == GIF_ERROR ||
      EGifPutExtensionTrailer(gif_) == GIF_ERROR)
    failed_ = true;
}

GifWriter::~GifWriter() {
  if (gif_) EGifCloseFile(gif_, nullptr);
}

bool GifWriter::check(int result, const char* what, QString* error) {
  if (result != GIF_ERROR && !failed_) return true;
  failed_ = true;
  if (error)
    *error = QString("GIF %1: %2").arg(what, gif_ ? GifErrorString(gif_->Error) : "not open");
  return false;
}

bool GifWriter::addFrame(const QImage& frame, QString* error) {
  if (!check(gif_ ? GIF_OK : GIF_ERROR, "writer", error)) return false;
  if (frame.size() != size_) {
    if (error)
      *error = QString("frame %1 is %2 x %3, not %4 x %5")
                   .arg(frames_ + 1)
                   .arg(frame.width())
                   .arg(frame.height())
                   .arg(size_.width())
                   .arg(size_.height());
    return false;
  }
  GraphicsControlBlock gcb;
  gcb.DisposalMode = DISPOSE_DO_NOT;
  gcb.UserInputFlag = false;
  gcb.DelayTime = delay_;
  gcb.TransparentColor = NO_TRANSPARENT_COLOR;
  GifByteType ext[4];
  const size_t extLength = EGifGCBToExtension(&gcb, ext);
  if (!check(EGifPutExtension(gif_, GRAPHICS_EXT_FUNC_CODE, int(extLength), ext), "frame", error))
    return false;
  if (!check(EGifPutImageDesc(gif_, 0, 0, size_.width(), size_.height(), false, nullptr), "frame",
             error))
    return false;
  std::vector<std::uint8_t> indices;
  palette_.map(opaque(frame), indices);
  for (int y = 0; y < size_.height(); ++y)
    if (!check(EGifPutLine(gif_, indices.data() + size_t(y) * size_.width(), size_.width()),
               "frame", error))
      return false;
  ++frames_;
  return true;
}

bool GifWriter::finish(QByteArray* gif, QString* error) {
  if (!check(gif_ ? GIF_OK : GIF_ERROR, "writer", error)) return false;
  int err = 0;
  const int r = EGifCloseFile(gif_, &err);
  gif_ = nullptr;
  if (r == GIF_ERROR) {
    if (error) *error = QString("GIF end: %1").arg(GifErrorString(err));
    return false;
  }
  *gif = bytes_;
  return true;
}

}  // namespace linkage::ui
