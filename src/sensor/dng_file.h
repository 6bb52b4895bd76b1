// Raw files a photographer can develop: a CFA mosaic as a 16-bit linear DNG
// (Adobe DNG 1.4) through libtiff, with the tags raw developers need.
#pragma once

#include <array>
#include <filesystem>
#include <string>

#include "core/vec.h"
#include "sensor/camera_rgb.h"
#include "sensor/mosaic.h"

namespace lensrt {

struct DngDescription {
  CfaPattern pattern;
  std::string make = "lensrt", model;    // the camera; UniqueCameraModel is "make model"
  std::array<double, 9> colorMatrix1{};  // XYZ -> camera RGB under calibrationIlluminant1, row-major
  int calibrationIlluminant1 = 21;       // EXIF LightSource: 21 is D65
  std::array<double, 3> asShotNeutral{1.0, 1.0, 1.0};  // camera RGB of the white to balance to
  double exposureSeconds = 0.0, iso = 0.0, fNumber = 0.0, focalLengthMm = 0.0;  // 0: not written
  std::string lensModel;             // EXIF LensModel; empty: not written
  int focalLengthIn35mmFilm = 0;     // the focal length giving the same field over 36x24's diagonal
  double focalPlanePixelsPerCm = 0;  // EXIF FocalPlaneX/YResolution (unit: cm); 0: not written
  std::string dateTimeOriginal;      // "YYYY:MM:DD HH:MM:SS"; empty: not written
};

// The linear sRGB (Rec.709 primaries) camera lensrt's RGB film is: XYZ to linear
// sRGB, D65 white (IEC 61966-2-1).
inline constexpr std::array<double, 9> kXyzToLinearSrgb{
    3.2404542, -1.5371385, -0.4985314, -0.9692660, 1.8760108, 0.0415560, 0.0556434, -0.2040259, 1.0572252};

// ColorMatrix1 and AsShotNeutral of a mosaic of `camera`'s RGB whose
// channels a readout scaled by `channelGains` (each channel's electrons per
// camera value, CameraRgb::relativeElectrons with physical exposure). A raw
// developer balances and converts the values the file holds, so the matrix's
// rows and the neutral carry the same gains, relative to green's (the
// neutral's green stays 1); without them a photon-counted mosaic develops
// with the channels' electron ratios as a colour cast.
void describeCameraColour(DngDescription& description, const CameraRgb& camera, const Vec3d& channelGains);

// Writes `mosaic` as a DNG; throws InputError(file, ...) when it cannot.
void writeDng(const std::filesystem::path& file, const Mosaic& mosaic, const DngDescription& description);

}  // namespace lensrt
