// A palette of at most 256 colours for the frames of an animation, by median cut (Heckbert
// 1982) over the colour histogram of sample frames, at full 8-bit precision per channel.
//
// Why median cut, one palette for all frames, and no dithering: a mechanism's frames are flat
// colours (background, links, pins) plus their anti-aliased edges. If the samples hold 256
// colours or fewer the palette is exactly those colours and the frames are encoded without
// loss. Otherwise the boxes with the most pixels times the widest channel range are split at
// their weighted median, so the flat colours each keep an entry of their own and the edge
// blends share the rest. One global palette keeps a colour the same in every frame (per-frame
// palettes make still parts flicker), and without dithering still parts stay still and the
// GIF compresses well.
#pragma once

#include <QImage>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace linkage::ui {

class Palette {
 public:
  // From the colours of `samples` (their alpha is ignored: frames are opaque).
  static Palette medianCut(const std::vector<QImage>& samples, int maxColours = 256);

  const std::vector<QRgb>& colours() const { return colours_; }
  // The nearest palette entry (Euclidean in RGB); answers are cached per colour.
  std::uint8_t index(QRgb c);
  // Every pixel of an opaque image (Format_RGB32) as palette indices, row by row.
  void map(const QImage& image, std::vector<std::uint8_t>& out);

 private:
  std::vector<QRgb> colours_;
  std::unordered_map<QRgb, std::uint8_t> cache_;
};

}  // namespace linkage::ui
