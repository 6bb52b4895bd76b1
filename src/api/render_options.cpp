#include "api/render_options.h"

#include <fmt/core.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>

#include "core/error.h"
#include "image/image_io.h"

namespace lensrt {
namespace {

// Whole-string integer parse; no atoi-style silent garbage.
std::optional<int> parseInt(const std::string& s) {
  int v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return v;
}

std::optional<float> parseFloat(const std::string& s) {
  try {
    std::size_t used = 0;
    const float v = std::stof(s, &used);
    if (used != s.size()) return std::nullopt;
    return v;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

constexpr int kMaxDimension = 65536;

}  // namespace

namespace {

// "" when `text` is a valid --res value, else why not.
std::string checkResolution(const std::string& text) {
  const std::size_t x = text.find_first_of("xX");
  const std::optional<int> w = parseInt(text.substr(0, x));
  const std::optional<int> h = x == std::string::npos ? std::optional<int>(0) : parseInt(text.substr(x + 1));
  if (!w || !h) return "expected WIDTHxHEIGHT in pixels (e.g. 640x360) or WIDTH, got '" + text + "'";
  if (*w < 1 || *w > kMaxDimension || (x != std::string::npos && (*h < 1 || *h > kMaxDimension)))
    return "width and height must be between 1 and " + std::to_string(kMaxDimension) + " pixels, got '" +
           text + "'";
  return "";
}

}  // namespace

Resolution parseResolution(const std::string& text) {
  if (const std::string why = checkResolution(text); !why.empty()) throw UsageError("--res", why);
  const std::size_t x = text.find_first_of("xX");
  return {*parseInt(text.substr(0, x)), x == std::string::npos ? 0 : *parseInt(text.substr(x + 1))};
}

EnvironmentSpec parseEnvironment(const std::string& text) {
  EnvironmentSpec spec;
  if (text == "none") {
    spec.none = true;
    return spec;
  }
  constexpr std::string_view kConstant = "constant:";
  if (text.rfind(kConstant, 0) == 0) {
    std::vector<float> values;
    std::string rest = text.substr(kConstant.size());
    std::size_t start = 0;
    while (true) {
      const std::size_t comma = rest.find(',', start);
      const std::optional<float> v = parseFloat(rest.substr(start, comma - start));
      if (!v || !std::isfinite(*v) || *v < 0)
        throw UsageError("--env",
                         "constant radiance must be one or three finite values >= 0 in W/(sr m^2), "
                         "e.g. constant:1 or constant:0.2,0.3,0.5, got '" +
                             text + "'");
      values.push_back(*v);
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    if (values.size() != 1 && values.size() != 3)
      throw UsageError("--env", "constant radiance takes one or three values, got '" + text + "'");
    spec.constant =
        values.size() == 1 ? Rgb{values[0], values[0], values[0]} : Rgb{values[0], values[1], values[2]};
    return spec;
  }
  if (!isReadableImageExtension(text))
    throw UsageError("--env",
                     "expected none, constant:V, constant:R,G,B or a lat-long image file (.exr, .hdr, .tif, "
                     ".webp, .png, ...), got '" +
                         text + "'");
  spec.file = text;
  return spec;
}

SceneReadLimits sceneReadLimits(const SceneAccessArgs& args) {
  SceneReadLimits limits;
  limits.allowExternalFiles = args.allowExternalFiles;
  limits.maxTextureBytes = args.maxTextureMiB << 20;
  return limits;
}

AovSelection parseAovs(const std::vector<std::string>& names) {
  AovSelection a;
  for (const std::string& n : names) {
    if (n == "depth")
      a.depth = true;
    else if (n == "z")
      a.z = true;
    else if (n == "normal")
      a.normal = true;
    else if (n == "albedo")
      a.albedo = true;
    else if (n == "variance")
      a.variance = true;
    else if (n == "crypto_object")
      a.cryptoObject = true;
    else if (n == "crypto_material")
      a.cryptoMaterial = true;
    else if (n == "object_id")
      a.objectId = true;
    else if (n == "position")
      a.position = true;
    else if (n == "uv")
      a.uv = true;
    else if (n == "object_coords")
      a.objectCoords = true;
    else if (n == "flow")
      a.flow = true;
    else
      throw UsageError("--aov", "unknown AOV '" + n +
                                    "' (choose from depth, z, normal, albedo, variance, crypto_object, "
                                    "crypto_material, object_id, position, uv, object_coords, flow)");
  }
  return a;
}

std::optional<AdaptiveSampling> adaptiveSampling(double noiseThreshold, std::optional<int> minSpp, int spp) {
  if (noiseThreshold == 0) {
    if (minSpp) throw UsageError("--min-spp", "needs --noise-threshold (adaptive sampling)");
    return std::nullopt;
  }
  if (!(noiseThreshold > 0) || !std::isfinite(noiseThreshold))
    throw UsageError(
        "--noise-threshold",
        fmt::format("expected a number > 0 (the relative standard error at which a pixel stops), "
                    "got {}",
                    noiseThreshold));
  AdaptiveSampling adaptive;
  adaptive.noiseThreshold = noiseThreshold;
  // The default minimum is at most --spp: --spp 8 alone asks for no more.
  adaptive.minSamples = minSpp.value_or(std::min(adaptive.minSamples, spp));
  if (adaptive.minSamples < 1)
    throw UsageError("--min-spp", fmt::format("expected at least 1 sample, got {}", adaptive.minSamples));
  if (adaptive.minSamples > spp)
    throw UsageError("--min-spp", fmt::format("{} is above --spp {} (the most samples a pixel takes)",
                                              adaptive.minSamples, spp));
  return adaptive;
}

}  // namespace lensrt
