// The response file: a camera's (or any sensor's) spectral sensitivities as
// CSV text, rows of `wavelength_nm,r,g,b` at any spacing in 300-1100 nm with
// strictly increasing wavelengths and values from 0 to 1e9, at least 3 rows.
// An optional header line (no numbers in it), blank lines and `#` comments;
// the comments `# maker: ...`, `# model: ...` and `# source: ...` describe
// the camera:
//
//   # maker: Nikon
//   # model: D850
//   wavelength_nm,r,g,b
//   380,0.0013,0.0012,0.0020
//   390,0.0017,0.0009,0.0035
//   ...
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "sensor/sensor_response.h"

namespace lensrt {

// Parses the text of a response file (`file` names it in errors and becomes
// the response's name). Throws InputError(file, problem, line) at the first
// problem: a wrong column count, a field that is not a number, NaN, infinity,
// a negative value or one above 1e9, a wavelength outside 300-1100 nm or not
// above the row before, fewer than 3 rows, or a channel that is 0 at every
// wavelength.
SensorResponse parseResponseCsv(std::string_view text, const std::string& file);

// Reads and parses a response file of at most 1 MiB. Throws InputError.
SensorResponse readResponseCsv(const std::filesystem::path& file);

}  // namespace lensrt
