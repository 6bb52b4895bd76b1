// Lens file readers: the accepted variants and every rejected case.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.h"
#include "optics/lens_readers.h"
#include "optics_test_util.h"

namespace lensrt {
namespace {

const std::string kBadDir = std::string(LENSRT_TEST_DATA_DIR) + "/optics/bad-lenses/";

TEST(Readers, PbrtToleratesBomCrlfAndNoFinalNewline) {
  const std::string text =
      "\xEF\xBB\xBF# a lens\r\n50\t5\t1.5\t20\r\n-50\t2\t1\t20\r\n0\t2\t0\t18\r\n-50\t40\t1\t20";
  const LensPrescription lens = parsePbrtLens(text, "x.dat");
  ASSERT_EQ(lens.surfaces.size(), 4u);
  EXPECT_EQ(lens.stopIndex(), 2);
  EXPECT_DOUBLE_EQ(lens.surfaces[0].medium.nd, 1.5);
  EXPECT_DOUBLE_EQ(lens.surfaces[2].medium.nd, 1.0);  // 0 means air
  EXPECT_DOUBLE_EQ(lens.surfaces[3].thickness, 40.0);
  EXPECT_EQ(lens.surfaces[3].line, 5);
  EXPECT_EQ(lens.description, "a lens");
  EXPECT_EQ(lens.name, "x");
  EXPECT_NO_THROW(validatePrescription(lens));
}

// ISET's and pbrt-v3's files: the nominal focal length as a lone number
// before the first surface row.
TEST(Readers, PbrtReadsAFocalLengthBeforeTheFirstRow) {
  const LensPrescription lens = loadLens(std::string(LENSRT_TEST_DATA_DIR) + "/optics/iset-dgauss-50mm.dat");
  EXPECT_DOUBLE_EQ(lens.nominalFocalLengthMm, 50.0);
  ASSERT_EQ(lens.surfaces.size(), 11u);
  EXPECT_DOUBLE_EQ(lens.surfaces[0].radius, 29.475);
  EXPECT_EQ(lens.surfaces[0].line, 8);
  // The same rows as the library's dgauss-50mm.
  const LensPrescription library = test::libraryLens("dgauss-50mm");
  for (std::size_t i = 0; i < library.surfaces.size(); ++i) {
    EXPECT_EQ(lens.surfaces[i].radius, library.surfaces[i].radius);
    EXPECT_EQ(lens.surfaces[i].thickness, library.surfaces[i].thickness);
  }
  const LensPrescription bare = parsePbrtLens(
      "\xEF\xBB\xBF"
      "35\r\n50 5 1.5 20\r\n0 2 0 18\r\n",
      "b.dat");
  EXPECT_DOUBLE_EQ(bare.nominalFocalLengthMm, 35.0);
  EXPECT_EQ(bare.surfaces.size(), 2u);
  // A second lone number is a row with the wrong column count.
  EXPECT_THROW(parsePbrtLens("35\n36\n50 5 1.5 20\n", "c.dat"), InputError);
}

TEST(Readers, TableReadsTheSeedLayout) {
  const std::string text =
      "# name: t\n# focal-length-mm: 99\nradius thick n_d V ap\n 58.950 7.520 1.670 47.1 50.4\n"
      "169.660 0.240 50.4\n (stop) 9.000 34.2\n flat 2 1.5 60 30 BK7\n-79.46 72.228 40.0\r\n";
  const LensPrescription lens = parseTableLens(text, "t.lens");
  ASSERT_EQ(lens.surfaces.size(), 5u);
  EXPECT_DOUBLE_EQ(lens.nominalFocalLengthMm, 99.0);
  EXPECT_DOUBLE_EQ(lens.surfaces[0].medium.vd, 47.1);
  EXPECT_TRUE(lens.surfaces[1].medium.isAir());
  EXPECT_TRUE(lens.surfaces[2].isStop);
  EXPECT_FALSE(lens.surfaces[3].isStop);
  EXPECT_EQ(lens.surfaces[3].radius, 0.0);
  EXPECT_EQ(lens.surfaces[3].medium.glass, "BK7");
}

TEST(Readers, JsonCarriesMetadataAndGlass) {
  const std::string text = R"({"format": "lensrt-lens", "version": 1, "name": "j", "description": "d",
    "source": "s", "focal_length_mm": 80,
    "surfaces": [{"radius": 50, "thickness": 5, "aperture": 20, "nd": 1.5, "vd": 64, "glass": "BK7"},
                 {"radius": -50, "thickness": 2, "aperture": 20},
                 {"radius": 0, "thickness": 2, "aperture": 18, "stop": true},
                 {"radius": -50, "thickness": 40, "aperture": 20}]})";
  const LensPrescription lens = parseJsonLens(text, "j.json");
  EXPECT_EQ(lens.source, "s");
  EXPECT_DOUBLE_EQ(lens.nominalFocalLengthMm, 80.0);
  EXPECT_EQ(lens.surfaces[0].medium.glass, "BK7");
  EXPECT_EQ(lens.stopIndex(), 2);
  EXPECT_NO_THROW(validatePrescription(lens));
}

struct BadCase {
  const char* file;
  const char* message;  // expected in the error
  int line;             // expected line, 0 when the format has none
};

class BadLens : public testing::TestWithParam<BadCase> {};

// The broken files are mutations of this one, so each fails for its own reason.
TEST(Readers, TheUnbrokenBaseLensLoads) {
  EXPECT_NO_THROW(loadLens(std::string(LENSRT_TEST_DATA_DIR) + "/optics/good-lens.dat"));
}

TEST_P(BadLens, IsRejectedWithAClearMessage) {
  const BadCase& c = GetParam();
  try {
    loadLens(kBadDir + c.file);
    FAIL() << c.file << " was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(e.message().find(c.message), std::string::npos) << "got: " << e.what();
    EXPECT_NE(e.file().find(c.file), std::string::npos) << e.what();
    EXPECT_EQ(e.line(), c.line) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    Optics, BadLens,
    testing::Values(
        BadCase{"zero-aperture.dat", "aperture diameter must be positive", 4},
        BadCase{"negative-aperture.dat", "aperture diameter must be positive", 5},
        BadCase{"aperture-wider-than-sphere.dat", "wider than the sphere", 1},
        BadCase{"no-stop.dat", "no aperture stop", 0}, BadCase{"two-stops.lens", "second aperture stop", 5},
        BadCase{"overlap.dat", "cuts into the previous surface", 4}, BadCase{"nan.dat", "NaN", 1},
        BadCase{"infinite.dat", "NaN or infinite", 5}, BadCase{"absurd-thickness.dat", "absurd", 5},
        BadCase{"three-columns.dat", "expected 4 columns", 5},
        BadCase{"four-columns.lens", "expected 5 columns", 5},
        BadCase{"not-a-number.lens", "expected a number for V_d", 2},
        BadCase{"index-below-one.dat", "refractive index", 4},
        BadCase{"syntax-error.json", "invalid JSON", 4}, BadCase{"unknown-key.json", "unknown key", 0},
        BadCase{"missing-aperture.json", "missing \"aperture\"", 0},
        BadCase{"no-surfaces.json", "no surfaces", 0}, BadCase{"no-format.json", "\"format\"", 0},
        BadCase{"lone-number-after-first-row.dat", "expected 4 columns", 6},
        BadCase{"negative-focal-length.dat", "focal length before the first surface must be a positive", 2},
        BadCase{"unknown-aspheric-term.lens", "unknown aspheric term 'A5'", 1},
        BadCase{"aperture-beyond-conic-domain.lens", "wider than the conic's domain", 1},
        BadCase{"aspheric-not-numbers.json", "\"aspheric\" must hold numbers only", 0}),
    [](const testing::TestParamInfo<BadCase>& info) {
      std::string name = info.param.file;
      for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
      return name;
    });

TEST(Readers, AMillionRowsAreRefusedEarly) {
  std::string text;
  text.reserve(12'000'000);
  for (int i = 0; i < 1'000'000; ++i) text += "50 5 1.5 20\n";
  try {
    parsePbrtLens(text, "huge.dat");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(e.message().find("more than"), std::string::npos) << e.what();
    EXPECT_EQ(e.line(), kMaxSurfaces + 1);
  }
}

TEST(Readers, FindLensResolvesNamesAndPaths) {
  EXPECT_EQ(findLens("dgauss-50mm", test::lensDir()).filename(), "dgauss-50mm.dat");
  const auto path = (test::lensDir() / "dgauss-100mm.lens").string();
  EXPECT_EQ(findLens(path, test::lensDir()), path);
  try {
    findLens("no-such-lens", test::lensDir());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(e.message().find("dgauss-50mm"), std::string::npos) << "lists the library: " << e.what();
  }
}

}  // namespace
}  // namespace lensrt
