// Texture slots as glTF describes them: KHR_texture_transform, UV sets,
// sampler wrap and filter modes, and COLOR_0 vertex colours, against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <set>
#include <vector>

#include "gltf_test_builder.h"
#include "scene/gltf_loader.h"
#include "scene/render_scene.h"
#include "scene/texture_sampling.h"

namespace lensrt {
namespace {

using nlohmann::json;
using test::GltfBuilder;

SceneDesc load(const GltfBuilder& b, Warnings& w) {
  return loadGltf(test::writeFile(test::testDir() / "scene.gltf", b.json()), -1, w);
}

// The 2x1 test PNG: texel 0 alpha 0 (u < 0.5), texel 1 alpha 1.
void addPngImage(GltfBuilder& b, const json& sampler) {
  b.doc["images"] = {{{"uri", std::string("data:image/png;base64,") + test::kTwoTexelPngBase64}}};
  // json::array: a braced single json is an array under GCC but a copy under clang.
  b.doc["samplers"] = json::array({sampler});
  b.doc["textures"] = {{{"source", 0}, {"sampler", 0}}};
}

const json kNearestClamp = {{"magFilter", 9728}, {"wrapS", 33071}, {"wrapT", 33071}};

// A masked square at z = 1 over an opaque floor at z = 0: which of the two a
// ray down at (x, y) hits says whether the mask's texel there is opaque.
bool maskOpaqueAt(const RenderScene& scene, float x, float y) {
  const auto hit = scene.intersect({{x, y, 5}, {0, 0, -1}});
  EXPECT_TRUE(hit);
  return hit && hit->instance == 0;
}

TEST(GltfTexture, TransformIsOffsetTimesRotationTimesScale) {
  GltfBuilder b;
  addPngImage(b, kNearestClamp);
  const json transform = {{"offset", {0.5, -0.25}}, {"rotation", 1.5707963267948966}, {"scale", {2, 3}}};
  b.doc["extensionsUsed"] = {"KHR_texture_transform"};
  b.doc["materials"] = {
      {{"pbrMetallicRoughness",
        {{"baseColorTexture", {{"index", 0}, {"extensions", {{"KHR_texture_transform", transform}}}}}}}}};
  b.node({{"mesh", b.square(0)}});
  Warnings w;
  const SceneDesc d = load(b, w);
  EXPECT_TRUE(w.all().empty());
  const TextureRef& ref = d.materials.at(0).baseColorTexture;
  ASSERT_TRUE(ref.valid());
  // Scale (2u, 3v), rotate by R = [cos sin; -sin cos] at 90 degrees -> (3v, -2u),
  // then offset: (3v + 0.5, -2u - 0.25).
  for (const Vec2f uv : {Vec2f{0.25f, 0.1f}, Vec2f{0, 0}, Vec2f{1, 1}, Vec2f{-0.5f, 0.75f}}) {
    const Vec2f t = ref.uv(uv, {9, 9});
    EXPECT_NEAR(t.x, 3 * uv.y + 0.5f, 1e-6f);
    EXPECT_NEAR(t.y, -2 * uv.x - 0.25f, 1e-6f);
  }
}

TEST(GltfTexture, OffsetMovesTheMaskOnTheSurface) {
  // u = x on the square; an offset of 0.5 (with REPEAT) moves the opaque texel to x < 0.5.
  GltfBuilder b;
  addPngImage(b, {{"magFilter", 9728}});
  b.doc["materials"] = {
      {{"alphaMode", "MASK"},
       {"pbrMetallicRoughness",
        {{"baseColorTexture",
          {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"offset", {0.5, 0}}}}}}}}}}}};
  b.node({{"mesh", b.square(0)}, {"translation", {0, 0, 1}}});
  b.node({{"mesh", b.square()}});
  Warnings w;
  const RenderScene scene(load(b, w));
  EXPECT_TRUE(maskOpaqueAt(scene, 0.25f, 0.5f));   // u' = 0.75: texel 1
  EXPECT_FALSE(maskOpaqueAt(scene, 0.75f, 0.5f));  // u' = 1.25 repeats to 0.25: texel 0
}

TEST(GltfTexture, TexCoordOneReadsTheSecondUvSet) {
  // TEXCOORD_1 = 1 - x: the mask is mirrored relative to TEXCOORD_0's.
  for (const bool viaExtension : {false, true}) {
    GltfBuilder b;
    addPngImage(b, kNearestClamp);
    json info = {{"index", 0}};
    if (viaExtension)
      info["extensions"] = {{"KHR_texture_transform", {{"texCoord", 1}}}};
    else
      info["texCoord"] = 1;
    b.doc["materials"] = {{{"alphaMode", "MASK"}, {"pbrMetallicRoughness", {{"baseColorTexture", info}}}}};
    const int pos = b.floats({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, "VEC3");
    const int uv0 = b.floats({0, 1, 1, 1, 1, 0, 0, 0}, "VEC2");
    const int uv1 = b.floats({1, 1, 0, 1, 0, 0, 1, 0}, "VEC2");
    const int idx = b.u16({0, 1, 2, 0, 2, 3});
    b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", pos}, {"TEXCOORD_0", uv0}, {"TEXCOORD_1", uv1}}},
                             {"indices", idx},
                             {"material", 0}})},
            {"translation", {0, 0, 1}}});
    b.node({{"mesh", b.square()}});
    Warnings w;
    const SceneDesc d = load(b, w);
    EXPECT_TRUE(w.all().empty());
    EXPECT_EQ(d.materials.at(0).baseColorTexture.texCoord, 1);
    ASSERT_EQ(d.meshes.at(0).uvs1.size(), 4u);
    const RenderScene scene(d);
    EXPECT_TRUE(maskOpaqueAt(scene, 0.25f, 0.5f)) << viaExtension;  // TEXCOORD_1 u = 0.75
    EXPECT_FALSE(maskOpaqueAt(scene, 0.75f, 0.5f)) << viaExtension;
    const auto hit = scene.intersect({{0.25f, 0.5f, 5}, {0, 0, -1}});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->uv.x, 0.25f, 1e-5f);
    EXPECT_NEAR(hit->uv1.x, 0.75f, 1e-5f);
  }
}

TEST(GltfTexture, MissingSecondUvSetWarns) {
  GltfBuilder b;
  addPngImage(b, kNearestClamp);
  b.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}, {"texCoord", 1}}}}}}};
  b.node({{"mesh", b.square(0)}});
  Warnings w;
  load(b, w);
  EXPECT_EQ(
      w.all(),
      (std::set<std::string>{
          "mesh '#0': its material reads TEXCOORD_1, which the primitive does not have; using (0, 0)"}));
}

TEST(GltfTexture, SamplerModesMapPerAxis) {
  GltfBuilder b;
  b.doc["images"] = {{{"uri", std::string("data:image/png;base64,") + test::kTwoTexelPngBase64}}};
  b.doc["samplers"] = {{{"wrapS", 33648}, {"wrapT", 33071}, {"magFilter", 9729}},
                       {{"wrapS", 33071}, {"wrapT", 10497}, {"minFilter", 9984}},
                       {{"minFilter", 9987}}};
  b.doc["textures"] = {
      {{"source", 0}, {"sampler", 0}}, {{"source", 0}, {"sampler", 1}}, {{"source", 0}, {"sampler", 2}}};
  b.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}},
                        {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 1}}}}}},
                        {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 2}}}}}}};
  b.node({{"mesh", b.square(0)}});
  b.node({{"mesh", b.square(1)}});
  b.node({{"mesh", b.square(2)}});
  Warnings w;
  const SceneDesc d = load(b, w);
  EXPECT_TRUE(w.all().empty());
  const Texture& mirrorClamp = d.textures.at(d.materials[0].baseColorTexture.texture);
  EXPECT_TRUE(mirrorClamp.wrapRepeatS && mirrorClamp.mirrorS);
  EXPECT_FALSE(mirrorClamp.wrapRepeatT);
  EXPECT_FALSE(mirrorClamp.nearest);
  const Texture& clampRepeat = d.textures.at(d.materials[1].baseColorTexture.texture);
  EXPECT_FALSE(clampRepeat.wrapRepeatS);
  EXPECT_TRUE(clampRepeat.wrapRepeatT && !clampRepeat.mirrorT);
  EXPECT_TRUE(clampRepeat.nearest);  // no magFilter: NEAREST_MIPMAP_NEAREST decides
  EXPECT_FALSE(d.textures.at(d.materials[2].baseColorTexture.texture).nearest);
}

TEST(GltfTexture, InvalidSamplerValuesWarnAndUseDefaults) {
  GltfBuilder b;
  addPngImage(b, {{"wrapS", 12345}, {"magFilter", 1}, {"minFilter", 9730}});
  b.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
  b.node({{"mesh", b.square(0)}});
  Warnings w;
  const SceneDesc d = load(b, w);
  EXPECT_EQ(w.all(),
            (std::set<std::string>{"texture sampler 0: wrapS 12345 is not a glTF wrap mode; using REPEAT",
                                   "texture sampler 0: magFilter 1 is not a glTF filter; using LINEAR",
                                   "texture sampler 0: minFilter 9730 is not a glTF filter; ignored"}));
  const Texture& t = d.textures.at(0);
  EXPECT_TRUE(t.wrapRepeatS && !t.mirrorS && !t.nearest);
}

TEST(GltfTexture, MalformedTransformsWarnAndKeepTheRest) {
  GltfBuilder b;
  addPngImage(b, kNearestClamp);
  const json transform = {{"offset", {0.5}}, {"rotation", "quarter"}, {"scale", {2, 2}}, {"texCoord", -1}};
  b.doc["materials"] = {
      {{"pbrMetallicRoughness",
        {{"baseColorTexture", {{"index", 0}, {"extensions", {{"KHR_texture_transform", transform}}}}}}}}};
  b.node({{"mesh", b.square(0)}});
  Warnings w;
  const SceneDesc d = load(b, w);
  const std::string where = "material '#0' baseColorTexture: KHR_texture_transform ";
  EXPECT_EQ(w.all(), (std::set<std::string>{where + "offset is not two numbers; ignored",
                                            where + "rotation is not a number of radians; ignored",
                                            where + "texCoord is not an index; ignored"}));
  const TextureRef& ref = d.materials.at(0).baseColorTexture;
  EXPECT_EQ(ref.texCoord, 0);
  EXPECT_NEAR(ref.uv({0.25f, 0.5f}, {}).x, 0.5f, 1e-6f);  // the scale still applies
  EXPECT_NEAR(ref.uv({0.25f, 0.5f}, {}).y, 1.0f, 1e-6f);
}

TEST(GltfTexture, TexCoordBeyondOneFallsBackToTheFactor) {
  GltfBuilder b;
  addPngImage(b, kNearestClamp);
  b.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}, {"texCoord", 2}}}}}}};
  b.node({{"mesh", b.square(0)}});
  Warnings w;
  const SceneDesc d = load(b, w);
  EXPECT_FALSE(d.materials.at(0).baseColorTexture.valid());
  EXPECT_EQ(w.all(),
            (std::set<std::string>{"material '#0' baseColorTexture: texCoord 2 is not supported (only "
                                   "TEXCOORD_0 and TEXCOORD_1); using the factor only"}));
}

// --- Wrap and filter modes of the sampler, at u = -0.25 and 1.25 ---

// 2x1: texel 0 = 0, texel 1 = 1 in red; one row, so v does not matter.
Texture twoTexels(bool nearest, bool repeat, bool mirror) {
  Texture t;
  t.width = 2;
  t.height = 1;
  t.texels = {{0, 0, 0, 1}, {1, 0, 0, 1}};
  t.nearest = nearest;
  t.wrapRepeatS = t.wrapRepeatT = repeat;
  t.mirrorS = t.mirrorT = mirror;
  return t;
}

TEST(GltfTexture, WrapModesAtMinusAQuarterAndOneAndAQuarter) {
  // REPEAT: -0.25 -> 0.75 (texel 1), 1.25 -> 0.25 (texel 0).
  const Texture repeat = twoTexels(true, true, false);
  EXPECT_EQ(sampleTexture(repeat, {-0.25f, 0.5f}).x, 1.0f);
  EXPECT_EQ(sampleTexture(repeat, {1.25f, 0.5f}).x, 0.0f);
  // CLAMP_TO_EDGE: the nearest edge texel.
  const Texture clamp = twoTexels(true, false, false);
  EXPECT_EQ(sampleTexture(clamp, {-0.25f, 0.5f}).x, 0.0f);
  EXPECT_EQ(sampleTexture(clamp, {1.25f, 0.5f}).x, 1.0f);
  // MIRRORED_REPEAT: -0.25 -> 0.25 (texel 0), 1.25 -> 0.75 (texel 1).
  const Texture mirror = twoTexels(true, true, true);
  EXPECT_EQ(sampleTexture(mirror, {-0.25f, 0.5f}).x, 0.0f);
  EXPECT_EQ(sampleTexture(mirror, {1.25f, 0.5f}).x, 1.0f);
  // Bilinear at the same points: -0.25 and 1.25 are texel centres (of the
  // wrapped image) for repeat and mirror, and clamp holds the edge value.
  EXPECT_NEAR(sampleTexture(twoTexels(false, true, false), {-0.25f, 0.5f}).x, 1.0f, 1e-6f);
  EXPECT_NEAR(sampleTexture(twoTexels(false, true, true), {1.25f, 0.5f}).x, 1.0f, 1e-6f);
  EXPECT_NEAR(sampleTexture(twoTexels(false, false, false), {1.25f, 0.5f}).x, 1.0f, 1e-6f);
}

TEST(GltfTexture, NearestJumpsAtTheTexelBoundaryLinearIsContinuous) {
  const Texture nearest = twoTexels(true, false, false);
  const Texture linear = twoTexels(false, false, false);
  // The boundary between texel 0 and 1 is u = 0.5.
  EXPECT_EQ(sampleTexture(nearest, {0.499f, 0.5f}).x, 0.0f);
  EXPECT_EQ(sampleTexture(nearest, {0.501f, 0.5f}).x, 1.0f);
  EXPECT_NEAR(sampleTexture(linear, {0.5f, 0.5f}).x, 0.5f, 1e-6f);
  // Bilinear is linear between the centres 0.25 and 0.75: value = 2 (u - 0.25).
  EXPECT_NEAR(sampleTexture(linear, {0.499f, 0.5f}).x, 2 * (0.499f - 0.25f), 1e-5f);
  EXPECT_NEAR(sampleTexture(linear, {0.6f, 0.5f}).x, 2 * (0.6f - 0.25f), 1e-5f);
}

// --- COLOR_0 ---

GltfBuilder colouredSquare(const std::function<int(GltfBuilder&)>& colours) {
  GltfBuilder b;
  const int pos = b.floats({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, "VEC3");
  const int colour = colours(b);
  b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", pos}, {"COLOR_0", colour}}},
                           {"indices", b.u16({0, 1, 2, 0, 2, 3})}})}});
  return b;
}

TEST(GltfTexture, VertexColoursDecodeNormalizedIntegers) {
  Warnings w;
  const SceneDesc u8 =
      load(colouredSquare([](GltfBuilder& b) {
             return b.u8({255, 0, 51, 255, 0, 255, 0, 128, 0, 0, 255, 0, 255, 255, 255, 255}, "VEC4", true);
           }),
           w);
  ASSERT_EQ(u8.meshes.at(0).colors.size(), 4u);
  EXPECT_EQ(u8.meshes[0].colors[0], (Vec4f{1, 0, 0.2f, 1}));  // 255 -> 1.0, 51 -> 0.2 exactly
  EXPECT_NEAR(u8.meshes[0].colors[1].w, 128 / 255.0f, 1e-7f);
  const SceneDesc u16 =
      load(colouredSquare([](GltfBuilder& b) {
             return b.u16({65535, 0, 0, 65535, 0, 0, 65535, 0, 0, 0, 0, 65535}, "VEC3", true);
           }),
           w);
  ASSERT_EQ(u16.meshes.at(0).colors.size(), 4u);
  EXPECT_EQ(u16.meshes[0].colors[0], (Vec4f{1, 0, 0, 1}));  // VEC3: alpha 1
  EXPECT_EQ(u16.meshes[0].colors[3], (Vec4f{0, 0, 1, 1}));
  const SceneDesc f = load(colouredSquare([](GltfBuilder& b) {
                             return b.floats({0.5f, 0.25f, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1}, "VEC3");
                           }),
                           w);
  EXPECT_EQ(f.meshes.at(0).colors.at(0), (Vec4f{0.5f, 0.25f, 1, 1}));
  EXPECT_TRUE(w.all().empty());
  // Interpolated at a hit: the barycentric mix of the corners' colours.
  const RenderScene scene(f);
  const auto hit = scene.intersect({{0.5f, 0.25f, 5}, {0, 0, -1}});
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->color.x, 0.5f * 0.5f + 0.25f * 1 + 0.25f * 1, 1e-5f);  // w0 = 0.5, w1 = 0.25, w2 = 0.25
}

TEST(GltfTexture, VertexColoursOfTheWrongTypeWarnAndAreIgnored) {
  for (const auto& make : std::vector<std::function<int(GltfBuilder&)>>{
           [](GltfBuilder& b) { return b.u8(std::vector<std::uint8_t>(16, 255), "VEC4", false); },
           [](GltfBuilder& b) {
             return b.floats({1, 1, 1, 1, 1, 1, 1, 1}, "VEC2");
           }}) {
    Warnings w;
    const SceneDesc d = load(colouredSquare(make), w);
    EXPECT_TRUE(d.meshes.at(0).colors.empty());
    EXPECT_EQ(w.all(),
              (std::set<std::string>{"mesh '#0': COLOR_0 is not a VEC3 or VEC4 of floats or normalized "
                                     "unsigned bytes or shorts; ignored"}));
  }
}

TEST(GltfTexture, VertexAlphaFeedsTheMask) {
  // Corners 0 and 3 (x = 0) transparent, 1 and 2 (x = 1) opaque: alpha = x.
  GltfBuilder b = colouredSquare([](GltfBuilder& g) {
    return g.floats({1, 1, 1, 0, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0}, "VEC4");
  });
  b.doc["materials"] = {{{"alphaMode", "MASK"}, {"alphaCutoff", 0.5}}};
  b.doc["meshes"][0]["primitives"][0]["material"] = 0;
  Warnings w;
  const RenderScene scene(load(b, w));
  EXPECT_FALSE(scene.intersect({{0.3f, 0.5f, 5}, {0, 0, -1}}));
  EXPECT_TRUE(scene.intersect({{0.7f, 0.5f, 5}, {0, 0, -1}}));
}

}  // namespace
}  // namespace lensrt
