// The ID AOVs as a compositor reads them back from the EXR: the Cryptomatte
// layout and header (specification 1.1/1.2), the matte of one object against
// the closed-form coverage of a known layout, object_id against that layout,
// tiles merging to the whole render, and the runs that cannot carry the IDs
// refused.
//
// The scene: two quads on the ground, seen straight down through the pinhole
// from 2 m with yfov 0.5 on a square 16 x 16 film, so that a pixel's footprint
// on the ground is a square of side p = 2 * 2 tan(0.25) / 16 and its coverage
// by a rectangle is their overlap area / p^2 (the box filter's samples are
// uniform in the pixel). The rectangles' edges cut pixels at 0.20 (A's right
// edge), 0.87 (B's left) and 0.23 (B's top).
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli/cli_util.h"
#include "image/image_io.h"

namespace lensrt {
namespace {

using cli::runLensrt;
using cli::RunResult;
using cli::TempDir;

// Ids computed by an independent MurmurHash3_x86_32 (Python, seed 0) that
// gives the specification's published 'bunny' 13851a76 and 'default'
// 42c9679f; none of these has an exponent of 0 or 255, so the id's bits are
// the hash.
constexpr std::uint32_t kNode0 = 0x8f5ae098, kNode1 = 0x0893bae6;
constexpr std::uint32_t kWhite = 0xdb8f0013, kRed = 0xeb5026fd, kDefault = 0x42c9679f;
// The metadata keys: the first 7 hex digits of the layer name's hash
// (CryptoObject 3ae39a58, CryptoMaterial be359d67).
const std::string kObjectKey = "cryptomatte/3ae39a5/", kMaterialKey = "cryptomatte/be359d6/";

constexpr int kRes = 16;
const double kHalf = 2.0 * std::tan(0.25);  // half the ground's width in view, metres
const double kPixel = 2.0 * kHalf / kRes;

struct Rect {
  double x0, x1, z0, z1;
};
// Node 0 (material white), node 1 (material red); the rest is background.
constexpr Rect kA{-0.9, 0.013, -0.9, 0.9}, kB{0.2, 0.9, -0.27, 0.9};

cli::Quad quad(const Rect& r, int material) {
  // Counterclockwise seen from above (+Y); image right is +X, image up is -Z.
  const float x0 = float(r.x0), x1 = float(r.x1), z0 = float(r.z0), z1 = float(r.z1);
  return {{{x0, 0, z1}, {x1, 0, z1}, {x1, 0, z0}, {x0, 0, z0}}, material};
}

// The share of pixel (x, y)'s footprint that the rectangle covers.
double coverage(const Rect& r, int x, int y) {
  const double px0 = -kHalf + x * kPixel, pz0 = -kHalf + y * kPixel;
  const double wx = std::max(0.0, std::min(r.x1, px0 + kPixel) - std::max(r.x0, px0));
  const double wz = std::max(0.0, std::min(r.z1, pz0 + kPixel) - std::max(r.z0, pz0));
  return wx * wz / (kPixel * kPixel);
}

struct Render {
  Image image;
  ImageMetadata meta;
  RunResult run;
};

std::string writeScene(const TempDir& dir) {
  cli::QuadScene scene;
  scene.quads = {quad(kA, 0), quad(kB, 1)};
  scene.materials = R"({"name":"white","pbrMetallicRoughness":{"baseColorFactor":[0.8,0.8,0.8,1]}},)"
                    R"({"name":"red","pbrMetallicRoughness":{"baseColorFactor":[0.8,0.1,0.1,1]}})";
  const std::string file = (dir / "scene.gltf").string();
  cli::writeFile(file, cli::quadsGltf(scene));
  return file;
}

std::vector<std::string> renderArgs(const std::string& scene, const std::string& out, int spp) {
  return {"render",     scene,
          "--res",      std::to_string(kRes) + "x" + std::to_string(kRes),
          "--spp",      std::to_string(spp),
          "--spectral", "off",
          "--aov",      "crypto_object,crypto_material,object_id",
          "-q",         "-o",
          out};
}

Render render(const std::vector<std::string>& args, const std::string& out) {
  Render r;
  r.run = runLensrt(args);
  EXPECT_EQ(r.run.status, 0) << r.run.err;
  if (r.run.status == 0) r.image = readImage(out, &r.meta);
  return r;
}

// The matte of an id: the sum of the coverages of the ranks that hold it.
double matte(const Image& im, const std::string& layer, std::uint32_t id, int x, int y) {
  double sum = 0;
  for (const char* rank : {"00", "01", "02"})
    for (const auto& [idc, cov] : {std::pair{".R", ".G"}, std::pair{".B", ".A"}}) {
      const float v = im.at(x, y, im.channelIndex(layer + rank + idc));
      if (std::bit_cast<std::uint32_t>(v) == id) sum += im.at(x, y, im.channelIndex(layer + rank + cov));
    }
  return sum;
}

// The 6 coverages of a layer, rank 0 first.
std::vector<float> coverages(const Image& im, const std::string& layer, int x, int y) {
  std::vector<float> c;
  for (const char* rank : {"00", "01", "02"})
    for (const char* k : {".G", ".A"}) c.push_back(im.at(x, y, im.channelIndex(layer + rank + k)));
  return c;
}

TEST(IdAovs, TheExrHasCryptomattesLayoutAndHeader) {
  const TempDir dir;
  const std::string out = (dir / "ids.exr").string();
  const Render r = render(renderArgs(writeScene(dir), out, 4), out);
  ASSERT_EQ(r.run.status, 0);
  for (const std::string layer : {"CryptoObject", "CryptoMaterial"}) {
    for (const char* rank : {"00", "01", "02"})
      for (const char* k : {".R", ".G", ".B", ".A"})
        EXPECT_GE(r.image.channelIndex(layer + rank + k), 0) << layer << rank << k;
    EXPECT_EQ(r.image.channelIndex(layer + "03.R"), -1);  // 6 ranks, the specification's default
  }
  EXPECT_GE(r.image.channelIndex("object_id.X"), 0);
  for (const auto& [key, layer] : {std::pair{kObjectKey, "CryptoObject"}, {kMaterialKey, "CryptoMaterial"}}) {
    EXPECT_EQ(r.meta.count(key + "name") ? r.meta.at(key + "name") : "", layer);
    EXPECT_EQ(r.meta.count(key + "hash") ? r.meta.at(key + "hash") : "", "MurmurHash3_32");
    EXPECT_EQ(r.meta.count(key + "conversion") ? r.meta.at(key + "conversion") : "", "uint32_to_float32");
  }
  ASSERT_TRUE(r.meta.count(kObjectKey + "manifest") && r.meta.count(kMaterialKey + "manifest"));
  const auto manifest = [&](const std::string& key) {
    return nlohmann::json::parse(r.meta.at(key + "manifest")).get<std::map<std::string, std::string>>();
  };
  EXPECT_EQ(manifest(kObjectKey),
            (std::map<std::string, std::string>{{"node0", "8f5ae098"}, {"node1", "0893bae6"}}));
  EXPECT_EQ(manifest(kMaterialKey),
            (std::map<std::string, std::string>{
                {"white", "db8f0013"}, {"red", "eb5026fd"}, {"default", "42c9679f"}}));
  // The pixels hold the manifest's ids: node0 (white) fills the top-left pixel.
  EXPECT_EQ(std::bit_cast<std::uint32_t>(r.image.at(0, 0, r.image.channelIndex("CryptoObject00.R"))), kNode0);
  EXPECT_EQ(std::bit_cast<std::uint32_t>(r.image.at(0, 0, r.image.channelIndex("CryptoMaterial00.R"))),
            kWhite);
  EXPECT_EQ(std::bit_cast<std::uint32_t>(r.image.at(15, 15, r.image.channelIndex("CryptoMaterial00.R"))),
            kRed);
}

// 1024 samples a pixel: a coverage f estimated from n independent samples has
// standard deviation sqrt(f (1 - f) / n) <= 0.016; the tolerance is 4 of
// those, 0.0625 (the sampler's strata make the error smaller still). It
// detects a matte off by more than that: coverage not normalised by the
// pixel's samples, the id and coverage channels swapped, an edge pixel given
// all to one id, rank 0 not the largest.
TEST(IdAovs, AnObjectsMatteIsItsCoverageAndTheIdsSumToAlpha) {
  const TempDir dir;
  const std::string out = (dir / "ids.exr").string();
  const Render r = render(renderArgs(writeScene(dir), out, 1024), out);
  ASSERT_EQ(r.run.status, 0);
  const Image& im = r.image;
  const int alpha = im.channelIndex("A"), objectId = im.channelIndex("object_id.X");
  const double tol = 4.0 * std::sqrt(0.25 / 1024);
  double worst = 0;
  int edges = 0;
  for (int y = 0; y < kRes; ++y)
    for (int x = 0; x < kRes; ++x) {
      const double a = coverage(kA, x, y), b = coverage(kB, x, y);
      const double ma = matte(im, "CryptoObject", kNode0, x, y), mb = matte(im, "CryptoObject", kNode1, x, y);
      EXPECT_NEAR(ma, a, tol) << "node0 at " << x << "," << y;
      EXPECT_NEAR(mb, b, tol) << "node1 at " << x << "," << y;
      EXPECT_NEAR(matte(im, "CryptoMaterial", kWhite, x, y), a, tol) << x << "," << y;
      EXPECT_NEAR(matte(im, "CryptoMaterial", kRed, x, y), b, tol) << x << "," << y;
      EXPECT_EQ(matte(im, "CryptoMaterial", kDefault, x, y), 0.0);
      // Outside: exactly nothing.
      if (a == 0) {
        EXPECT_EQ(ma, 0.0) << x << "," << y;
      }
      if (b == 0) {
        EXPECT_EQ(mb, 0.0) << x << "," << y;
      }
      worst = std::max({worst, std::abs(ma - a), std::abs(mb - b)});
      edges += (a > 0 && a < 1) || (b > 0 && b < 1);
      // The ids' coverages (background's id 0 aside) sum to A, and all to 1.
      const std::vector<float> c = coverages(im, "CryptoObject", x, y);
      EXPECT_NEAR(ma + mb, im.at(x, y, alpha), 1e-6) << x << "," << y;
      double all = 0;
      for (const float v : c) all += v;
      EXPECT_NEAR(all, 1.0, 1e-6) << x << "," << y;
      EXPECT_TRUE(std::is_sorted(c.rbegin(), c.rend())) << "ranks out of order at " << x << "," << y;
      // object_id: the node covering most of the pixel, -1 for the background.
      const double bg = 1 - a - b;
      const float expected = a > 0.6 ? 0.0f : b > 0.6 ? 1.0f : bg > 0.6 ? -1.0f : NAN;
      if (!std::isnan(expected)) {
        EXPECT_EQ(im.at(x, y, objectId), expected) << x << "," << y;
      }
    }
  EXPECT_GE(edges, 16 + 13);  // A's right edge and B's two edges cross pixels
  std::printf("largest matte error %.4f (tolerance %.4f)\n", worst, tol);
}

// Tiles are whole pixels, so lensrt merge joins them into the whole render's
// ID channels and header, bit for bit.
TEST(IdAovs, MergedTilesAreTheWholeRender) {
  const TempDir dir;
  const std::string scene = writeScene(dir);
  const std::string whole = (dir / "whole.exr").string(), merged = (dir / "merged.exr").string();
  const Render w = render(renderArgs(scene, whole, 16), whole);
  std::vector<std::string> mergeArgs = {"merge", "-q", "-o", merged};
  for (int i = 0; i < 2; ++i) {
    const std::string part = (dir / ("t" + std::to_string(i) + ".exr")).string();
    std::vector<std::string> args = renderArgs(scene, part, 16);
    args.insert(args.end(), {"--tile", std::to_string(i) + "/2"});
    ASSERT_EQ(runLensrt(args).status, 0);
    mergeArgs.push_back(part);
  }
  const RunResult m = runLensrt(mergeArgs);
  ASSERT_EQ(m.status, 0) << m.err;
  ImageMetadata meta;
  const Image joined = readImage(merged, &meta);
  ASSERT_EQ(joined.channels, w.image.channels);
  int differ = 0;
  for (std::size_t i = 0; i < joined.pixels.size(); ++i)
    differ +=
        std::bit_cast<std::uint32_t>(joined.pixels[i]) != std::bit_cast<std::uint32_t>(w.image.pixels[i]);
  EXPECT_EQ(differ, 0);
  for (const auto& [key, value] : w.meta)
    if (key.rfind("cryptomatte/", 0) == 0) {
      EXPECT_EQ(meta.count(key) ? meta.at(key) : "", value) << key;
    }
}

// A checkpoint would resume the running sums without the id counts: refused
// with one line naming --aov, before rendering.
TEST(IdAovs, CheckpointsAndResumeAreRefused) {
  const TempDir dir;
  const std::string scene = writeScene(dir), out = (dir / "a.exr").string();
  for (const std::vector<std::string>& extra :
       {std::vector<std::string>{"--checkpoint", "60"}, std::vector<std::string>{"--resume", out}}) {
    std::vector<std::string> args = renderArgs(scene, out, 4);
    args.insert(args.end(), extra.begin(), extra.end());
    const RunResult r = runLensrt(args);
    EXPECT_NE(r.status, 0);
    EXPECT_EQ(cli::lines(r.err).size(), 1u) << r.err;
    EXPECT_NE(r.err.find("--aov"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("checkpointed or resumed"), std::string::npos) << r.err;
  }
}

}  // namespace
}  // namespace lensrt
