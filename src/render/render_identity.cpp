#include "render/render_identity.h"

namespace lensrt {
namespace {

std::string what(const std::string& key) {
  if (key == "lensrt:scene_sha256") return "the scene file differs";
  if (key == "lensrt:camera") return "the camera differs";
  if (key == "lensrt:settings") return "the settings differ";
  if (key == "lensrt:seed") return "the seed differs";
  return key + " differs";
}

}  // namespace

std::string renderIdentityDifference(const ImageMetadata& a, const ImageMetadata& b) {
  for (const char* key : kRenderIdentityKeys) {
    const auto ia = a.find(key), ib = b.find(key);
    if (ia == a.end() || ib == b.end()) return std::string("has no ") + key + " (not a lensrt render?)";
    if (ia->second != ib->second) {
      // Scene digests say nothing to a reader; the other values do.
      if (std::string(key) == "lensrt:scene_sha256") return what(key) + " (its content changed)";
      return what(key) + " ('" + ia->second + "' against '" + ib->second + "')";
    }
  }
  return "";
}

}  // namespace lensrt
