// The image a command writes (-o): checked before any work is done, and
// written with errors that name that file rather than the temporary one the
// image layer writes first.
#pragma once

#include <fmt/core.h>

#include <filesystem>
#include <optional>

#include "image/image.h"
#include "image/image_io.h"

namespace lensrt {

// Creates the folder that will hold `file` and its missing parents (every
// command that writes does: -o parts/3.exr makes parts/). Returns that folder
// when it had to be made, so the command can say so once; nullopt when it
// was there. Throws InputError(file, why) when it cannot be made.
std::optional<std::filesystem::path> createFolderFor(const std::filesystem::path& file);

// Creates the output's folder (createFolderFor, returned), then throws
// UsageError (exit 2) for a name that is no image file, and
// InputError (exit 1) when the file cannot be created there: the directory is
// missing, not a directory, not writable (checked by creating and removing a
// probe file, so read-only mounts, /proc and /sys are caught even for root),
// or its disk is full.
std::optional<std::filesystem::path> checkOutputFile(const std::filesystem::path& out);

// One line on stderr when a command made the folder its output goes to.
inline void noteCreatedFolder(const std::optional<std::filesystem::path>& folder, bool quiet) {
  if (folder && !quiet) fmt::print(stderr, "lensrt: created folder {}\n", folder->string());
}

// writeImage, with a failure reported against `out` (a full disk as such).
void writeOutputImage(const std::filesystem::path& out, const Image& image, const ImageMetadata& metadata,
                      const ImageWriteOptions& options = {});

}  // namespace lensrt
