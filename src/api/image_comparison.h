// `lensrt diff` and Python's lensrt.diff: two images compared by
// thresholds as OpenImageIO's idiff does, or statistically (noise-aware),
// with every figure as the JSON document `lensrt diff --json` prints.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "image/image.h"
#include "image/image_diff.h"
#include "image/noise_aware_diff.h"

namespace lensrt {

// Exit statuses, as idiff's: the verdict, or why there was none.
inline constexpr int kDiffPass = 0, kDiffWarn = 1, kDiffFail = 2, kDiffIncomparable = 3, kDiffUnreadable = 4;

struct ComparisonOptions {
  DiffThresholds thresholds;
  std::string heatmap;  // a false-colour map of the per-pixel error to write; empty: none
  double heatmapMax = 0;
  bool noiseAware = false;
  NoiseAwareOptions noise;
  int spp = 0;  // noise-aware: both images' samples per pixel; 0: their lensrt:spp metadata
};

struct ComparedImage {
  std::string name;  // as the report names it: the file, or what the caller calls it
  Image image;
  ImageMetadata metadata;
};

struct Comparison {
  int exitStatus = kDiffPass;
  std::string error;  // why no comparison was made (exit status 3 or 4); empty otherwise
  std::optional<DiffReport> report;
  std::optional<NoiseAwareReport> noise;
  NoiseAwareOptions noiseOptions;  // as applied
  DiffVerdict verdict = DiffVerdict::Pass;
  nlohmann::json json;  // `lensrt diff --json`'s document, the error one included
};

// Compares; writes the heatmap when asked (throws InputError when it cannot).
Comparison compareImages(const ComparedImage& a, const ComparedImage& b, const ComparisonOptions& options);
// Reads both files first: an unreadable one gives exit status 4 and its error.
Comparison compareImageFiles(const std::string& fileA, const std::string& fileB,
                             const ComparisonOptions& options);

}  // namespace lensrt
