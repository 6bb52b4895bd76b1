// When an image was "taken", as EXR's capDate and the DNG's DateTimeOriginal
// hold it: "YYYY:MM:DD HH:MM:SS".
#pragma once

#include <string>

namespace lensrt {

// Local time now; where SOURCE_DATE_EPOCH is set (reproducible files, as
// reproducible builds date theirs), that instant in UTC.
std::string captureDate();

}  // namespace lensrt
