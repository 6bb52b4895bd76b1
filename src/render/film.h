// Per-pixel accumulation and the output channel layout.
//
// Design notes: docs/design/film.md.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/vec.h"
#include "render/integrator.h"

namespace lensrt {

struct AovSelection {
  bool depth = false;  // depth.Z: from the camera node's origin to the first hit
  bool normal = false;
  bool albedo = false;
  bool variance = false;
  bool spp = false;
  // Z: the first hit's depth along the camera's viewing axis (last of the
  // flags, so aggregate initialisations of the others keep their meaning).
  bool z = false;
  // ID AOVs (render/id_coverage.h), written after the others:
  bool cryptoObject = false;    // CryptoObject00.RGBA..02.RGBA: glTF node names
  bool cryptoMaterial = false;  // CryptoMaterial00.RGBA..02.RGBA: material names
  bool objectId = false;        // object_id: the most covered node index, -1 background
  // flow.forward.X/Y, flow.backward.X/Y: image motion in pixels (render/motion_flow.h), last.
  bool flow = false;
  bool ids() const { return cryptoObject || cryptoMaterial || objectId; }
  // Coordinate AOVs (CoordinateSums), written after the ID AOVs: the first
  // hit's world point (position.X/Y/Z), TEXCOORD_0 (uv.U/V) and point in its
  // mesh's own frame (object_coords.X/Y/Z), means over the samples that hit.
  bool position = false;
  bool uv = false;
  bool objectCoords = false;
  bool coords() const { return position || uv || objectCoords; }
  // The AOVs whose sums are not in the running sums (the ID AOVs' id counts,
  // flow's sums): a checkpoint could not continue them, nor ranks send them.
  // Their --aov names, e.g. "object_id, flow"; empty: none.
  std::string unsavedAovs() const;
};

// The Cryptomatte layers' names, as in the channels and the manifest.
inline constexpr const char* kCryptoObjectLayer = "CryptoObject";
inline constexpr const char* kCryptoMaterialLayer = "CryptoMaterial";

std::vector<std::string> filmChannels(const AovSelection& aovs);

class PixelAccumulator {
 public:
  // `weight` is the camera ray's weight; a blocked camera ray adds a zero
  // sample. `lensReflected`: the ray was reflected in the lens (flare).
  // Returns false when the sample was dropped (radiance not finite).
  bool add(const PathSample& s, float weight, bool lensReflected = false);
  void addBlocked();
  std::uint64_t droppedSamples() const { return dropped_; }
  // Every sample added, dropped ones included: the index of the next one.
  std::uint64_t samplesTaken() const { return count_ + dropped_; }
  // Per channel, the mean so far and the standard error of that mean (the
  // square root of the variance AOV's value); errors are 0 below 2 samples.
  struct MeanAndError {
    double mean[3] = {0, 0, 0};
    double standardError[3] = {0, 0, 0};
  };
  MeanAndError meanAndError() const;
  // Writes this pixel's channels (layout of filmChannels) to `out`.
  void write(const AovSelection& aovs, float* out) const;

  // The running sums as bytes (native byte order), so a checkpoint can
  // continue them exactly: doubles stay doubles, nothing is rounded.
  static constexpr std::size_t kStateBytes = 17 * 8 + 3 * 4;
  void saveState(std::byte* out) const;
  void loadState(const std::byte* in);

 private:
  double sum_[3] = {0, 0, 0};
  double sumSq_[3] = {0, 0, 0};
  std::uint64_t count_ = 0;
  std::uint64_t hits_ = 0;
  // A: samples that reached the scene (reached_, straight or reflected in the
  // lens; hits_ of them hit), those that came straight (seen_), and those of
  // them that hit (covered_).
  std::uint64_t reached_ = 0, seen_ = 0, covered_ = 0;
  std::uint64_t dropped_ = 0;
  double distance_ = 0;
  double planarZ_ = 0;
  Vec3f normal_{0, 0, 0};
  double albedo_[3] = {0, 0, 0};
};

// A pixel's sums for the coordinate AOVs, kept apart from PixelAccumulator so
// that renders without them keep no more per pixel. Counts the same samples
// as depth.Z: those PixelAccumulator::add took that hit something.
class CoordinateSums {
 public:
  void add(const PathSample& s);
  // Writes the selected coordinate channels (filmChannels' order) to `out`.
  void write(const AovSelection& aovs, float* out) const;
  static constexpr std::size_t kStateBytes = 8 + 8 * 8;
  void saveState(std::byte* out) const;
  void loadState(const std::byte* in);

 private:
  std::uint64_t hits_ = 0;
  double position_[3] = {0, 0, 0};
  double uv_[2] = {0, 0};
  double object_[3] = {0, 0, 0};
};

}  // namespace lensrt
