// --aperture-mask FILE: a grey-scale image (PNG, or another format the glTF
// textures' decoder reads: JPEG, BMP, TGA) turned into the ApertureMask the
// full lens applies at its stop.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "camera/aperture_mask.h"

namespace lensrt {

// Grey is the mean of R, G and B (a grey image has them equal); the stored
// value (0 black .. 1 white, no sRGB decoding) is the transmittance; alpha
// is ignored. Throws InputError(file, reason) when the file is missing or
// cannot be decoded, is larger than 4096 x 4096, or is black over the
// whole stop.
ApertureMask readApertureMask(const std::filesystem::path& file);

// The same from the file's bytes; `name` names it in errors (and its file
// name part in the mask's description).
ApertureMask decodeApertureMask(std::string_view bytes, const std::string& name);

}  // namespace lensrt
