// Readers for lens prescription files, and the lens library lookup.
//
// Design notes: docs/design/lens-readers.md.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "optics/prescription.h"

namespace lensrt {

// Parse text already in memory; `file` names it in messages (and its stem
// becomes the lens name when the text does not give one).
LensPrescription parsePbrtLens(std::string_view text, const std::string& file);
LensPrescription parseTableLens(std::string_view text, const std::string& file);
LensPrescription parseJsonLens(std::string_view text, const std::string& file);
// Takes the file's bytes (UTF-16 is decoded here).
LensPrescription parseZemaxLens(std::string_view bytes, const std::string& file);

// Read and validate a lens file, choosing the reader by extension.
LensPrescription loadLens(const std::filesystem::path& path);

// A path to an existing file, or a library name ("dgauss-50mm") looked up as
// lensDir/name.{lens,json,dat,zmx}. Throws InputError listing the library when
// neither exists.
std::filesystem::path findLens(const std::string& nameOrPath, const std::filesystem::path& lensDir);

// Library lens files in lensDir, sorted by name.
std::vector<std::filesystem::path> listLenses(const std::filesystem::path& lensDir);

}  // namespace lensrt
