#include "image/image_merge.h"

#include <stdexcept>
#include <vector>

namespace lensrt {
namespace {

std::string frameOf(const Image& im) {
  return std::to_string(im.fullWidth()) + "x" + std::to_string(im.fullHeight());
}

std::string placeOf(const Image& im) {
  return "x " + std::to_string(im.originX) + ".." + std::to_string(im.originX + im.width) + ", y " +
         std::to_string(im.originY) + ".." + std::to_string(im.originY + im.height);
}

}  // namespace

Image mergeImageParts(std::span<const Image> parts, std::span<const std::string> names) {
  if (parts.empty()) throw std::invalid_argument("no parts to merge");
  if (names.size() != parts.size()) throw std::invalid_argument("one name per part is needed");
  const Image& first = parts[0];
  const int W = first.fullWidth(), H = first.fullHeight();
  Image out(W, H, first.channels);
  // Which part covers each pixel (-1: none yet).
  std::vector<int> owner(std::size_t(W) * std::size_t(H), -1);
  for (std::size_t p = 0; p < parts.size(); ++p) {
    const Image& part = parts[p];
    if (part.fullWidth() != W || part.fullHeight() != H)
      throw std::invalid_argument(names[p] + " is part of a " + frameOf(part) + " frame, " + names[0] +
                                  " of a " + frameOf(first) + " frame");
    std::vector<int> source(out.channelCount());
    for (std::size_t c = 0; c < out.channelCount(); ++c) {
      source[c] = part.channelIndex(out.channels[c]);
      if (source[c] < 0)
        throw std::invalid_argument(names[p] + " has no channel " + out.channels[c] + " (" + names[0] +
                                    " has)");
    }
    if (part.channelCount() != out.channelCount())
      throw std::invalid_argument(names[p] + " has " + std::to_string(part.channelCount()) + " channels, " +
                                  names[0] + " " + std::to_string(out.channelCount()));
    if (part.originX < 0 || part.originY < 0 || part.originX + part.width > W ||
        part.originY + part.height > H)
      throw std::invalid_argument(names[p] + "'s pixels (" + placeOf(part) + ") lie outside its " +
                                  frameOf(part) + " frame");
    for (int y = 0; y < part.height; ++y)
      for (int x = 0; x < part.width; ++x) {
        const int fx = part.originX + x, fy = part.originY + y;
        int& o = owner[std::size_t(fy) * std::size_t(W) + std::size_t(fx)];
        if (o >= 0)
          throw std::invalid_argument(names[std::size_t(o)] + " and " + names[p] +
                                      " overlap (both have pixel " + std::to_string(fx) + "," +
                                      std::to_string(fy) + ")");
        o = int(p);
        for (std::size_t c = 0; c < out.channelCount(); ++c)
          out.at(fx, fy, int(c)) = part.at(x, y, source[c]);
      }
  }
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      if (owner[std::size_t(y) * std::size_t(W) + std::size_t(x)] < 0) {
        // Name the whole missing run of that row, which is what a reader looks for.
        int end = x;
        while (end < W && owner[std::size_t(y) * std::size_t(W) + std::size_t(end)] < 0) ++end;
        throw std::invalid_argument("the parts leave a gap: no part has row " + std::to_string(y) + ", x " +
                                    std::to_string(x) + ".." + std::to_string(end) + " of the " +
                                    frameOf(first) + " frame");
      }
  return out;
}

}  // namespace lensrt
