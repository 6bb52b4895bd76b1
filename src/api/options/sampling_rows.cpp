// Samples and the integrator (api/render_spec.h's SamplingSpec). Rows of the option table
// (api/option_table.h).
#include <limits>
#include <optional>

#include "api/options/rows.h"
#include "render/adaptive_sampling.h"

namespace lensrt {

void addSamplingRows(std::vector<Option>& table) {
  const auto add = [&table](Option o) -> Option& { return addRow(table, "sampling", std::move(o)); };
  {
    Option& o = add(integer(
        row("--spp", "spp", "N",
            "samples per pixel (>= 1; with --noise-threshold, the most a pixel takes), e.g. "
            "--spp 64 (default 16)",
            "64", PyValue::Integer),
        [](auto& s) -> auto& { return s.sampling.spp; }, 1, 1 << 24, "samples per pixel"));
    // A render resumed to more samples is the same render.
    o.identity = Identity::Extent;
  }
  {
    Option o = row("--noise-threshold", "noise_threshold", "E",
                   "adaptive sampling: a pixel stops once the relative standard error of its mean is below "
                   "this (dark pixels: of a floor of 0.05), between --min-spp and --spp samples, e.g. "
                   "--noise-threshold 0.01",
                   "0.05", PyValue::Number);
    o.set = [](RenderSpec& s, const std::string& text) {
      s.sampling.noiseThreshold = parseNumberFrom("--noise-threshold", text, 0,
                                                  "the relative standard error at which a pixel stops", true);
    };
    o.show = [](const RenderSpec& s) {
      return s.sampling.noiseThreshold > 0 ? numberText(s.sampling.noiseThreshold) : std::string("default");
    };
    add(std::move(o));
  }
  {
    Option& o = add(row("--min-spp", "min_spp", "N",
                        "adaptive sampling: samples every pixel takes before it may stop (default 16), e.g. "
                        "--min-spp 32",
                        "4", PyValue::Integer));
    o.set = [](RenderSpec& s, const std::string& text) {
      s.sampling.minSpp = int(parseIntegerIn("--min-spp", text, 1, 1 << 24, "samples per pixel"));
    };
    o.show = [](const RenderSpec& s) {
      return s.sampling.minSpp ? std::to_string(*s.sampling.minSpp) : std::string("default");
    };
  }
  {
    Option o = row("--seed", "seed", "N", "random seed; same seed, same image on any machine, e.g. --seed 7",
                   "7", PyValue::Integer);
    o.set = [](RenderSpec& s, const std::string& text) {
      s.sampling.seed = parseUnsignedIn("--seed", text, 0, std::numeric_limits<std::uint64_t>::max());
    };
    o.show = [](const RenderSpec& s) { return std::to_string(s.sampling.seed); };
    add(std::move(o));
  }
  add(integer(
      row("--max-depth", "max_depth", "N",
          "maximum scattering events per path (0: emitters only, 1: direct light), e.g. --max-depth 8 "
          "(default 8)",
          "3", PyValue::Integer),
      [](auto& s) -> auto& { return s.sampling.maxDepth; }, 0, 1024, "scattering events per path"));
  {
    Option o = row("--light-sampler", "light_sampler", "tree|power",
                   "how next-event estimation picks a light: tree (a light tree, by what each light can give "
                   "the shading point: for many lights; default) or power (by power alone, wherever the "
                   "point), e.g. --light-sampler power",
                   "power", PyValue::Text);
    o.set = [](RenderSpec& s, const std::string& text) {
      const std::optional<LightSampling> sampling = parseLightSampling(text);
      if (!sampling) throw UsageError("--light-sampler", "expected tree or power, got '" + text + "'");
      s.sampling.lightSampling = *sampling;
    };
    o.show = [](const RenderSpec& s) { return std::string(lightSamplingName(s.sampling.lightSampling)); };
    add(std::move(o));
  }
  add(integer(
          row("--threads", "threads", "N", "worker threads (0: all cores), e.g. --threads 4", "2",
              PyValue::Integer),
          [](auto& s) -> auto& { return s.sampling.threads; }, 0, 4096, "worker threads, 0 for all cores"))
      .identity = Identity::None;
  {
    Option& o = add(integer(
        row("--tile-size", "tile_size", "PIXELS",
            "tile size in pixels for scheduling threads (does not change the image; default "
            "16)",
            "8", PyValue::Integer),
        [](auto& s) -> auto& { return s.sampling.tileSize; }, 1, 4096, "pixels"));
    o.identity = Identity::None;
  }
}

}  // namespace lensrt
