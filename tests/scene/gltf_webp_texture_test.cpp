// EXT_texture_webp: a texture's WebP image, decoded through the OpenImageIO
// plugin, comes before its PNG/JPEG fallback; the fallback serves when the
// WebP cannot be decoded; what a WebP header declares is held to the texture
// limits before decoding; and other formats the plugin reads (TIFF) are
// recognised by their content.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <vector>

#include "core/error.h"
#include "image/oiio_plugin.h"
#include "gltf_test_builder.h"
#include "oiio_plugin_for_tests.h"
#include "scene/gltf_loader.h"

namespace lensrt {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::GltfBuilder;

constexpr float kCodes[3] = {200, 100, 50};  // the WebP's colour, 8-bit sRGB codes

float srgbToLinear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

// The bytes of a 4x4 image of kCodes written through the plugin (to `path`).
std::vector<std::uint8_t> solidImage(const fs::path& path, const std::string& format, int bits) {
  std::vector<float> pixels;
  for (int i = 0; i < 16; ++i)
    for (const float code : kCodes) pixels.push_back(code / 255.0f);
  PluginWriteOptions options;
  options.format = format;
  options.bits = bits;
  options.quality = format == "webp" ? 95 : 0;
  OiioPlugin::get(path.string(), "the test").write(path, pixels, 4, 4, 3, options);
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string dataUri(const std::string& mime, const std::vector<std::uint8_t>& bytes) {
  return "data:" + mime + ";base64," + test::base64(bytes);
}

// A textured square whose texture 0 is `texture` over `images`.
GltfBuilder texturedSquare(const json& images, const json& texture) {
  GltfBuilder b;
  b.doc["extensionsUsed"] = {"EXT_texture_webp"};
  b.doc["images"] = images;
  b.doc["textures"] = json::array({texture});
  b.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
  b.node({{"mesh", b.square(0)}});
  return b;
}

const json kPngFallback = {{"uri", std::string("data:image/png;base64,") + test::kTwoTexelPngBase64}};
const json kWebPWithFallback = {{"source", 0}, {"extensions", {{"EXT_texture_webp", {{"source", 1}}}}}};

// The scene written to `dir` (by default a fresh one: test::testDir() empties it).
SceneDesc load(const GltfBuilder& b, Warnings& w, const fs::path& dir = test::testDir()) {
  return loadGltf(test::writeFile(dir / "scene.gltf", b.json()), -1, w);
}

void expectWebPColour(const Texture& t) {
  ASSERT_EQ(t.width, 4);
  ASSERT_EQ(t.height, 4);
  const Vec4f texel = t.texels[5];
  const float rgb[3] = {texel.x, texel.y, texel.z};
  for (int c = 0; c < 3; ++c)  // lossy WebP: within 2 codes
    EXPECT_NEAR(rgb[c], srgbToLinear(kCodes[c] / 255.0f), 0.01f) << c;
  EXPECT_EQ(texel.w, 1.0f);
}

TEST(GltfWebPTexture, TheWebPImageComesBeforeItsFallback) {
  if (!test::useBuiltOiioPlugin()) GTEST_SKIP() << "built without OpenImageIO";
  const json webp = {{"uri", dataUri("image/webp", solidImage(test::testDir() / "tex.webp", "webp", 8))}};
  Warnings w;
  const SceneDesc d = load(texturedSquare(json::array({kPngFallback, webp}), kWebPWithFallback), w);
  EXPECT_TRUE(w.all().empty()) << *w.all().begin();
  const TextureRef& ref = d.materials.at(0).baseColorTexture;
  ASSERT_TRUE(ref.valid());
  expectWebPColour(d.textures.at(std::size_t(ref.texture)));
  EXPECT_EQ(d.textures.at(std::size_t(ref.texture)).name, "#1");
}

TEST(GltfWebPTexture, AWebPFileWithoutFallbackUnderARequiredExtension) {
  if (!test::useBuiltOiioPlugin()) GTEST_SKIP() << "built without OpenImageIO";
  const fs::path dir = test::testDir();
  solidImage(dir / "tex.webp", "webp", 8);
  GltfBuilder b = texturedSquare(json::array({{{"uri", "tex.webp"}}}),
                                 {{"extensions", {{"EXT_texture_webp", {{"source", 0}}}}}});
  b.doc["extensionsRequired"] = {"EXT_texture_webp"};
  Warnings w;
  const SceneDesc d = load(b, w, dir);
  EXPECT_TRUE(w.all().empty()) << *w.all().begin();
  const TextureRef& ref = d.materials.at(0).baseColorTexture;
  ASSERT_TRUE(ref.valid());
  expectWebPColour(d.textures.at(std::size_t(ref.texture)));
  EXPECT_EQ(d.textures.at(std::size_t(ref.texture)).name, "tex.webp");
}

// "RIFF", a size, "WEBP", then a VP8 chunk of noise.
const std::vector<std::uint8_t> kCorruptWebP = {'R', 'I', 'F', 'F', 24,  0,  0, 0,    'W',  'E', 'B',
                                                'P', 'V', 'P', '8', ' ', 12, 0, 0,    0,    1,   2,
                                                3,   4,   5,   6,   7,   8,  9, 0x9d, 0x01, 0x2a};

TEST(GltfWebPTexture, ACorruptWebPGivesWayToItsFallbackWithAWarning) {
  if (!test::useBuiltOiioPlugin()) GTEST_SKIP() << "built without OpenImageIO";
  Warnings w;
  const SceneDesc d =
      load(texturedSquare(json::array({kPngFallback, {{"uri", dataUri("image/webp", kCorruptWebP)}}}),
                          kWebPWithFallback),
           w);
  EXPECT_EQ(w.all(),
            (std::set<std::string>{"texture image '#1' could not be decoded; using its fallback '#0'"}));
  const TextureRef& ref = d.materials.at(0).baseColorTexture;
  ASSERT_TRUE(ref.valid());
  EXPECT_EQ(d.textures.at(std::size_t(ref.texture)).width, 2);  // the PNG
}

TEST(GltfWebPTexture, ACorruptWebPWithoutFallbackLeavesTheFactor) {
  if (!test::useBuiltOiioPlugin()) GTEST_SKIP() << "built without OpenImageIO";
  Warnings w;
  const SceneDesc d = load(texturedSquare(json::array({{{"uri", dataUri("image/webp", kCorruptWebP)}}}),
                                          {{"extensions", {{"EXT_texture_webp", {{"source", 0}}}}}}),
                           w);
  EXPECT_EQ(
      w.all(),
      (std::set<std::string>{"texture image '#0' could not be decoded; using the material factor only"}));
  EXPECT_FALSE(d.materials.at(0).baseColorTexture.valid());
}

// A VP8X header declaring a 16384x16384 canvas in 30 bytes: refused on the
// header, before the decoder allocates a gigabyte for it.
TEST(GltfWebPTexture, AWebPDeclaringMoreTexelsThanATextureMayHaveIsAnError) {
  if (!test::useBuiltOiioPlugin()) GTEST_SKIP() << "built without OpenImageIO";
  const std::vector<std::uint8_t> huge = {'R', 'I', 'F', 'F', 22,   0,    0,    0,    'W',  'E',
                                          'B', 'P', 'V', 'P', '8',  'X',  10,   0,    0,    0,
                                          0,   0,   0,   0,   0xff, 0x3f, 0x00, 0xff, 0x3f, 0x00};
  GltfBuilder b = texturedSquare(json::array({{{"uri", dataUri("image/webp", huge)}}}),
                                 {{"extensions", {{"EXT_texture_webp", {{"source", 0}}}}}});
  Warnings w;
  try {
    load(b, w);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.message(),
              "texture image '#0' declares 16384x16384 texels, more than the 128 Mtexels a texture "
              "may have");
  }
}

TEST(GltfWebPTexture, AnExtensionWithoutAnImageIsIgnoredWithAWarning) {
  if (!test::useBuiltOiioPlugin()) GTEST_SKIP() << "built without OpenImageIO";
  Warnings w;
  const SceneDesc d =
      load(texturedSquare(json::array({kPngFallback}),
                          {{"source", 0}, {"extensions", {{"EXT_texture_webp", {{"source", 7}}}}}}),
           w);
  EXPECT_EQ(w.all(),
            (std::set<std::string>{"texture 0: EXT_texture_webp has no valid image source; ignored"}));
  EXPECT_TRUE(d.materials.at(0).baseColorTexture.valid());
}

TEST(GltfWebPTexture, ADataUriThatIsNotBase64LeavesTheFactor) {
  Warnings w;
  const SceneDesc d = load(texturedSquare(json::array({{{"uri", "data:image/webp;base64,UklG@RiQ="}}}),
                                          {{"extensions", {{"EXT_texture_webp", {{"source", 0}}}}}}),
                           w);
  EXPECT_EQ(w.all(),
            (std::set<std::string>{
                "texture image '#0' is a data: URI without base64 data; using the material factor only"}));
  EXPECT_FALSE(d.materials.at(0).baseColorTexture.valid());
}

TEST(GltfWebPTexture, ATiffTextureIsRecognisedByItsContent) {
  if (!test::useBuiltOiioPlugin()) GTEST_SKIP() << "built without OpenImageIO";
  Warnings w;
  const SceneDesc d =
      load(texturedSquare(
               json::array(
                   {{{"uri", dataUri("image/tiff", solidImage(test::testDir() / "tex.tif", "tiff", 16))}}}),
               {{"source", 0}}),
           w);
  EXPECT_TRUE(w.all().empty()) << *w.all().begin();
  const TextureRef& ref = d.materials.at(0).baseColorTexture;
  ASSERT_TRUE(ref.valid());
  const Texture& t = d.textures.at(std::size_t(ref.texture));
  const float rgb[3] = {t.texels[5].x, t.texels[5].y, t.texels[5].z};
  for (int c = 0; c < 3; ++c)  // 16-bit, lossless
    EXPECT_NEAR(rgb[c], srgbToLinear(kCodes[c] / 255.0f), 1e-4f) << c;
}

}  // namespace
}  // namespace lensrt
