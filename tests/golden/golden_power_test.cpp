// The golden suite's power: what change each case can see. A fresh render of
// a case (not the reference's seed) is perturbed as a regression would
// perturb it, and the noise-aware diff against the reference must FAIL:
//  - a gain of 2% (the variance scaled by the square, as a scaled estimate's is);
//  - every channel moved right by one pixel (the first column repeated).
// The unperturbed render must PASS (else the case has a false alarm).
//
// In the suite each case runs for the test seed alone (a deterministic check
// that cannot pass for a blind case). tools/measure-golden-power sets
// LENSRT_GOLDEN_POWER_SEEDS=N: each case then renders N seeds and prints its
// detection rates for gains of 0.5, 1, 2 and 5% and the shift, its false
// alarms, and its minimum detectable gain (the smallest caught in at least 99%
// of the seeds), the figures of the README's table; the test then asks for a
// 2% gain and the shift caught in at least 99% of the seeds.
#include <gtest/gtest.h>

#include <array>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "golden/golden_util.h"
#include "image/image_io.h"
#include "image/noise_aware_diff.h"

namespace lensrt::golden {
namespace {

constexpr std::array kGains{1.005, 1.01, 1.02, 1.05};

// The white furnace renders 1 in every pixel, sphere and sky alike: its
// image is the same shifted, so no test can see a shift there (it guards the
// energy balance, which the gain test covers).
bool shiftInvariant(const GoldenCase& c) {
  return c.name == "furnace-pinhole";
}

int seedsToMeasure() {
  const char* n = std::getenv("LENSRT_GOLDEN_POWER_SEEDS");
  return n && std::atoi(n) > 0 ? std::atoi(n) : 0;
}

int sppOf(const ImageMetadata& meta) {
  const auto it = meta.find("lensrt:spp");
  return it == meta.end() ? 0 : std::atoi(it->second.c_str());
}

// As `lensrt diff --noise-aware` judges (its defaults, spp from the metadata).
bool fails(const Image& reference, int referenceSpp, const Image& candidate, int candidateSpp) {
  NoiseAwareOptions o;
  o.samplesA = referenceSpp;
  o.samplesB = candidateSpp;
  return !noiseAwareDiff(reference, candidate, o).pass;
}

class GoldenPower : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(GoldenPower, CatchesATwoPercentGainAndAOnePixelShift) {
  const GoldenCase& c = GetParam();
  if (!std::filesystem::exists(referencePath(c)))
    GTEST_SKIP() << "no reference for " << c.name << " (GoldenImage fails for it)";
  ImageMetadata referenceMeta;
  const Image reference = readImage(referencePath(c), &referenceMeta);
  const int referenceSpp = sppOf(referenceMeta);
  const int measured = seedsToMeasure();
  const int seeds = measured > 0 ? measured : 1;
  const TempDir dir;
  int falseAlarms = 0, shiftCaught = 0;
  std::array<int, kGains.size()> gainCaught{};
  for (int i = 0; i < seeds; ++i) {
    const int seed = measured > 0 ? 1000 + i : kTestSeed;
    const auto file = dir / "render.exr";
    const RunResult r = renderCase(c, seed, file);
    ASSERT_EQ(r.status, 0) << r.err;
    ImageMetadata meta;
    const Image render = readImage(file, &meta);
    const int spp = sppOf(meta);
    falseAlarms += fails(reference, referenceSpp, render, spp);
    shiftCaught += fails(reference, referenceSpp, shifted(render), spp);
    for (std::size_t g = 0; g < kGains.size(); ++g)
      gainCaught[g] += fails(reference, referenceSpp, gained(render, kGains[g]), spp);
  }
  const int twoPercent = gainCaught[2];
  if (measured == 0) {
    EXPECT_EQ(falseAlarms, 0) << c.name << ": the unperturbed render fails (see GoldenImage)";
    EXPECT_EQ(twoPercent, 1) << c.name << ": a 2% gain passes against the reference";
    if (shiftCaught != 1 && !shiftInvariant(c)) {
      ImageMetadata meta;
      const Image render = readImage(dir / "render.exr", &meta);
      NoiseAwareOptions o;
      o.samplesA = referenceSpp;
      o.samplesB = sppOf(meta);
      const NoiseAwareReport n = noiseAwareDiff(reference, shifted(render), o);
      ADD_FAILURE() << c.name << ": a 1 px shift passes against the reference (max |t| " << n.maxT << ", "
                    << n.failingPixels << " failing pixels, " << n.allowedFailures << " allowed; flux z "
                    << n.fluxZ[0] << ", gain z " << n.gainZ[0] << ")";
    }
    return;
  }
  // The smallest gain of the ladder caught in at least 99% of the seeds.
  std::string detectable = "> 5%";
  for (std::size_t g = kGains.size(); g-- > 0;)
    if (100 * gainCaught[g] >= 99 * seeds)
      detectable = std::to_string((kGains[g] - 1) * 100).substr(0, 3) + "%";
  std::printf(
      "%-22s seeds %d  false alarms %d  gain caught 0.5%% %d, 1%% %d, 2%% %d, 5%% %d  shift %d  "
      "minimum detectable gain %s%s\n",
      c.name.c_str(), seeds, falseAlarms, gainCaught[0], gainCaught[1], gainCaught[2], gainCaught[3],
      shiftCaught, detectable.c_str(), shiftInvariant(c) ? "  (uniform: no shift to see)" : "");
  EXPECT_GE(100 * twoPercent, 99 * seeds) << c.name;
  if (!shiftInvariant(c)) {
    EXPECT_GE(100 * shiftCaught, 99 * seeds) << c.name;
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, GoldenPower, ::testing::ValuesIn(loadCases()),
                         [](const ::testing::TestParamInfo<GoldenCase>& info) {
                           std::string name = info.param.name;
                           for (char& ch : name)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return name;
                         });

}  // namespace
}  // namespace lensrt::golden
