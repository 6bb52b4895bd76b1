// Every shared Khronos sample renders without NaN or Inf through every camera
// model of `lensrt render --camera` (tests/cli covers the default pinhole over
// every file variant; here one variant per sample, each model). Skipped when
// ../shared is absent.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "image/image_io.h"
#include "robustness/run_util.h"

namespace lensrt::robustness {
namespace {

namespace fs = std::filesystem;

// One file per sample folder: the .glb when there is one, else a .gltf.
std::vector<fs::path> oneFilePerSample(const fs::path& scenes) {
  std::map<fs::path, fs::path> chosen;
  for (const auto& e : fs::recursive_directory_iterator(scenes)) {
    const std::string ext = e.path().extension().string();
    if (ext != ".gltf" && ext != ".glb") continue;
    const fs::path sample = fs::relative(e.path(), scenes).begin()->string();
    auto [it, inserted] = chosen.try_emplace(sample, e.path());
    if (!inserted && ext == ".glb" && it->second.extension() != ".glb") it->second = e.path();
  }
  std::vector<fs::path> files;
  for (const auto& [sample, file] : chosen) files.push_back(file);
  return files;
}

TEST(SharedScenes, RenderWithoutNaNThroughEveryCameraModel) {
  const fs::path scenes = fs::path(LENSRT_SHARED_DIR) / "scenes";
  if (!fs::is_directory(scenes)) GTEST_SKIP() << "no shared scenes at " << scenes;
  const RunResult help = runWithTimeout({LENSRT_BINARY, "render", "--help"}, 60);
  if (help.out.find("--camera") == std::string::npos || help.out.find("--lens") == std::string::npos)
    GTEST_SKIP() << "lensrt render has no --camera/--lens yet (the pinhole case is in tests/cli)";
  const TempDir dir("shared_scenes");
  int rendered = 0;
  for (const fs::path& file : oneFilePerSample(scenes)) {
    for (const std::string model : {"thin", "thick", "lens"}) {
      const fs::path out = dir.path() / "s.exr";
      const RunResult r = runWithTimeout(
          {LENSRT_BINARY, "render", file.string(), "--camera", model, "--lens", "dgauss-50mm", "--focus",
           "inf", "--res", "24x16", "--spp", "2", "--env", "constant:0.5", "-q", "-o", out.string()},
          300);
      ASSERT_FALSE(r.timedOut) << file << " " << model;
      ASSERT_EQ(r.status, 0) << file << " " << model << ": " << r.err;
      ImageMetadata meta;
      const Image img = readImage(out, &meta);
      EXPECT_EQ(meta["lensrt:nan_samples"], "0") << file << " " << model;
      for (const float v : img.pixels) ASSERT_TRUE(std::isfinite(v)) << file << " " << model;
      ++rendered;
    }
  }
  EXPECT_GT(rendered, 0);
}

}  // namespace
}  // namespace lensrt::robustness
