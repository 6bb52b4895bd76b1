// The raw file's EXIF against the closed form of a known camera: a thin lens
// of 50 mm. On the 36 x 24 mm frame (48 x 32 pixels) its 35 mm equivalent
// is 50 and the focal plane holds 48 / 3.6 = 13.333 pixels per cm across and
// 32 / 2.4 down; on APS-C (23.6 x 15.6 mm, cropped to 3:2: 23.4 x 15.6 mm,
// diagonal 28.124 mm) it is 50 x 43.267 / 28.124 = 76.9, written 77; on a
// square 20 x 20 mm sensor (32 x 32 pixels, 16 per cm) 50 x 43.267 / 28.284
// = 76.5, written 76 (by the width's crop it would be 90, the height's 60).
// Without a camera response, Model names lensrt's model; LensModel is
// absent without a lens file.
#include <gtest/gtest.h>
#include <tiffio.h>

#include <cmath>
#include <memory>
#include <string>

#include "cli/cli_util.h"

namespace lensrt {
namespace {

struct Closer {
  void operator()(TIFF* t) const { TIFFClose(t); }
};

TEST(RawDngExif, AThinLensOfKnownFocalLengthAndSensor) {
  const cli::TempDir dir;
  struct Case {
    std::string sensor;
    int width, height;
    double widthMm, heightMm;
    int equivalent;
  };
  for (const Case& c : {Case{"36x24", 48, 32, 36.0, 24.0, 50}, Case{"aps-c", 48, 32, 23.4, 15.6, 77},
                        Case{"20x20", 32, 32, 20.0, 20.0, 76}}) {
    SCOPED_TRACE(c.sensor);
    const std::string dng = (dir / "a.dng").string();
    const cli::RunResult r = cli::runLensrt({"render",
                                             std::string(LENSRT_SOURCE_DIR) + "/scenes/dof_row.gltf",
                                             "--camera",
                                             "thin",
                                             "--focal-length",
                                             "50",
                                             "--fstop",
                                             "8",
                                             "--focus",
                                             "2",
                                             "--sensor",
                                             c.sensor,
                                             "--res",
                                             std::to_string(c.width) + "x" + std::to_string(c.height),
                                             "--spp",
                                             "1",
                                             "-q",
                                             "-o",
                                             (dir / "a.exr").string(),
                                             "--raw",
                                             dng});
    ASSERT_EQ(r.status, 0) << r.err;
    const std::unique_ptr<TIFF, Closer> tiff(TIFFOpen(dng.c_str(), "r"));
    ASSERT_TRUE(tiff);
    char* model = nullptr;
    ASSERT_TRUE(TIFFGetField(tiff.get(), TIFFTAG_MODEL, &model));
    EXPECT_STREQ(model, "thin");
    toff_t exif = 0;
    ASSERT_TRUE(TIFFGetField(tiff.get(), TIFFTAG_EXIFIFD, &exif));
    ASSERT_TRUE(TIFFReadEXIFDirectory(tiff.get(), exif));
    std::uint16_t f35 = 0, unit = 0;
    float focal = 0, perCmX = 0, perCmY = 0;
    ASSERT_TRUE(TIFFGetField(tiff.get(), EXIFTAG_FOCALLENGTH, &focal));
    EXPECT_NEAR(focal, 50.0, 1e-4);
    ASSERT_TRUE(TIFFGetField(tiff.get(), EXIFTAG_FOCALLENGTHIN35MMFILM, &f35));
    EXPECT_EQ(f35, c.equivalent);
    ASSERT_TRUE(TIFFGetField(tiff.get(), EXIFTAG_FOCALPLANEXRESOLUTION, &perCmX));
    ASSERT_TRUE(TIFFGetField(tiff.get(), EXIFTAG_FOCALPLANEYRESOLUTION, &perCmY));
    ASSERT_TRUE(TIFFGetField(tiff.get(), EXIFTAG_FOCALPLANERESOLUTIONUNIT, &unit));
    EXPECT_EQ(unit, 3);  // centimetres
    EXPECT_NEAR(perCmX, c.width / (c.widthMm / 10), 1e-4);
    EXPECT_NEAR(perCmY, c.height / (c.heightMm / 10), 1e-3);
    char* lens = nullptr;
    EXPECT_FALSE(TIFFGetField(tiff.get(), EXIFTAG_LENSMODEL, &lens));
    char* when = nullptr;
    ASSERT_TRUE(TIFFGetField(tiff.get(), EXIFTAG_DATETIMEORIGINAL, &when));
    EXPECT_EQ(std::string(when).size(), 19u) << when;  // "YYYY:MM:DD HH:MM:SS"
  }
}

}  // namespace
}  // namespace lensrt
