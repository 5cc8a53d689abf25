#include "export/palette.h"

#include <algorithm>
#include <array>

namespace linkage::ui {

namespace {

struct Entry {
  QRgb colour;
  std::uint64_t count;
};

int channel(QRgb c, int ch) {
  return ch == 0 ? qRed(c) : ch == 1 ? qGreen(c) : qBlue(c);
}

struct Box {
  std::vector<Entry> entries;
  std::uint64_t count = 0;
  int widest = 0, range = 0;  // the channel with the largest spread, and that spread

  void measure() {
    count = 0;
    std::array<int, 3> lo{255, 255, 255}, hi{0, 0, 0};
    for (const Entry& e : entries) {
      count += e.count;
      for (int ch = 0; ch < 3; ++ch) {
        lo[ch] = std::min(lo[ch], channel(e.colour, ch));
        hi[ch] = std::max(hi[ch], channel(e.colour, ch));
      }
    }
    range = -1;
    for (int ch = 0; ch < 3; ++ch)
      if (hi[ch] - lo[ch] > range) range = hi[ch] - lo[ch], widest = ch;
  }
  double priority() const { return entries.size() < 2 ? -1 : double(count) * range; }
  QRgb mean() const {
    double s[3] = {0, 0, 0};
    for (const Entry& e : entries)
      for (int ch = 0; ch < 3; ++ch) s[ch] += double(e.count) * channel(e.colour, ch);
    auto c = [&](int ch) { return int(s[ch] / double(count) + 0.5); };
    return qRgb(c(0), c(1), c(2));
  }
};

}  // namespace

Palette Palette::medianCut(const std::vector<QImage>& samples, int maxColours) {
  std::unordered_map<QRgb, std::uint64_t> histogram;
  for (const QImage& image : samples) {
    const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
    for (int y = 0; y < rgb.height(); ++y) {
      const QRgb* row = reinterpret_cast<const QRgb*>(rgb.constScanLine(y));
      for (int x = 0; x < rgb.width(); ++x) ++histogram[row[x] | 0xff000000u];
    }
  }
  Palette p;
  maxColours = std::clamp(maxColours, 1, 256);
  if (histogram.size() <= static_cast<size_t>(maxColours)) {
    for (const auto& [c, n] : histogram) p.colours_.push_back(c);
    std::sort(p.colours_.begin(), p.colours_.end());  // the same palette for the same frames
    if (p.colours_.empty()) p.colours_.push_back(qRgb(255, 255, 255));
    return p;
  }
  std::vector<Box> boxes(1);
  for (const auto& [c, n] : histogram) boxes[0].entries.push_back({c, n});
  std::sort(boxes[0].entries.begin(), boxes[0].entries.end(),
            [](const Entry& a, const Entry& b) { return a.colour < b.colour; });
  boxes[0].measure();
  while (static_cast<int>(boxes.size()) < maxColours) {
    auto it = std::max_element(boxes.begin(), boxes.end(), [](const Box& a, const Box& b) {
      return a.priority() < b.priority();
    });
    if (it->priority() < 0) break;  // every box is a single colour
    Box& box = *it;
    const int ch = box.widest;
    std::sort(box.entries.begin(), box.entries.end(), [ch](const Entry& a, const Entry& b) {
      return channel(a.colour, ch) < channel(b.colour, ch);
    });
    // The weighted median, keeping at least one entry on each side.
    std::uint64_t half = box.count / 2, sum = 0;
    size_t cut = 1;
    for (; cut < box.entries.size() - 1; ++cut) {
      sum += box.entries[cut - 1].count;
      if (sum >= half) break;
    }
    Box upper;
    upper.entries.assign(box.entries.begin() + cut, box.entries.end());
    box.entries.resize(cut);
    box.measure();
    upper.measure();
    boxes.push_back(std::move(upper));
  }
  for (const Box& b : boxes) p.colours_.push_back(b.mean());
  return p;
}

std::uint8_t Palette::index(QRgb c) {
  c |= 0xff000000u;
  auto it = cache_.find(c);
  if (it != cache_.end()) return it->second;
  int best = 0;
  long bestD = -1;
  for (size_t i = 0; i < colours_.size(); ++i) {
    const long dr = qRed(c) - qRed(colours_[i]), dg = qGreen(c) - qGreen(colours_[i]),
               db = qBlue(c) - qBlue(colours_[i]);
    const long d = dr * dr + dg * dg + db * db;
    if (bestD < 0 || d < bestD) bestD = d, best = static_cast<int>(i);
  }
  cache_.emplace(c, static_cast<std::uint8_t>(best));
  return static_cast<std::uint8_t>(best);
}

void Palette::map(const QImage& image, std::vector<std::uint8_t>& out) {
  out.resize(static_cast<size_t>(image.width()) * image.height());
  size_t k = 0;
  // Frames are mostly runs of one colour (background, link bodies): the last answer first.
  QRgb last = 0xff000000u;
  std::uint8_t lastIndex = index(last);
  for (int y = 0; y < image.height(); ++y) {
    const QRgb* row = reinterpret_cast<const QRgb*>(image.constScanLine(y));
    for (int x = 0; x < image.width(); ++x) {
      if ((row[x] | 0xff000000u) != last) {
        last = row[x] | 0xff000000u;
        lastIndex = index(last);
      }
      out[k++] = lastIndex;
    }
  }
}

}  // namespace linkage::ui
