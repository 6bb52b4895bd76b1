// The ID AOVs of one pixel: which object (glTF node) and material each camera
// sample's first hit saw, counted, for Cryptomatte's ranked (id, coverage)
// pairs and the integer object_id channel.
//
// Coverage of an id = the pixel's samples whose first hit has it / the
// samples counted (those whose camera ray reached the scene straight through
// the lens; the lens-blocked and flare's lens-reflected ones are left out as
// for alpha). The background (no hit) is an entry of its own, id 0.0, so the
// coverages of a pixel sum to 1 whenever it has at most kCryptoRanks ids.
// Ranks are by count, ties by the id's bits, so the layout is deterministic.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"

namespace lensrt {

struct SceneDesc;
struct AovSelection;

// The names the ID AOVs hash: a glTF node's name ("node<i>" when it has
// none), a material's ("material<i>" when it has none, "default" for glTF's
// default material).
std::string materialIdName(const SceneDesc& desc, int material);

// Per instance and per material, the ids a sample records.
struct SceneIds {
  explicit SceneIds(const SceneDesc& desc);
  std::vector<std::uint32_t> instanceBits;  // Cryptomatte id of the instance's node
  std::vector<std::int32_t> instanceNode;
  std::vector<std::uint32_t> materialBits;  // [material + 1]: the default material first
};

// The Cryptomatte header attributes of the layers asked for:
// cryptomatte/<key>/{name,hash,conversion,manifest}, key = the first 7 hex
// digits of the layer name's hash; the manifest maps every name to its id's
// bits as 8 hex digits (JSON).
ImageMetadata cryptomatteMetadata(const SceneDesc& desc, const AovSelection& aovs);

// Ranks written per Cryptomatte layer: 3 RGBA channel sets of 2 pairs, the
// specification's (and Blender's) default depth.
constexpr int kCryptoRanks = 6;

struct IdCount {
  std::uint32_t idBits = 0;  // the float32 id's bits, 0 for the background
  std::int32_t index = -1;   // glTF node index (objects) or material index; -1 background
  std::uint32_t count = 0;
};

class IdCoverage {
 public:
  void add(std::uint32_t objectBits, std::int32_t node, std::uint32_t materialBits, std::int32_t material);
  // The kCryptoRanks most covered ids, as id, coverage, id, coverage, ...
  // (2 * kCryptoRanks floats, zero-filled).
  void writeRanks(bool material, float* out) const;
  // The node index of the most covered entry (-1 for the background or no sample).
  std::int32_t topNode() const;

 private:
  static void bump(std::vector<IdCount>& list, std::uint32_t bits, std::int32_t index);
  static std::vector<IdCount> ranked(const std::vector<IdCount>& list);
  std::vector<IdCount> objects_, materials_;
  std::uint32_t samples_ = 0;
};

}  // namespace lensrt
