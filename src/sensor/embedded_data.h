// The measured spectra of the repository's data/ folder, compiled into the
// binary at build time (embed_text_files.cmake writes embedded_data.cpp), so
// that an installed lensrt reads no data files.
#pragma once

#include <span>
#include <string_view>

namespace lensrt {

struct EmbeddedFile {
  std::string_view name;  // the file name without its extension
  std::string_view text;  // the file's bytes
};

// data/sensor-responses/*.csv, sorted by name.
std::span<const EmbeddedFile> embeddedSensorResponses();
// data/colorchecker.csv.
std::string_view embeddedColorChecker();

}  // namespace lensrt
