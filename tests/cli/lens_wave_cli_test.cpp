// `lensrt lens psf` and `lensrt lens mtf` end to end: the outputs, the
// sampling they state, and one-line errors for an afocal lens and a field
// beyond the lens's coverage.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli/cli_util.h"

namespace lensrt {
namespace {

using cli::readFile;
using cli::runLensrt;
using cli::TempDir;

std::size_t lineCount(const std::string& text) {
  return std::size_t(std::count(text.begin(), text.end(), '\n'));
}

TEST(LensWaveCli, PsfWritesSvgCsvAndStatesItsSampling) {
  const TempDir dir;
  const auto r = runLensrt({"lens", "psf", "dgauss-50mm", "--fstop", "8", "-o", (dir / "psf.svg").string(),
                            "--csv", (dir / "psf.csv").string(), "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j["sampling"]["aliased"].get<bool>());
  EXPECT_EQ(j["sampling"]["pupil_samples"].get<int>(), 65);
  EXPECT_GE(j["sampling"]["fft_size"].get<int>(), 2 * 65);
  EXPECT_EQ(j["wavelengths"].size(), 3u);  // d, F, C
  // dgauss-50mm at f/8 on the axis is close to diffraction-limited.
  EXPECT_GT(j["strehl"].get<double>(), 0.9);
  EXPECT_LE(j["strehl"].get<double>(), 1.0 + 1e-9);
  EXPECT_NE(r.err.find("not aliased"), std::string::npos) << r.err;
  EXPECT_NE(readFile(dir / "psf.svg").find("id=\"encircled-energy\""), std::string::npos);
  EXPECT_EQ(readFile(dir / "psf.csv").rfind("offset_um,psf_x,psf_y,limit_x,limit_y", 0), 0u);
}

// Aberrations cannot lift a uniformly lit pupil's MTF above its diffraction
// limit; the MTF starts at 1.
TEST(LensWaveCli, MtfStaysBelowItsDiffractionLimit) {
  const auto r = runLensrt(
      {"lens", "mtf", "dgauss-50mm", "--fstop", "4", "--field", "10", "--wavelengths", "550", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& m = j["mtf"];
  ASSERT_EQ(m["tangential"].size(), 101u);
  EXPECT_DOUBLE_EQ(m["tangential"][0].get<double>(), 1.0);
  for (std::size_t k = 0; k < m["tangential"].size(); ++k) {
    EXPECT_LE(m["tangential"][k].get<double>(), m["limit_tangential"][k].get<double>() + 0.01) << k;
    EXPECT_LE(m["sagittal"][k].get<double>(), m["limit_sagittal"][k].get<double>() + 0.01) << k;
  }
  EXPECT_EQ(j["through_focus"]["film_shift_mm"].size(), 21u);
}

TEST(LensWaveCli, AfocalLensAndFieldBeyondCoverageAreOneLineErrors) {
  const std::string afocal = std::string(LENSRT_TEST_DATA_DIR) + "/bad-inputs/lens-afocal.lens";
  const auto a = runLensrt({"lens", "psf", afocal, "--json"});
  EXPECT_EQ(a.status, 1);
  EXPECT_EQ(lineCount(a.err), 1u) << a.err;
  EXPECT_NE(a.err.find("lens-afocal.lens"), std::string::npos) << a.err;
  const auto f = runLensrt({"lens", "mtf", "dgauss-50mm", "--field", "60", "--json"});
  EXPECT_EQ(f.status, 2);
  EXPECT_EQ(lineCount(f.err), 1u) << f.err;
  EXPECT_NE(f.err.find("--field: dgauss-50mm"), std::string::npos) << f.err;
  EXPECT_NE(f.err.find("coverage"), std::string::npos) << f.err;
  const auto p = runLensrt({"lens", "psf", "dgauss-50mm", "--pupil-samples", "10", "--json"});
  EXPECT_EQ(p.status, 2);
  EXPECT_NE(p.err.find("--pupil-samples"), std::string::npos) << p.err;
  EXPECT_TRUE(a.out.empty() && f.out.empty() && p.out.empty());
}

}  // namespace
}  // namespace lensrt
