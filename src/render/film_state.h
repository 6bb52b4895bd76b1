// The running per-pixel sums of a render in progress over a region of the
// frame, with the samples per pixel done so far. Passes of samples add to
// it in sample order, so a render cut into passes (or stopped, saved and
// resumed) sums exactly what an uninterrupted one sums: the same bits.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "image/image.h"
#include "render/film.h"
#include "render/id_coverage.h"
#include "render/motion_flow.h"
#include "render/pixel_region.h"

namespace lensrt {

class FilmState {
 public:
  FilmState(const PixelRegion& region, const AovSelection& aovs);

  const PixelRegion& region() const { return region_; }
  const AovSelection& aovs() const { return aovs_; }
  int samplesDone() const { return samplesDone_; }
  void setSamplesDone(int spp) { samplesDone_ = spp; }
  // Frame coordinates, inside region().
  PixelAccumulator& pixel(int x, int y) {
    return pixels_[std::size_t(y - region_.y0) * std::size_t(region_.width()) + std::size_t(x - region_.x0)];
  }

  // The pixel's ID AOV counts; only when aovs().ids().
  IdCoverage& ids(int x, int y) {
    return ids_[std::size_t(y - region_.y0) * std::size_t(region_.width()) + std::size_t(x - region_.x0)];
  }

  // The pixel's flow sums; only when aovs().flow.
  FlowSums& flow(int x, int y) {
    return flow_[std::size_t(y - region_.y0) * std::size_t(region_.width()) + std::size_t(x - region_.x0)];
  }
  // The pixel's coordinate AOV sums; only when aovs().coords().
  CoordinateSums& coords(int x, int y) {
    return coords_[std::size_t(y - region_.y0) * std::size_t(region_.width()) + std::size_t(x - region_.x0)];
  }

  std::uint64_t droppedSamples() const;
  // The camera samples of every pixel: region pixels x samplesDone(), or
  // fewer when adaptive sampling stopped pixels early.
  std::uint64_t samplesTaken() const;
  std::uint64_t blockedCameraRays = 0;

  // The means so far: channels per filmChannels(aovs), the region's size,
  // placed in a frame of frameWidth x frameHeight.
  Image image(int frameWidth, int frameHeight) const;

  // A self-describing byte image of the state (a header with the region,
  // AOVs and samples done, then every pixel's sums); fromBytes throws
  // std::invalid_argument with a one-line reason for anything malformed.
  // toBytes throws std::invalid_argument with the ID AOVs or flow (their
  // sums are not saved yet).
  std::vector<std::byte> toBytes() const;
  static FilmState fromBytes(std::span<const std::byte> bytes);

 private:
  PixelRegion region_;
  AovSelection aovs_;
  int samplesDone_ = 0;
  std::vector<PixelAccumulator> pixels_;
  std::vector<IdCoverage> ids_;
  std::vector<FlowSums> flow_;
  std::vector<CoordinateSums> coords_;
};

}  // namespace lensrt
