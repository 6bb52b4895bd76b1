// Deterministic per-pixel sample streams: every value is a pure function of
// (seed, pixel index, sample index, dimension), so images do not depend on the
// thread count, the tiling or the order tiles run in.
//
// Each 2D dimension pair is an Owen-scrambled Sobol (0,2)-sequence, padded
// across dimensions by an independent per-dimension shuffle of the sample
// index (Burley 2020, "Practical Hash-based Owen Scrambling"). Any prefix of
// the samples of one pixel is well stratified in every pair.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/vec.h"

namespace lensrt {

// Dimension layout of a camera path: the camera consumes the first dimensions
// in this order, then each bounce takes kDimensionsPerBounce more.
enum SampleDimension : std::uint32_t {
  kDimFilm = 0,        // 2D: offset inside the pixel
  kDimLens = 1,        // 2D: aperture / exit pupil
  kDimWavelength = 2,  // 1D
  kDimFirstBounce = 3,
};
inline constexpr std::uint32_t kDimensionsPerBounce = 5;  // light pick, light 2D, lobe, BSDF 2D, roulette
// 2D: the camera ray's diffraction bend (--diffraction on). A stream of its
// own past any path's dimensions, so turning it on leaves the others as
// they were.
inline constexpr std::uint32_t kDimDiffraction = 0x00d1ff00u;

std::uint32_t hashCombine(std::uint32_t seed, std::uint32_t v);
std::uint32_t hash64(std::uint64_t v);

// The points of kDims consecutive dimensions of one sample, computed together:
// get2D(k) is the sampler's get2D(first + k), get1D(k) its get1D(first + k),
// bit for bit. A path vertex takes its kDimensionsPerBounce values from one
// block; on CPUs with AVX2 the dimensions are hashed in SIMD lanes.
class SampleBlock {
 public:
  static constexpr std::uint32_t kDims = 8;
  float get1D(std::uint32_t k) const { return x_[k]; }
  Vec2f get2D(std::uint32_t k) const { return {x_[k], y_[k]}; }

 private:
  friend class Sampler;
  std::array<float, kDims> x_{}, y_{};
};
static_assert(kDimensionsPerBounce <= SampleBlock::kDims && kDimFirstBounce <= SampleBlock::kDims);

// One dimension's seeds for the index shuffle and the x and y scrambles.
struct DimensionSeeds {
  std::uint32_t shuffle, x, y;
};

// What every sample of one pixel shares: the scramble seeds of its first
// dimensions, hashed once per pixel rather than once per sample and
// dimension (the same values; a Sampler made with them gives the same bits).
class PixelSeeds {
 public:
  PixelSeeds() = default;
  // Seeds for dimensions [0, dimensions); reuses this object's storage.
  void reset(std::uint64_t seed, std::uint64_t pixelIndex, std::uint32_t dimensions);
  std::uint32_t pixelSeed() const { return pixelSeed_; }
  std::uint32_t dimensions() const { return std::uint32_t(shuffle_.size()); }

 private:
  friend class Sampler;
  std::uint32_t pixelSeed_ = 0;
  // Per dimension: the seeds of the index shuffle, the x and the y scramble.
  std::vector<std::uint32_t> shuffle_, xSeed_, ySeed_;
};

class Sampler {
 public:
  Sampler(std::uint64_t seed, std::uint64_t pixelIndex, std::uint32_t sampleIndex);
  // A sample of the pixel `seeds` was made for (it must outlive the Sampler).
  Sampler(const PixelSeeds& seeds, std::uint32_t sampleIndex);

  // Values in [0, 1). A "dimension" is a stream id; 1D and 2D requests on the same
  // id return the first coordinate(s) of the same point.
  float get1D(std::uint32_t dimension) const;
  Vec2f get2D(std::uint32_t dimension) const;
  // Dimensions first .. first + SampleBlock::kDims - 1 at once.
  SampleBlock block(std::uint32_t first) const;
  // The scalar path of block(), whatever the CPU (for tests).
  SampleBlock blockScalar(std::uint32_t first) const;

 private:
  // A dimension's seeds for the index shuffle and the x and y scrambles
  // (hashed here unless the pixel's table has them).
  DimensionSeeds seeds(std::uint32_t dimension) const;

  std::uint32_t pixelSeed_;
  std::uint32_t reversedIndex_;  // the sample index, bit reversed
  const PixelSeeds* seeds_ = nullptr;
};

}  // namespace lensrt
