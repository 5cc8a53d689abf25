// Animated GIFs with giflib (Debian's libgif): frames of one size, one global palette
// (palette.h), a delay per frame in hundredths of a second, looping forever (the NETSCAPE2.0
// extension). The file is built in memory and written atomically.
#pragma once

#include <QByteArray>
#include <QImage>
#include <QString>

#include "export/palette.h"

struct GifFileType;

namespace linkage::ui {

class GifWriter {
 public:
  // delay: hundredths of a second per frame (at least 2: browsers play 0 and 1 as 10).
  GifWriter(QSize size, Palette palette, int delayCentiseconds);
  ~GifWriter();
  GifWriter(const GifWriter&) = delete;
  GifWriter& operator=(const GifWriter&) = delete;

  // A frame of the writer's size (others are refused); its alpha is composed over white.
  bool addFrame(const QImage& frame, QString* error);
  // Ends the stream; the GIF's bytes.
  bool finish(QByteArray* gif, QString* error);
  int frames() const { return frames_; }

 private:
  bool check(int giflibResult, const char* what, QString* error);

  QSize size_;
  Palette palette_;
  int delay_;
  int frames_ = 0;
  QByteArray bytes_;
  GifFileType* gif_ = nullptr;
  bool failed_ = false;
};

}  // namespace linkage::ui
