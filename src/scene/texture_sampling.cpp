#include "scene/texture_sampling.h"

#include <cmath>

namespace lensrt {
namespace {

// Maps an integer texel coordinate (possibly outside [0, size)) into the image.
int wrapIndex(int i, int size, bool repeat, bool mirror) {
  if (!repeat) return i < 0 ? 0 : (i >= size ? size - 1 : i);
  if (!mirror) {
    const int m = i % size;
    return m < 0 ? m + size : m;
  }
  const int period = 2 * size;
  int m = i % period;
  if (m < 0) m += period;
  return m < size ? m : period - 1 - m;
}

Vec4f lerp(const Vec4f& a, const Vec4f& b, float t) {
  return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t, a.w + (b.w - a.w) * t};
}

}  // namespace

Vec4f sampleTexture(const Texture& tex, Vec2f uv) {
  if (tex.width <= 0 || tex.height <= 0 ||
      tex.texels.size() < static_cast<std::size_t>(tex.width) * static_cast<std::size_t>(tex.height))
    return {1, 1, 1, 1};
  // Non-finite uvs would turn into undefined integer conversions below.
  const float u = std::isfinite(uv.x) ? uv.x : 0.0f;
  const float v = std::isfinite(uv.y) ? uv.y : 0.0f;
  // Reduce huge coordinates first so float-to-int conversion stays in range.
  const auto reduce = [](float c, bool repeat, bool mirror) {
    if (!repeat) return std::fmin(std::fmax(c, -1.0f), 2.0f);
    const float period = mirror ? 2.0f : 1.0f;
    return c - period * std::floor(c / period);
  };
  const float x = reduce(u, tex.wrapRepeatS, tex.mirrorS) * static_cast<float>(tex.width);
  const float y = reduce(v, tex.wrapRepeatT, tex.mirrorT) * static_cast<float>(tex.height);
  const auto texel = [&](int i, int j) {
    i = wrapIndex(i, tex.width, tex.wrapRepeatS, tex.mirrorS);
    j = wrapIndex(j, tex.height, tex.wrapRepeatT, tex.mirrorT);
    return tex.texels[static_cast<std::size_t>(j) * static_cast<std::size_t>(tex.width) +
                      static_cast<std::size_t>(i)];
  };
  if (tex.nearest) return texel(static_cast<int>(std::floor(x)), static_cast<int>(std::floor(y)));
  const float fx = x - 0.5f, fy = y - 0.5f;
  const int i0 = static_cast<int>(std::floor(fx)), j0 = static_cast<int>(std::floor(fy));
  const float tx = fx - static_cast<float>(i0), ty = fy - static_cast<float>(j0);
  return lerp(lerp(texel(i0, j0), texel(i0 + 1, j0), tx), lerp(texel(i0, j0 + 1), texel(i0 + 1, j0 + 1), tx),
              ty);
}

}  // namespace lensrt
