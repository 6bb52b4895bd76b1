#include "run/checkpoint.h"

#include <fstream>
#include <span>
#include <stdexcept>
#include <string>

#include "api/output_file.h"
#include "api/scene_digest.h"
#include "api/text_file.h"
#include "core/error.h"
#include "image/image_io.h"
#include "render/render_identity.h"

namespace lensrt {

namespace fs = std::filesystem;

fs::path checkpointSumsFile(const fs::path& image) {
  return fs::path(image.string() + ".sums");
}

void writeCheckpoint(const fs::path& image, const FilmState& state, const Image& pixels,
                     ImageMetadata metadata, const ImageWriteOptions& options) {
  const std::vector<std::byte> bytes = state.toBytes();
  const std::string_view view(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  metadata["lensrt:sums_sha256"] = sha256Hex(view);
  writeTextFileAtomically(checkpointSumsFile(image), std::string(view));
  writeOutputImage(image, pixels, metadata, options);
}

FilmState readCheckpoint(const fs::path& image, const ImageMetadata& identity, const PixelRegion& region) {
  ImageMetadata meta;
  readImage(image, &meta);
  const std::string file = image.string();
  // Not a checkpoint at all says more than which of its settings differ.
  const auto digest = meta.find("lensrt:sums_sha256");
  if (digest == meta.end())
    throw InputError(
        file, "has no running sums to resume from (render with --checkpoint to make a resumable image)");
  if (const std::string diff = renderIdentityDifference(meta, identity); !diff.empty())
    throw InputError(file, "cannot resume another render: " + diff);
  const fs::path sums = checkpointSumsFile(image);
  std::ifstream in(sums, std::ios::binary);
  if (!in) throw InputError(sums.string(), "cannot read the checkpoint's running sums");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (sha256Hex(bytes) != digest->second)
    throw InputError(sums.string(), "does not belong to " + file + " (its SHA-256 differs from the one " +
                                        file + " records)");
  try {
    FilmState state =
        FilmState::fromBytes(std::span(reinterpret_cast<const std::byte*>(bytes.data()), bytes.size()));
    if (!(state.region() == region))
      throw InputError(file, "cannot resume another render: the checkpoint covers pixels " +
                                 state.region().describe() + ", this render " + region.describe());
    return state;
  } catch (const std::invalid_argument& e) {
    throw InputError(sums.string(), e.what());
  }
}

}  // namespace lensrt
