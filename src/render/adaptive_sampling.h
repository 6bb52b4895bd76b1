// Adaptive sampling: a pixel stops taking samples once the relative standard
// error of its mean is below a threshold. Each pixel decides from its own
// running sums alone, and only at fixed sample counts (the decision points,
// a function of the settings, never of timing), so the image is the same for
// any thread count, tile size, pass schedule, MPI ranks or resume.
#pragma once

#include <cstdint>

#include "render/film.h"

namespace lensrt {

struct AdaptiveSampling {
  // The relative standard error of a pixel's mean at which it stops (e.g. 0.01).
  double noiseThreshold = 0.01;
  // No pixel stops before this many samples: a handful of samples can agree
  // by chance (all of them missing a small light) and look converged.
  int minSamples = 16;
};

// Below this mean (in the image's units, 1 = display white), the error is
// measured against this floor instead of the pixel: as Cycles normalises by
// the square root of the pixel's value, a dark pixel is judged on absolute
// noise that a viewer could see, not on a relative error that a near-black
// pixel could only reach after very many samples.
inline constexpr double kAdaptiveDarkFloor = 0.05;

// The relative standard error of the pixel's mean: the channels' standard
// errors summed, over the channels' means summed (with the floor for each).
double relativeStandardError(const PixelAccumulator& pixel);

// The decision points after `samples` samples: the minimum, then steps of an
// eighth of the count (at least one), so a render up to N spp checks about
// 8 ln(N / min) times and each check costs a pass over the pixels at most.
bool isDecisionPoint(const AdaptiveSampling& adaptive, int samples);
int nextDecisionPoint(const AdaptiveSampling& adaptive, int samples);  // the first one above `samples`

// Whether a pixel that has taken all `samplesDone` samples so far takes the
// next one: always between decision points, and at one unless converged.
bool keepsSampling(const AdaptiveSampling& adaptive, const PixelAccumulator& pixel, int samplesDone);

}  // namespace lensrt
