// Text outputs (reports, SVG, CSV) written so that a reader never sees half a
// file and a failed write leaves the previous file untouched.
#pragma once

#include <filesystem>
#include <string>

namespace lensrt {

// Writes `contents` to a uniquely named temporary beside `file` and renames it
// over `file`. InputError(file, "cannot write: ...") on failure, the
// temporary removed.
void writeTextFileAtomically(const std::filesystem::path& file, const std::string& contents);

// The same, or standard output when `output` is "-".
void writeTextOutput(const std::string& output, const std::string& contents);

}  // namespace lensrt
