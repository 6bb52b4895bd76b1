// GltfLoader (scene/gltf_loader.h), which `--frames` uses: a file parsed once
// and posed frame after frame, each frame taking the previous one's
// materials, gives every frame exactly as loadGltf reads it alone.
#include <gtest/gtest.h>

#include <cmath>

#include "gltf_test_builder.h"
#include "scene/gltf_loader.h"

namespace lensrt {
namespace {

using nlohmann::json;
using test::GltfBuilder;

// A red triangle sliding 4 m along x and turning 90 degrees about z over 2 s.
std::filesystem::path slidingTriangle() {
  GltfBuilder b;
  const int pos = b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  b.doc["materials"] = json::array({{{"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.1, 0.1, 1}}}}}});
  const int mesh = b.mesh({{"attributes", {{"POSITION", pos}}}, {"material", 0}});
  const int node = b.node({{"mesh", mesh}});
  const float h = float(std::sqrt(0.5));
  b.doc["animations"] = json::array(
      {{{"samplers",
         {{{"input", b.floats({0, 2}, "SCALAR")}, {"output", b.floats({0, 0, 0, 4, 0, 0}, "VEC3")}},
          {{"input", b.floats({0, 2}, "SCALAR")}, {"output", b.floats({0, 0, 0, 1, 0, 0, h, h}, "VEC4")}}}},
        {"channels",
         {{{"sampler", 0}, {"target", {{"node", node}, {"path", "translation"}}}},
          {{"sampler", 1}, {"target", {{"node", node}, {"path", "rotation"}}}}}}}});
  return test::writeFile(test::testDir() / "sliding.gltf", b.json());
}

void expectSameScene(const SceneDesc& a, const SceneDesc& b) {
  EXPECT_EQ(a.pose, b.pose);
  EXPECT_EQ(a.motionSteps, b.motionSteps);
  ASSERT_EQ(a.instances.size(), b.instances.size());
  for (std::size_t i = 0; i < a.instances.size(); ++i) {
    EXPECT_EQ(a.instances[i].worldFromObject.matrix(), b.instances[i].worldFromObject.matrix());
    ASSERT_EQ(a.instances[i].motion.size(), b.instances[i].motion.size());
    for (std::size_t k = 0; k < a.instances[i].motion.size(); ++k)
      EXPECT_EQ(a.instances[i].motion[k].worldFromObject.matrix(),
                b.instances[i].motion[k].worldFromObject.matrix());
  }
  ASSERT_EQ(a.meshes.size(), b.meshes.size());
  for (std::size_t m = 0; m < a.meshes.size(); ++m) EXPECT_EQ(a.meshes[m].positions, b.meshes[m].positions);
  ASSERT_EQ(a.materials.size(), b.materials.size());
  for (std::size_t m = 0; m < a.materials.size(); ++m)
    EXPECT_EQ(a.materials[m].baseColor, b.materials[m].baseColor);
}

TEST(GltfLoaderSequence, EachFrameIsTheFileReadAloneAtItsTime) {
  const std::filesystem::path file = slidingTriangle();
  Warnings w;
  GltfLoader loader(file, -1, w);
  SceneDesc previous;
  bool first = true;
  for (const double t : {0.0, 0.5, 1.25, 3.0}) {
    for (const double span : {0.0, 0.2}) {
      const AnimationTime time{t, "", span};
      SceneDesc frame = loader.load(time, first ? nullptr : &previous);
      first = false;
      expectSameScene(frame, loadGltf(file, -1, w, {}, time));
      previous = std::move(frame);
    }
  }
  ASSERT_EQ(previous.materials.size(), 1u);
  EXPECT_FLOAT_EQ(previous.materials[0].baseColor.x, 0.8f);
  EXPECT_TRUE(w.all().empty()) << *w.all().begin();
}

}  // namespace
}  // namespace lensrt
