// What makes two images parts (tiles, crops, checkpoints) of the same render:
// the metadata under these keys is equal. The command line fills them in
// (scene digest, camera, settings, seed); merge and resume compare them.
#pragma once

#include <array>
#include <string>

#include "image/image.h"

namespace lensrt {

// lensrt:scene_sha256  SHA-256 of the scene file(s) and environment map
// lensrt:camera        the camera's description (model, lens, focus, aperture, ...)
// lensrt:settings      every other setting that changes the image (size, depth, environment, AOVs)
// lensrt:seed          the random seed
inline constexpr std::array<const char*, 4> kRenderIdentityKeys{"lensrt:scene_sha256", "lensrt:camera",
                                                                "lensrt:settings", "lensrt:seed"};

// "" when `a` and `b` agree on every identity key, else one phrase saying
// what differs, e.g. "the seed differs (3 against 4)"; a missing key says
// "has no lensrt:seed (not a lensrt render?)".
std::string renderIdentityDifference(const ImageMetadata& a, const ImageMetadata& b);

}  // namespace lensrt
