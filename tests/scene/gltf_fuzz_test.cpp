// Structural corruption of a feature-rich glTF: indices, counts, offsets and
// strides set to hostile values, keys removed, types swapped. Every variant
// must load or throw InputError; anything else (a crash, another exception,
// an Embree failure on what the loader accepted) fails.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/error.h"
#include "gltf_test_builder.h"
#include "scene/gltf_loader.h"
#include "scene/render_scene.h"

namespace lensrt {
namespace {

using nlohmann::json;
using test::GltfBuilder;

GltfBuilder richScene() {
  GltfBuilder b;
  b.doc["extensionsUsed"] = {"EXT_mesh_gpu_instancing", "KHR_lights_punctual",
                             "KHR_materials_emissive_strength"};
  b.doc["images"] = {{{"uri", std::string("data:image/png;base64,") + test::kTwoTexelPngBase64}}};
  b.doc["samplers"] = {{{"magFilter", 9728}, {"wrapS", 33648}}};
  b.doc["textures"] = {{{"source", 0}, {"sampler", 0}}};
  b.doc["materials"] = {{{"alphaMode", "MASK"},
                         {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}},
                         {"emissiveFactor", {1, 1, 1}},
                         {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 3}}}}}}};
  b.doc["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.7}, {"znear", 0.1}}}}};
  b.doc["extensions"]["KHR_lights_punctual"]["lights"] =
      json::array({{{"type", "spot"}, {"intensity", 10}, {"spot", {{"outerConeAngle", 0.6}}}}});
  const int square = b.square(0);
  const int pos = b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}, "VEC3");
  const std::vector<std::uint8_t> which{1};
  const std::vector<float> moved{2, 0, 0};
  const int iv = b.view(which.data(), 1);
  const int vv = b.view(moved.data(), 12);
  b.doc["accessors"][pos]["sparse"] = {{"count", 1},
                                       {"indices", {{"bufferView", iv}, {"componentType", 5121}}},
                                       {"values", {{"bufferView", vv}}}};
  const int strip =
      b.mesh({{"attributes", {{"POSITION", pos}}}, {"mode", 5}, {"indices", b.u8({0, 1, 2, 3})}});
  const int t = b.floats({0, 0, 0, 3, 0, 0}, "VEC3");
  const int child = b.node(
      {{"mesh", strip}, {"camera", 0}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}, false);
  b.node({{"mesh", square}, {"children", {child}}, {"translation", {0, 0, 1}}});
  b.node({{"mesh", square},
          {"extensions", {{"EXT_mesh_gpu_instancing", {{"attributes", {{"TRANSLATION", t}}}}}}}});
  return b;
}

void collectPaths(const json& j, const json::json_pointer& at, std::vector<json::json_pointer>& out) {
  if (j.is_object()) {
    for (const auto& [k, v] : j.items()) collectPaths(v, at / k, out);
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) collectPaths(j[i], at / i, out);
  }
  out.push_back(at);
}

json hostile(std::mt19937& rng) {
  static const std::vector<json> values = {-1,
                                           0,
                                           1,
                                           2,
                                           3,
                                           4,
                                           5,
                                           7,
                                           12,
                                           255,
                                           256,
                                           65535,
                                           65536,
                                           2147483647,
                                           -2147483647,
                                           4294967295.0,
                                           1e19,
                                           1e300,
                                           -1e300,
                                           0.5,
                                           -0.0,
                                           "x",
                                           json::array(),
                                           json::object(),
                                           nullptr,
                                           true};
  return values[rng() % values.size()];
}

TEST(GltfFuzz, StructuralCorruptionLoadsOrThrowsInputError) {
  const GltfBuilder base = richScene();
  const json doc = json::parse(base.json());
  {
    Warnings w;
    const SceneDesc d = loadGltf(test::writeFile(test::testDir() / "base.gltf", doc.dump()), -1, w);
    ASSERT_EQ(d.lights.size(), 1u);  // the baseline exercises what the variants corrupt
    ASSERT_EQ(d.cameras.size(), 1u);
    ASSERT_EQ(d.textures.size(), 1u);
  }
  std::vector<json::json_pointer> paths;
  collectPaths(doc, json::json_pointer(), paths);
  std::mt19937 rng(7);
  const std::filesystem::path file = test::testDir() / "variant.gltf";
  int loaded = 0, rejected = 0;
  for (int round = 0; round < 400; ++round) {
    json variant = doc;
    const int edits = 1 + static_cast<int>(rng() % 3);
    for (int e = 0; e < edits; ++e) {
      const json::json_pointer& p = paths[rng() % paths.size()];
      if (p.empty() || !variant.contains(p)) continue;
      // Never touch the base64 buffer itself: that is byte fuzzing, done elsewhere.
      if (p.back() == "uri" && p.parent_pointer().parent_pointer().back() == "buffers") continue;
      if (rng() % 5 == 0 && variant[p.parent_pointer()].is_object()) {
        variant[p.parent_pointer()].erase(p.back());
      } else {
        variant[p] = hostile(rng);
      }
    }
    test::writeFile(file, variant.dump());
    Warnings w;
    try {
      SceneDesc d = loadGltf(file, -1, w);
      const RenderScene scene(std::move(d));
      scene.intersect({{0.5f, 0.5f, 10}, {0, 0, -1}});
      ++loaded;
    } catch (const InputError&) {
      ++rejected;
    }
  }
  EXPECT_GT(loaded, 0);
  EXPECT_GT(rejected, 0);
}

}  // namespace
}  // namespace lensrt
