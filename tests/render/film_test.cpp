// The film's A channel is coverage: of the samples that reach the scene
// straight through the lens, the fraction that hit geometry. Counted by
// hand here, sample by sample, so each rule has its own check: samples the
// lens blocks are not counted, nor are those reflected in it (flare) beside
// straight ones; a pixel no sample reached is 0.
#include "render/film.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

namespace lensrt {
namespace {

PathSample sample(bool hit) {
  PathSample s;
  s.hit = hit;
  s.radiance = {0.25f, 0.5f, 1.0f};
  if (hit) {
    s.distance = 2;
    s.normal = {0, 0, 1};
  }
  return s;
}

const AovSelection kNoAovs{};

float alphaOf(const PixelAccumulator& p) {
  float out[4];
  p.write(kNoAovs, out);
  return out[3];
}

// A pinhole never blocks nor reflects: A is hits over samples, as it always
// was (3 of 8: exactly 0.375).
TEST(FilmAlpha, WithEverySampleStraightAIsHitsOverSamples) {
  PixelAccumulator p;
  for (int i = 0; i < 8; ++i) p.add(sample(i % 3 == 0), 1.0f);
  EXPECT_EQ(alphaOf(p), 0.375f);
}

// The lens blocks samples (vignetting): they darken RGB, not A. A wall seen
// through a corner that blocks 7 of 8 samples is opaque.
TEST(FilmAlpha, SamplesTheLensBlocksLeaveAAlone) {
  PixelAccumulator p;
  for (int i = 0; i < 7; ++i) p.addBlocked();
  p.add(sample(true), 1.0f);
  EXPECT_EQ(alphaOf(p), 1.0f);
  float out[4];
  p.write(kNoAovs, out);
  EXPECT_EQ(out[2], 1.0f / 8);  // RGB keeps the vignetting: the mean over all 8

  PixelAccumulator half;  // 2 straight, 1 hits; 5 blocked
  for (int i = 0; i < 5; ++i) half.addBlocked();
  half.add(sample(true), 1.0f);
  half.add(sample(false), 1.0f);
  EXPECT_EQ(alphaOf(half), 0.5f);
}

// Flare's samples, reflected in the lens, look in other directions than the
// pixel: beside straight samples they do not count, whether they hit or not.
TEST(FilmAlpha, LensReflectedSamplesDoNotCountBesideStraightOnes) {
  PixelAccumulator wall;  // straight samples all hit; reflected ones miss (sky)
  for (int i = 0; i < 4; ++i) wall.add(sample(true), 1.0f);
  for (int i = 0; i < 12; ++i) wall.add(sample(false), 1.0f, true);
  EXPECT_EQ(alphaOf(wall), 1.0f);

  PixelAccumulator sky;  // straight samples miss; reflected ones hit a wall
  for (int i = 0; i < 4; ++i) sky.add(sample(false), 1.0f);
  for (int i = 0; i < 12; ++i) sky.add(sample(true), 1.0f, true);
  EXPECT_EQ(alphaOf(sky), 0.0f);
}

// Without any straight sample (flare at a few spp), the reflected ones'
// coverage; without any sample that reached the scene, 0.
TEST(FilmAlpha, NoStraightSampleTakesTheReflectedOnesAndNoneReachedIsZero) {
  PixelAccumulator reflected;
  reflected.addBlocked();
  reflected.add(sample(true), 1.0f, true);
  reflected.add(sample(true), 1.0f, true);
  reflected.add(sample(false), 1.0f, true);
  reflected.add(sample(true), 1.0f, true);
  EXPECT_EQ(alphaOf(reflected), 0.75f);

  PixelAccumulator blocked;
  for (int i = 0; i < 4; ++i) blocked.addBlocked();
  EXPECT_EQ(alphaOf(blocked), 0.0f);
  EXPECT_EQ(alphaOf(PixelAccumulator{}), 0.0f);
}

// A sample with a non-finite radiance is dropped from every mean, A's too.
TEST(FilmAlpha, DroppedSamplesAreNotCounted) {
  PixelAccumulator p;
  p.add(sample(true), 1.0f);
  PathSample bad = sample(false);
  bad.radiance = {std::numeric_limits<float>::quiet_NaN(), 0, 0};
  p.add(bad, 1.0f);
  EXPECT_EQ(p.droppedSamples(), 1u);
  EXPECT_EQ(alphaOf(p), 1.0f);
}

// A checkpoint (and an MPI strip) carries the counts: saved halfway and
// continued, a mix of blocked, straight and reflected samples gives the
// bits of the uninterrupted pixel, A included.
TEST(FilmAlpha, SavedStateContinuesTheCounts) {
  const auto feed = [](PixelAccumulator& p, int from, int to) {
    for (int i = from; i < to; ++i) {
      if (i % 5 == 0)
        p.addBlocked();
      else
        p.add(sample(i % 3 != 0), 0.5f + 0.01f * float(i), i % 4 == 1);
    }
  };
  const AovSelection all{true, true, true, true, true};
  const std::size_t channels = filmChannels(all).size();
  PixelAccumulator whole;
  feed(whole, 0, 40);
  PixelAccumulator first;
  feed(first, 0, 17);
  std::vector<std::byte> bytes(PixelAccumulator::kStateBytes);
  first.saveState(bytes.data());
  PixelAccumulator resumed;
  resumed.loadState(bytes.data());
  feed(resumed, 17, 40);
  std::vector<float> a(channels), b(channels);
  whole.write(all, a.data());
  resumed.write(all, b.data());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), channels * sizeof(float)), 0);
  // Straight samples: i not a multiple of 5 and i % 4 != 1; they hit unless i % 3 == 0.
  int seen = 0, covered = 0;
  for (int i = 0; i < 40; ++i)
    if (i % 5 != 0 && i % 4 != 1) {
      ++seen;
      covered += i % 3 != 0;
    }
  EXPECT_EQ(b[3], float(double(covered) / seen));
}

}  // namespace
}  // namespace lensrt
