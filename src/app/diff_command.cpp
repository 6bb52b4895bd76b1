// `lensrt diff A B`: compare two images, idiff-style, optionally noise-aware.
#include <fmt/core.h>

#include <memory>
#include <optional>
#include <string>

#include "api/image_comparison.h"
#include "api/output_file.h"
#include "app/command.h"
#include "app/option_checks.h"
#include "core/error.h"
#include "image/image_diff.h"
#include "image/image_io.h"
#include "image/noise_aware_diff.h"
#include "image/output_formats.h"

namespace lensrt {
namespace {

struct DiffOptions {
  std::string fileA, fileB;
  ComparisonOptions comparison;
  bool json = false;
};

constexpr const char* kDescription =
    "Compare two images, by thresholds as OpenImageIO's idiff does or statistically (--noise-aware)\n"
    "Channel by channel: EXR (through OpenEXR), PNG, JPEG,\n"
    "Radiance HDR, BMP, TGA, PSD, GIF, PIC or PNM (through stb_image), TIFF, DPX,\n"
    "JPEG 2000, WebP and the other formats OpenImageIO reads (through lensrt's\n"
    "OpenImageIO plugin, loaded only for them).\n"
    "Prints per channel and overall: max |A-B| and its pixel, mean |A-B|, RMSE,\n"
    "PSNR (peak 1.0), mean relative error |A-B|/max((|A|+|B|)/2, floor), and the\n"
    "pixels over the fail/warn thresholds. Thresholds and verdicts follow\n"
    "OpenImageIO's idiff: a value fails when |A-B| > --fail AND\n"
    "|A-B|/((|A|+|B|)/2) > --fail-relative; a pixel fails when any channel does;\n"
    "the images FAIL when more than --fail-percent % of pixels fail or the max\n"
    "error exceeds --hard-fail, else WARN by the --warn* rules, else PASS.\n"
    "Channels are matched by name.\n"
    "\n"
    "--noise-aware (both images need variance.R/G/B, the variance of each\n"
    "pixel's mean, from `lensrt render --aov variance`). Three tests, the count\n"
    "test at half the image-level false-alarm rate --image-alpha, the flux and\n"
    "gain tests at a quarter each; any failing FAILS:\n"
    " count test: per pixel and channel t = |A-B| / sqrt(varA + varB +\n"
    "   (floor*(|A|+|B|)/2)^2) against the two-sided Student-t quantile (nu =\n"
    "   min spp - 1, spp from lensrt:spp metadata or --spp; normal if unknown;\n"
    "   an adaptive render's spp channel gives each pixel its own)\n"
    "   that fails an equivalent pixel with probability --pixel-alpha\n"
    "   (Sidak-split over R,G,B); pixels with zero variance in both images use\n"
    "   the --fail absolute threshold. Fails when the failing pixels exceed the\n"
    "   k with P(Binomial(N, pixel-alpha) > k) <= image-alpha/2.\n"
    " flux test: per channel z = sum(A-B) / sqrt(sum(varA+varB+floor^2)),\n"
    "   normal for unbiased renders; fails when |z| exceeds the two-sided\n"
    "   quantile at image-alpha/12 (catches small global changes that no single\n"
    "   pixel shows).\n"
    " gain test: per channel z = sum(m d / v) / sqrt(sum(m^2 / v)), d = A-B,\n"
    "   m = (|A|+|B|)/2, v as above: the weighted least-squares fit of d = g m,\n"
    "   which weights each pixel by its signal to noise, so a few noisy pixels\n"
    "   (fireflies, small bright lights) cannot hide a 2% gain; tested like the\n"
    "   flux test when both images have the same spp (else reported only).\n"
    "Two renders with different seeds thus FAIL with probability at most\n"
    "image-alpha (pixels assumed independent). Only R,G,B decide; the idiff\n"
    "counts are reported, not applied (--hard-fail/--hard-warn still apply).\n"
    "\n"
    "Exit status: 0 identical or within thresholds, 1 warning, 2 failure (also\n"
    "bad usage), 3 not comparable (size or channels differ), 4 unreadable file.";

void printText(const DiffOptions& o, const DiffReport& r, const std::optional<NoiseAwareReport>& noise) {
  fmt::print("Comparing \"{}\" and \"{}\" ({}x{}, {} channels)\n", o.fileA, o.fileB, r.width, r.height,
             r.channels.size());
  fmt::print("  {:<12} {:>11} {:>12} {:>11} {:>11} {:>8} {:>11} {:>16}\n", "channel", "max error",
             "at (x, y)", "mean error", "RMSE", "PSNR dB", "mean rel", "over fail (%)");
  const auto row = [](const DiffStats& s) {
    fmt::print("  {:<12} {:>11.4g} {:>12} {:>11.4g} {:>11.4g} {:>8.2f} {:>11.4g} {:>16}\n", s.channel,
               s.maxError, fmt::format("({}, {})", s.maxX, s.maxY), s.meanError, s.rmse, s.psnr,
               s.meanRelativeError, fmt::format("{} ({:.3g}%)", s.failCount, s.failPercent));
  };
  for (const auto& s : r.channels) row(s);
  row(r.overall);
  const auto& all = r.overall;
  fmt::print("  Max error = {:.6g} @ ({}, {}, {})\n", all.maxError, all.maxX, all.maxY, all.maxChannel);
  fmt::print("  {} pixels ({:.3g}%) over warn {:g}\n", all.warnCount, all.warnPercent,
             o.comparison.thresholds.warn);
  fmt::print("  {} pixels ({:.3g}%) over fail {:g}\n", all.failCount, all.failPercent,
             o.comparison.thresholds.fail);
  if (noise) {
    const auto& n = *noise;
    fmt::print(
        "  Noise-aware count test: |t| > {:.3f} ({}) fails a pixel; {} of {} pixels fail ({} by t, {} of {} "
        "zero-variance by |A-B| > {:g}); expected {:.3g}, allowed {}; max |t| = {:.3g} @ ({}, {}, {})\n",
        n.criticalValue, n.degreesOfFreedom > 0 ? fmt::format("t, nu = {:g}", n.degreesOfFreedom) : "normal",
        n.failingPixels, n.testedPixels, n.statisticalFailures, n.zeroVarianceFailures, n.zeroVariancePixels,
        o.comparison.noise.absoluteThreshold, n.expectedFailures, n.allowedFailures, n.maxT, n.maxX, n.maxY,
        n.maxChannel);
    fmt::print(
        "  Noise-aware flux test: z(R,G,B) = {:.3g}, {:.3g}, {:.3g} (|z| > {:.3f} fails); relative flux "
        "difference {:.3g}, {:.3g}, {:.3g}\n",
        n.fluxZ[0], n.fluxZ[1], n.fluxZ[2], n.fluxCriticalValue, n.fluxRelativeDifference[0],
        n.fluxRelativeDifference[1], n.fluxRelativeDifference[2]);
    fmt::print(
        "  Noise-aware gain test: z(R,G,B) = {:.3g}, {:.3g}, {:.3g} ({}); weighted gain {:.3g}, {:.3g}, "
        "{:.3g}\n",
        n.gainZ[0], n.gainZ[1], n.gainZ[2],
        n.gainDecides ? fmt::format("|z| > {:.3f} fails", n.fluxCriticalValue)
                      : std::string("reported only: the images' spp differ or are unknown"),
        n.gainEstimate[0], n.gainEstimate[1], n.gainEstimate[2]);
    fmt::print("  Noise-aware: pixel alpha {:g}, image alpha {:g}: {}\n",
               o.comparison.noise.pixelFalseAlarmRate, o.comparison.noise.imageFalseAlarmRate,
               n.pass ? "consistent with noise" : "NOT consistent with noise");
  }
}

int runDiff(const DiffOptions& o) {
  const ComparisonOptions& co = o.comparison;
  if (!co.heatmap.empty()) noteCreatedFolder(createFolderFor(co.heatmap), false);
  const Comparison c = compareImageFiles(o.fileA, o.fileB, co);
  if (!c.error.empty()) {
    // On stderr, and with --json also as JSON on stdout so scripts always get a document.
    fmt::print(stderr, "lensrt: error: {}\n", c.error);
    if (o.json) fmt::print("{}\n", c.json.dump(2));
    return c.exitStatus;
  }
  if (o.json) {
    fmt::print("{}\n", c.json.dump(2));
  } else {
    printText(o, *c.report, c.noise);
    fmt::print("{}\n", verdictName(c.verdict));
  }
  return c.exitStatus;
}

}  // namespace

CommandAction addDiffCommand(CLI::App& app, const CommandContext&) {
  CLI::App* sub =
      app.add_subcommand("diff", "Compare two images; exit 0 pass, 1 warn, 2 fail, 3/4 see --help");
  sub->description(kDescription);
  auto o = std::make_shared<DiffOptions>();
  auto& t = o->comparison.thresholds;
  sub->add_option("A", o->fileA, "First image")->required();
  sub->add_option("B", o->fileB, "Second image")->required();
  // Every check names its range in a few digits (CLI11's NonNegativeNumber
  // spelled out the largest double), and the thresholds whose default is inf
  // take inf.
  const auto absolute = numberFrom(0, "|A-B|");
  const auto relative = numberFrom(0, "|A-B|/((|A|+|B|)/2)");
  const auto anyValue = numberFrom(0, "|A-B| of any one value", false, true);
  const auto percent = numberIn(0, 100, "percent of the pixels");
  sub->add_option("--fail", t.fail, "Failure threshold on |A-B|")->capture_default_str()->check(absolute);
  sub->add_option("--fail-relative", t.failRelative, "Failure threshold on |A-B|/((|A|+|B|)/2)")
      ->capture_default_str()
      ->check(relative);
  sub->add_option("--fail-percent", t.failPercent, "Percentage of pixels allowed to fail")
      ->capture_default_str()
      ->check(percent);
  sub->add_option("--hard-fail", t.hardFail, "Fail if any value's |A-B| exceeds this (default: inf)")
      ->check(anyValue);
  sub->add_option("--warn", t.warn, "Warning threshold on |A-B|")->capture_default_str()->check(absolute);
  sub->add_option("--warn-relative", t.warnRelative, "Warning threshold on |A-B|/((|A|+|B|)/2)")
      ->capture_default_str()
      ->check(relative);
  sub->add_option("--warn-percent", t.warnPercent, "Percentage of pixels allowed to warn")
      ->capture_default_str()
      ->check(percent);
  sub->add_option("--hard-warn", t.hardWarn, "Warn if any value's |A-B| exceeds this (default: inf)")
      ->check(anyValue);
  sub->add_option("--relative-floor", t.relativeFloor, "Floor of the mean relative error's denominator")
      ->capture_default_str()
      ->check(numberFrom(0, "a pixel value", true));
  sub->add_option(
         "--heatmap", o->comparison.heatmap,
         "Write a false-colour map of the per-pixel max |A-B| (noise-aware: max |t|) with a labelled "
         "colour bar (" +
             outputExtensionList() + ")")
      ->check(CLI::Validator(
          [](std::string& file) {
            return isWritableImageExtension(file) ? std::string()
                                                  : "expects a " + outputExtensionList() + " file";
          },
          "IMAGE"));
  sub->add_option("--heatmap-max", o->comparison.heatmapMax,
                  "Value at the top of the heatmap scale (default: the max error; noise-aware: twice the |t| "
                  "threshold)")
      ->check(numberFrom(0, "0 for the default"));
  sub->add_flag("--noise-aware", o->comparison.noiseAware,
                "Judge by per-pixel t-tests against the variance AOVs (see above)");
  sub->add_option("--pixel-alpha", o->comparison.noise.pixelFalseAlarmRate,
                  "Noise-aware: per-pixel false-alarm rate")
      ->capture_default_str()
      ->check(numberIn(1e-12, 0.5, "a probability"));
  sub->add_option("--image-alpha", o->comparison.noise.imageFalseAlarmRate,
                  "Noise-aware: image-level false-alarm rate")
      ->capture_default_str()
      ->check(numberIn(1e-12, 0.5, "a probability"));
  sub->add_option("--variance-floor", o->comparison.noise.relativeFloor,
                  "Noise-aware: standard-deviation floor as a fraction of the pixel value")
      ->capture_default_str()
      ->check(numberFrom(0, "a fraction of the pixel value"));
  sub->add_option("--spp", o->comparison.spp,
                  "Noise-aware: samples per pixel of both (default: lensrt:spp metadata; an spp "
                  "channel, from adaptive sampling, overrides it per pixel)")
      ->check(integerIn(1, 1 << 24, "samples per pixel"));
  sub->add_flag("--json", o->json, "Print all figures as JSON");
  return [o]() { return runDiff(*o); };
}

}  // namespace lensrt
