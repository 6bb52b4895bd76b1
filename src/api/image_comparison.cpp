#include "api/image_comparison.h"

#include <fmt/core.h>

#include <cmath>
#include <vector>

#include "core/error.h"
#include "image/heatmap.h"
#include "image/image_io.h"

namespace lensrt {
namespace {

static_assert(int(DiffVerdict::Pass) == kDiffPass && int(DiffVerdict::Warn) == kDiffWarn &&
              int(DiffVerdict::Fail) == kDiffFail);

std::optional<int> sppFromMetadata(const ImageMetadata& metadata) {
  const auto it = metadata.find("lensrt:spp");
  if (it == metadata.end()) return std::nullopt;
  try {
    std::size_t used = 0;
    const int spp = std::stoi(it->second, &used);
    if (used == it->second.size() && spp > 0) return spp;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

nlohmann::json numberOrNull(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

nlohmann::json statsJson(const DiffStats& s) {
  return {{"channel", s.channel},
          {"maxError", numberOrNull(s.maxError)},
          {"maxPixel", {s.maxX, s.maxY}},
          {"maxChannel", s.maxChannel},
          {"meanError", numberOrNull(s.meanError)},
          {"rmse", numberOrNull(s.rmse)},
          {"psnr", numberOrNull(s.psnr)},
          {"meanRelativeError", numberOrNull(s.meanRelativeError)},
          {"failCount", s.failCount},
          {"failPercent", s.failPercent},
          {"warnCount", s.warnCount},
          {"warnPercent", s.warnPercent}};
}

nlohmann::json noiseJson(const NoiseAwareReport& n, const NoiseAwareOptions& o) {
  return {
      {"pixelFalseAlarmRate", o.pixelFalseAlarmRate},
      {"imageFalseAlarmRate", o.imageFalseAlarmRate},
      {"relativeFloor", o.relativeFloor},
      {"degreesOfFreedom", n.degreesOfFreedom},
      {"criticalValue", n.criticalValue},
      {"testedPixels", n.testedPixels},
      {"zeroVariancePixels", n.zeroVariancePixels},
      {"zeroVarianceFailures", n.zeroVarianceFailures},
      {"statisticalFailures", n.statisticalFailures},
      {"failingPixels", n.failingPixels},
      {"expectedFailures", n.expectedFailures},
      {"allowedFailures", n.allowedFailures},
      {"fluxZ", {numberOrNull(n.fluxZ[0]), numberOrNull(n.fluxZ[1]), numberOrNull(n.fluxZ[2])}},
      {"fluxRelativeDifference",
       {numberOrNull(n.fluxRelativeDifference[0]), numberOrNull(n.fluxRelativeDifference[1]),
        numberOrNull(n.fluxRelativeDifference[2])}},
      {"gainZ", {numberOrNull(n.gainZ[0]), numberOrNull(n.gainZ[1]), numberOrNull(n.gainZ[2])}},
      {"gainDecides", n.gainDecides},
      {"gainEstimate",
       {numberOrNull(n.gainEstimate[0]), numberOrNull(n.gainEstimate[1]), numberOrNull(n.gainEstimate[2])}},
      {"fluxCriticalValue", n.fluxCriticalValue},
      {"maxT", numberOrNull(n.maxT)},
      {"maxPixel", {n.maxX, n.maxY}},
      {"maxChannel", n.maxChannel},
      {"pass", n.pass}};
}

Comparison refusal(const std::string& a, const std::string& b, int status, const std::string& message) {
  Comparison c;
  c.exitStatus = status;
  c.error = message;
  c.json = nlohmann::json{{"a", a}, {"b", b}, {"error", message}, {"exitStatus", status}};
  return c;
}

}  // namespace

Comparison compareImages(const ComparedImage& ca, const ComparedImage& cb, const ComparisonOptions& o) {
  const Image &a = ca.image, &b = cb.image;
  if (const auto why = incomparableReason(a, b))
    return refusal(ca.name, cb.name, kDiffIncomparable,
                   fmt::format("\"{}\" and \"{}\" are not comparable: {}", ca.name, cb.name, *why));
  Comparison c;
  c.report = diffImages(a, b, o.thresholds);
  const DiffReport& report = *c.report;
  c.verdict = report.verdict;
  if (o.noiseAware) {
    if (!hasVarianceChannels(a) || !hasVarianceChannels(b))
      return refusal(ca.name, cb.name, kDiffIncomparable,
                     fmt::format("\"{}\" and \"{}\" are not comparable noise-aware: both need R,G,B and "
                                 "variance.R/G/B channels (lensrt render --aov variance)",
                                 ca.name, cb.name));
    c.noiseOptions = o.noise;
    c.noiseOptions.absoluteThreshold = o.thresholds.fail;
    c.noiseOptions.samplesA = o.spp > 0 ? o.spp : sppFromMetadata(ca.metadata).value_or(0);
    c.noiseOptions.samplesB = o.spp > 0 ? o.spp : sppFromMetadata(cb.metadata).value_or(0);
    c.noise = noiseAwareDiff(a, b, c.noiseOptions);
    const double maxError = report.overall.maxError;
    c.verdict = !c.noise->pass || maxError > o.thresholds.hardFail ? DiffVerdict::Fail
                : maxError > o.thresholds.hardWarn                 ? DiffVerdict::Warn
                                                                   : DiffVerdict::Pass;
  }
  const std::optional<NoiseAwareReport>& noise = c.noise;

  if (!o.heatmap.empty()) {
    // Noise-aware, the map shows |t| with the pixel threshold mid-scale, so
    // failing pixels are the green-to-yellow half.
    HeatmapOptions options;
    options.scaleMax = o.heatmapMax > 0 ? o.heatmapMax : noise ? 2 * noise->criticalValue : 0.0;
    if (noise) options.title = fmt::format("|t|, fail > {:.3g}", noise->criticalValue);
    const std::vector<float> values = noise ? perPixelMaxT(a, b, c.noiseOptions) : perPixelMaxError(a, b);
    writeImage(o.heatmap, makeHeatmap(values, a.width, a.height, options), {});
  }

  c.exitStatus = int(c.verdict);
  nlohmann::json j{{"a", ca.name},
                   {"b", cb.name},
                   {"width", report.width},
                   {"height", report.height},
                   {"thresholds",
                    {{"fail", o.thresholds.fail},
                     {"failRelative", o.thresholds.failRelative},
                     {"failPercent", o.thresholds.failPercent},
                     {"hardFail", numberOrNull(o.thresholds.hardFail)},
                     {"warn", o.thresholds.warn},
                     {"warnRelative", o.thresholds.warnRelative},
                     {"warnPercent", o.thresholds.warnPercent},
                     {"hardWarn", numberOrNull(o.thresholds.hardWarn)},
                     {"relativeFloor", o.thresholds.relativeFloor}}},
                   {"channels", nlohmann::json::array()},
                   {"overall", statsJson(report.overall)},
                   {"noiseAware", noise ? noiseJson(*noise, o.noise) : nlohmann::json(nullptr)},
                   {"verdict", verdictName(c.verdict)},
                   {"exitStatus", c.exitStatus}};
  for (const auto& s : report.channels) j["channels"].push_back(statsJson(s));
  if (!o.heatmap.empty()) j["heatmap"] = o.heatmap;
  c.json = std::move(j);
  return c;
}

Comparison compareImageFiles(const std::string& fileA, const std::string& fileB, const ComparisonOptions& o) {
  ComparedImage a{fileA, {}, {}}, b{fileB, {}, {}};
  try {
    a.image = readImage(fileA, &a.metadata);
    b.image = readImage(fileB, &b.metadata);
  } catch (const InputError& e) {
    return refusal(fileA, fileB, kDiffUnreadable, e.what());
  }
  return compareImages(a, b, o);
}

}  // namespace lensrt
