#include "sensor/dng_file.h"

#include <fmt/core.h>
#include <tiffio.h>

#include <memory>
#include <mutex>
#include <string>

#include "core/error.h"
#include "image/image_io.h"

namespace lensrt {
namespace {

struct TiffCloser {
  void operator()(TIFF* tiff) const { TIFFClose(tiff); }
};

// libtiff reports through process-wide handlers: its messages are collected
// for the one error line instead of printed.
thread_local std::string tiffMessage;
void collect(const char* module, const char* format, va_list args) {
  char buffer[512];
  std::vsnprintf(buffer, sizeof buffer, format, args);
  tiffMessage = module ? std::string(module) + ": " + buffer : std::string(buffer);
}

void writeTiff(const std::filesystem::path& path, const std::filesystem::path& file, const Mosaic& m,
               const DngDescription& d) {
  static std::once_flag handlers;
  std::call_once(handlers, [] {
    TIFFSetErrorHandler(collect);
    TIFFSetWarningHandler(nullptr);
  });
  tiffMessage.clear();
  const std::unique_ptr<TIFF, TiffCloser> tiff(TIFFOpen(path.c_str(), "w"));
  const auto fail = [&](const std::string& what) {
    throw InputError(file.string(),
                     "cannot write the DNG: " + what + (tiffMessage.empty() ? "" : " (" + tiffMessage + ")"));
  };
  if (!tiff) fail("cannot open");
  TIFF* t = tiff.get();
  // The EXIF directory first (exposure time, ISO, f-number, focal length),
  // then IFD 0 pointing to it: libtiff writes a custom directory where the
  // file ends, and IFD 0 after it links itself from the header.
  std::uint64_t exifOffset = 0;
  if (TIFFCreateEXIFDirectory(t) != 0) fail("cannot create the EXIF directory");
  bool exifOk = true;
  // Varargs pass floats as doubles: libtiff reads rationals so.
  if (d.exposureSeconds > 0) exifOk = exifOk && TIFFSetField(t, EXIFTAG_EXPOSURETIME, d.exposureSeconds);
  if (d.fNumber > 0) exifOk = exifOk && TIFFSetField(t, EXIFTAG_FNUMBER, d.fNumber);
  if (d.focalLengthMm > 0) exifOk = exifOk && TIFFSetField(t, EXIFTAG_FOCALLENGTH, d.focalLengthMm);
  if (d.iso > 0) {
    const std::uint16_t iso = std::uint16_t(std::min(d.iso, 65535.0));
    exifOk = exifOk && TIFFSetField(t, EXIFTAG_ISOSPEEDRATINGS, 1, &iso);
  }
  if (!d.lensModel.empty()) exifOk = exifOk && TIFFSetField(t, EXIFTAG_LENSMODEL, d.lensModel.c_str());
  if (d.focalLengthIn35mmFilm > 0) {
    const std::uint16_t f35 = std::uint16_t(std::min(d.focalLengthIn35mmFilm, 65535));
    exifOk = exifOk && TIFFSetField(t, EXIFTAG_FOCALLENGTHIN35MMFILM, f35);
  }
  if (d.focalPlanePixelsPerCm > 0) {
    const std::uint16_t centimetres = 3;  // EXIF FocalPlaneResolutionUnit
    exifOk = exifOk && TIFFSetField(t, EXIFTAG_FOCALPLANEXRESOLUTION, d.focalPlanePixelsPerCm) &&
             TIFFSetField(t, EXIFTAG_FOCALPLANEYRESOLUTION, d.focalPlanePixelsPerCm) &&
             TIFFSetField(t, EXIFTAG_FOCALPLANERESOLUTIONUNIT, centimetres);
  }
  if (!d.dateTimeOriginal.empty())
    exifOk = exifOk && TIFFSetField(t, EXIFTAG_DATETIMEORIGINAL, d.dateTimeOriginal.c_str());
  if (!exifOk || !TIFFWriteCustomDirectory(t, &exifOffset)) fail("writing the EXIF directory");
  TIFFFreeDirectory(t);
  if (TIFFCreateDirectory(t) != 0) fail("cannot start the image directory");
  const std::uint8_t dngVersion[4] = {1, 4, 0, 0}, backward[4] = {1, 1, 0, 0};
  const std::uint16_t cfaDims[2] = {2, 2};
  std::uint8_t cfa[4];
  for (int i = 0; i < 4; ++i) cfa[i] = std::uint8_t(d.pattern.colours[std::size_t(i)]);
  const std::string unique = d.make + " " + d.model;
  float colorMatrix[9], neutral[3];
  for (int i = 0; i < 9; ++i) colorMatrix[i] = float(d.colorMatrix1[std::size_t(i)]);
  for (int i = 0; i < 3; ++i) neutral[i] = float(d.asShotNeutral[std::size_t(i)]);
  const float black = float(m.blackLevel);
  const std::uint32_t white = std::uint32_t(m.whiteLevel);
  bool ok =
      TIFFSetField(t, TIFFTAG_SUBFILETYPE, 0) &&
      TIFFSetField(t, TIFFTAG_IMAGEWIDTH, std::uint32_t(m.width)) &&
      TIFFSetField(t, TIFFTAG_IMAGELENGTH, std::uint32_t(m.height)) &&
      TIFFSetField(t, TIFFTAG_BITSPERSAMPLE, 16) && TIFFSetField(t, TIFFTAG_SAMPLESPERPIXEL, 1) &&
      TIFFSetField(t, TIFFTAG_COMPRESSION, COMPRESSION_NONE) &&
      TIFFSetField(t, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_CFA) &&
      TIFFSetField(t, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG) &&
      TIFFSetField(t, TIFFTAG_ORIENTATION, ORIENTATION_TOPLEFT) &&
      TIFFSetField(t, TIFFTAG_ROWSPERSTRIP, std::uint32_t(m.height)) &&
      TIFFSetField(t, TIFFTAG_MAKE, d.make.c_str()) && TIFFSetField(t, TIFFTAG_MODEL, d.model.c_str()) &&
      TIFFSetField(t, TIFFTAG_SOFTWARE, "lensrt") && TIFFSetField(t, TIFFTAG_DNGVERSION, dngVersion) &&
      TIFFSetField(t, TIFFTAG_DNGBACKWARDVERSION, backward) &&
      TIFFSetField(t, TIFFTAG_UNIQUECAMERAMODEL, unique.c_str()) &&
      TIFFSetField(t, TIFFTAG_CFAREPEATPATTERNDIM, cfaDims) && TIFFSetField(t, TIFFTAG_CFAPATTERN, 4, cfa) &&
      TIFFSetField(t, TIFFTAG_BLACKLEVEL, 1, &black) && TIFFSetField(t, TIFFTAG_WHITELEVEL, 1, &white) &&
      TIFFSetField(t, TIFFTAG_COLORMATRIX1, 9, colorMatrix) &&
      TIFFSetField(t, TIFFTAG_CALIBRATIONILLUMINANT1, std::uint16_t(d.calibrationIlluminant1)) &&
      TIFFSetField(t, TIFFTAG_ASSHOTNEUTRAL, 3, neutral) && TIFFSetField(t, TIFFTAG_EXIFIFD, exifOffset);
  if (!ok) fail("a tag was refused");
  std::vector<std::uint16_t> row(std::size_t(m.width));
  for (int y = 0; y < m.height; ++y) {
    std::copy_n(m.dn.begin() + std::ptrdiff_t(y) * m.width, m.width, row.begin());
    if (TIFFWriteScanline(t, row.data(), std::uint32_t(y), 0) < 0) fail("writing row " + std::to_string(y));
  }
  if (!TIFFWriteDirectory(t)) fail("writing the directory");
}

}  // namespace

void describeCameraColour(DngDescription& d, const CameraRgb& camera, const Vec3d& channelGains) {
  const Vec3d gains = channelGains / channelGains.y;
  const Mat3d m = Mat3d::diagonal(gains) * camera.xyzToCamera;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) d.colorMatrix1[std::size_t(3 * r + c)] = m(r, c);
  const Vec3d neutral = gains * camera.asShotNeutral;
  d.asShotNeutral = {neutral.x, neutral.y, neutral.z};
}

void writeDng(const std::filesystem::path& file, const Mosaic& mosaic, const DngDescription& description) {
  if (mosaic.width <= 0 || mosaic.height <= 0 ||
      mosaic.dn.size() != std::size_t(mosaic.width) * std::size_t(mosaic.height))
    throw InputError(file.string(), "cannot write an empty mosaic");
  writeFileThrough(file,
                   [&](const std::filesystem::path& tmp) { writeTiff(tmp, file, mosaic, description); });
}

}  // namespace lensrt
