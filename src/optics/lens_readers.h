// Readers for lens prescription files, and the lens library lookup.
//
// Formats (chosen by extension):
//  .dat   pbrt's format: 4 columns per surface: radius, thickness to the next
//         surface, index n_d of the medium after it (0 or 1 = air), aperture
//         DIAMETER; radius 0 marks the stop. '#' starts a comment.
//  .lens  the seed lecture's table: 5 columns radius, thickness, n_d, V_d,
//         aperture diameter; a 3-number row is radius, thickness, aperture in
//         air; radius 0 or the word "stop" (also "(stop)") marks the stop. A
//         first row starting with "radius" is a column header. '#' comments;
//         "# name:", "# description:", "# source:", "# focal-length-mm:" header
//         comments fill the metadata.
//  .json  ours, see lenses/README.md:
//         {"format": "lensrt-lens", "version": 1, "name": ..., "description": ...,
//          "source": ..., "focal_length_mm": ...,
//          "surfaces": [{"radius": r, "thickness": t, "aperture": d,
//                        "nd": n, "vd": v, "glass": "SK16", "stop": true}, ...]}
//         nd/vd/glass describe the medium after the surface (absent = air).
//  .zmx   Zemax OpticStudio sequential files, UTF-16 (BOM) or ASCII: SURF
//         blocks of TYPE STANDARD or EVENASPH with CURV, DISZ, CONI, PARM
//         (EVENASPH: PARM 1 = r^2 term, must be 0; PARM 2..8 = A4..A16), DIAM
//         (semi-diameter), STOP, GLAS (built-in catalogue name or ___BLANK
//         model glass with n_d, V_d); UNIT MM|CM|IN|METER scales to mm. The
//         object (SURF 0) and image (last SURF) surfaces are not lens surfaces;
//         flat surfaces that change nothing are dropped; a stop on a refracting
//         surface becomes a flat stop at its vertex plane. Other keywords are
//         skipped; coordinate breaks, mirrors, gradient index, non-sequential
//         files and other surface types are refused naming the SURF.
// All files may be UTF-8 with a BOM, CRLF line ends and no final newline.
// Errors throw InputError(file, message, line) naming the problem.
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
