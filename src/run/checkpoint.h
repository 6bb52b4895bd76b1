// Checkpoints of a render in progress: the image so far (an ordinary EXR whose
// lensrt:spp is the samples done, with the render's identity in its metadata)
// and, beside it in IMAGE.sums, the exact running sums (render/film_state.h)
// needed to continue it bit for bit. The sums file is written first and the
// image names its SHA-256, so an image and a sums file that do not belong
// together (a crash between the two writes) are refused, never mixed.
#pragma once

#include <filesystem>

#include "image/image.h"
#include "image/image_io.h"
#include "render/film_state.h"

namespace lensrt {

std::filesystem::path checkpointSumsFile(const std::filesystem::path& image);

// Writes IMAGE.sums then IMAGE (with `options`, as the finished image would
// be), each atomically. Throws InputError.
void writeCheckpoint(const std::filesystem::path& image, const FilmState& state, const Image& pixels,
                     ImageMetadata metadata, const ImageWriteOptions& options = {});

// The state saved in a checkpoint of the render `identity` describes, over
// `region`. Throws InputError naming the file and what differs when it is
// another render's (scene, camera, settings, seed, region) or is damaged.
FilmState readCheckpoint(const std::filesystem::path& image, const ImageMetadata& identity,
                         const PixelRegion& region);

}  // namespace lensrt
