// The golden suite must be able to fail: each test renders a case with the
// test seed, checks that it passes against the reference (so the verdict is
// the perturbation's doing), then perturbs it and expects a FAIL (exit 2).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "golden/golden_util.h"
#include "image/image_io.h"

namespace lensrt::golden {
namespace {

constexpr int kFail = 2;

class GoldenSensitivity : public ::testing::Test {
 protected:
  // Renders case `name` with the test seed and checks that it passes.
  void renderPassing(const std::string& name) {
    c_ = &findCase(name);
    if (!std::filesystem::exists(referencePath(*c_)))
      GTEST_SKIP() << "no reference for " << name << " (tools/update-references); GoldenImage fails for it";
    render_ = dir_ / "render.exr";
    const RunResult r = renderCase(*c_, kTestSeed, render_);
    ASSERT_EQ(r.status, 0) << r.err;
    const RunResult d = diffWithReference(*c_, render_);
    ASSERT_EQ(d.status, 0) << "the unperturbed render must pass:\n" << d.out;
  }

  void expectFailure(const std::filesystem::path& perturbed) {
    const RunResult d = diffWithReference(*c_, perturbed);
    EXPECT_EQ(d.status, kFail) << d.out << d.err;
    EXPECT_NE(d.out.find("NOT consistent with noise"), std::string::npos) << d.out;
  }

  // Rewrites the render through `change` (which sees the image) as perturbed.exr.
  template <class Change>
  std::filesystem::path perturb(Change change) {
    ImageMetadata meta;
    Image image = readImage(render_, &meta);
    change(image);
    const auto out = dir_ / "perturbed.exr";
    writeImage(out, image, meta);
    return out;
  }

  const GoldenCase* c_ = nullptr;
  TempDir dir_;
  std::filesystem::path render_;
};

// A 2% exposure change moves most pixels by well under their noise; the
// directly seen ceiling light, nearly noise-free, shows it (measured: 8
// failing pixels where 3 are allowed, max |t| 7.4; the flux test alone,
// z = -1.5, would not: the light's edge pixels dominate its variance).
TEST_F(GoldenSensitivity, TwoPercentGainFails) {
  renderPassing("cornell-pinhole");
  if (IsSkipped() || HasFatalFailure()) return;
  expectFailure(perturb([](Image& image) { image = gained(std::move(image), 1.02); }));
}

// Every channel moved right by one pixel (the first column repeated).
TEST_F(GoldenSensitivity, OnePixelShiftFails) {
  renderPassing("cornell-pinhole");
  if (IsSkipped() || HasFatalFailure()) return;
  expectFailure(perturb([](Image& image) { image = shifted(image); }));
}

TEST_F(GoldenSensitivity, ChangedFNumberOfTheThinLensFails) {
  // f/1.4 focused at 0.3 m blurs the box by about 5 pixels; f/8 by less
  // than one. (Smaller changes, f/2 to f/4 at the same blur scale, hide in
  // the noise of a one-second render: the test cannot see everything.)
  renderPassing("cornell-thin");
  if (IsSkipped() || HasFatalFailure()) return;
  const auto changed = dir_ / "fstop.exr";
  const RunResult r = renderCase(withOption(*c_, "--fstop", "8"), kTestSeed, changed);
  ASSERT_EQ(r.status, 0) << r.err;
  expectFailure(changed);
}

TEST_F(GoldenSensitivity, ChangedFNumberOfTheLensStackFails) {
  // The wide-angle lens's vignetting changes with the stop.
  renderPassing("flat-wall-lens-wide");
  if (IsSkipped() || HasFatalFailure()) return;
  const auto changed = dir_ / "fstop.exr";
  const RunResult r = renderCase(withOption(*c_, "--fstop", "4"), kTestSeed, changed);  // the case: 2.8
  ASSERT_EQ(r.status, 0) << r.err;
  expectFailure(changed);
}

TEST_F(GoldenSensitivity, ChangedFocalLengthOfThePinholeFails) {
  renderPassing("cornell-pinhole");
  if (IsSkipped() || HasFatalFailure()) return;
  ImageMetadata meta;
  readImage(referencePath(*c_), &meta);
  const double focalLength = std::stod(meta.at("lensrt:focal_length_mm"));  // from the glTF's yfov
  const auto changed = dir_ / "focal.exr";
  const RunResult r =
      renderCase(*c_, kTestSeed, changed, {"--focal-length", std::to_string(1.05 * focalLength)});
  ASSERT_EQ(r.status, 0) << r.err;
  expectFailure(changed);
}

// The pinhole references record radiance (the default film): the same render
// on the irradiance film (cos^4 of the field angle, 0.64 in the corners of the
// Cornell camera's 39 degree field) must not pass for it.
TEST_F(GoldenSensitivity, IrradianceFilmOnARadianceReferenceFails) {
  renderPassing("cornell-pinhole");
  if (IsSkipped() || HasFatalFailure()) return;
  const auto changed = dir_ / "irradiance.exr";
  const RunResult r = renderCase(withOption(*c_, "--film", "irradiance"), kTestSeed, changed);
  ASSERT_EQ(r.status, 0) << r.err;
  expectFailure(changed);
}

}  // namespace
}  // namespace lensrt::golden
