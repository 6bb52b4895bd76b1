// Every Khronos sample under ${LENSRT_SHARED_DIR}/scenes loads and builds.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>

#include "scene/gltf_loader.h"
#include "scene/render_scene.h"

namespace lensrt {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> sharedScenes() {
  std::vector<fs::path> files;
  const fs::path root = fs::path(LENSRT_SHARED_DIR) / "scenes";
  std::error_code ec;
  if (!fs::is_directory(root, ec)) return files;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    const std::string ext = entry.path().extension().string();
    if (entry.is_regular_file() && (ext == ".gltf" || ext == ".glb")) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

TEST(SharedScenes, AllLoadAndBuild) {
  const std::vector<fs::path> files = sharedScenes();
  if (files.empty()) GTEST_SKIP() << "no glTF samples: " << LENSRT_SHARED_DIR << "/scenes is absent";
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.string());
    Warnings warnings([&](const std::string& w) { std::cout << "  warning: " << w << "\n"; });
    std::cout << fs::relative(file, fs::path(LENSRT_SHARED_DIR) / "scenes").string() << "\n";
    const auto start = std::chrono::steady_clock::now();
    SceneDesc desc;
    ASSERT_NO_THROW(desc = loadGltf(file, -1, warnings));
    const auto loaded = std::chrono::steady_clock::now();
    std::size_t triangles = 0;
    for (const MeshInstance& inst : desc.instances) triangles += desc.meshes[inst.mesh].triangleCount();
    const std::size_t cameras = desc.cameras.size(), lights = desc.lights.size();
    const RenderScene scene(std::move(desc));
    const auto built = std::chrono::steady_clock::now();
    const auto ms = [](auto d) { return std::chrono::duration<double, std::milli>(d).count(); };
    std::cout << "  " << triangles << " triangles, " << cameras << " cameras, " << lights << " lights; load "
              << ms(loaded - start) << " ms, build " << ms(built - loaded) << " ms\n";
    EXPECT_GT(triangles, 0u);
    // A ray from outside the bounds toward the centre must find geometry
    // (all samples are closed or face the +Z viewer... so aim from several sides).
    const Bounds3f b = scene.bounds();
    ASSERT_FALSE(b.empty());
    int hits = 0;
    const Vec3f c = b.center();
    const float r = length(b.diagonal()) + 1;
    for (const Vec3f d :
         {Vec3f{0, 0, -1}, Vec3f{0, 0, 1}, Vec3f{1, 0, 0}, Vec3f{-1, 0, 0}, Vec3f{0, -1, 0}, Vec3f{0, 1, 0}})
      for (int k = 0; k < 25; ++k) {
        const Vec3f jitter{(k % 5 - 2) * 0.1f * b.diagonal().x, (k / 5 - 2) * 0.1f * b.diagonal().y, 0};
        if (scene.intersect({c - d * r + jitter * (d.z != 0 ? 1.0f : 0.0f), d})) ++hits;
      }
    EXPECT_GT(hits, 0);
  }
}

// The Khronos KHR_texture_transform conformance scene: loads without a
// warning, and its rotation quad (22.5 degrees) carries the extension's R.
TEST(SharedScenes, TextureTransformTestLoadsTheSpecsMatrices) {
  const fs::path file =
      fs::path(LENSRT_SHARED_DIR) / "scenes/TextureTransformTest/glTF/TextureTransformTest.gltf";
  std::error_code ec;
  if (!fs::exists(file, ec)) GTEST_SKIP() << file << " is absent";
  Warnings warnings;
  const SceneDesc desc = loadGltf(file, -1, warnings);
  EXPECT_TRUE(warnings.all().empty());
  const float c = std::cos(0.392699f), s = std::sin(0.392699f);
  int rotated = 0;
  for (const Material& m : desc.materials) {
    const UvTransform& t = m.baseColorTexture.transform;
    // The rotation-only quad: no offset, cos on the diagonal (the "all" quad scales too).
    if (t.m[2] != 0 || t.m[5] != 0 || std::abs(t.m[0] - c) > 1e-5f) continue;
    ++rotated;
    EXPECT_NEAR(t.m[1], s, 1e-5f);
    EXPECT_NEAR(t.m[3], -s, 1e-5f);
    EXPECT_NEAR(t.m[4], c, 1e-5f);
  }
  EXPECT_EQ(rotated, 1);
}

}  // namespace
}  // namespace lensrt
