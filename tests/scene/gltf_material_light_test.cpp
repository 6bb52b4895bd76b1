// Loader materials, textures, alpha, extensions and KHR_lights_punctual units.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <tuple>
#include <vector>

#include "core/constants.h"
#include "core/error.h"
#include "gltf_test_builder.h"
#include "scene/gltf_loader.h"
#include "scene/render_scene.h"

namespace lensrt {
namespace {

using nlohmann::json;
using test::GltfBuilder;

SceneDesc load(const GltfBuilder& b, Warnings& w) {
  return loadGltf(test::writeFile(test::testDir() / "scene.gltf", b.json()), -1, w);
}

// IEC 61966-2-1 decoding, written out independently of the loader.
double srgbToLinear(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

void addPngImage(GltfBuilder& b) {
  b.doc["images"] = {{{"uri", std::string("data:image/png;base64,") + test::kTwoTexelPngBase64}}};
  b.doc["samplers"] = {{{"magFilter", 9728}, {"wrapS", 33071}, {"wrapT", 33071}}};
  b.doc["textures"] = {{{"source", 0}, {"sampler", 0}}};
}

TEST(GltfMaterial, ColourTexturesDecodeSrgbOthersStayLinear) {
  GltfBuilder b;
  addPngImage(b);
  b.doc["materials"] = {{{"pbrMetallicRoughness",
                          {{"baseColorTexture", {{"index", 0}}},
                           {"baseColorFactor", {0.5, 0.5, 0.5, 1}},
                           {"metallicRoughnessTexture", {{"index", 0}}},
                           {"metallicFactor", 0.25},
                           {"roughnessFactor", 0.75}}},
                         {"emissiveTexture", {{"index", 0}}},
                         {"normalTexture", {{"index", 0}, {"scale", 0.5}}},
                         {"doubleSided", true}}};
  b.node({{"mesh", b.square(0)}});
  Warnings w;
  const SceneDesc d = load(b, w);
  EXPECT_TRUE(w.all().empty());
  ASSERT_EQ(d.materials.size(), 1u);
  const Material& m = d.materials[0];
  EXPECT_EQ(m.baseColor, (Vec4f{0.5f, 0.5f, 0.5f, 1}));
  EXPECT_EQ(m.metallic, 0.25f);
  EXPECT_EQ(m.roughness, 0.75f);
  EXPECT_EQ(m.normalScale, 0.5f);
  EXPECT_TRUE(m.doubleSided);
  ASSERT_EQ(d.textures.size(), 2u);  // one sRGB decoding, one linear, of the same image
  EXPECT_EQ(m.baseColorTexture.texture, m.emissiveTexture.texture);
  EXPECT_EQ(m.metallicRoughnessTexture.texture, m.normalTexture.texture);
  const Texture& colour = d.textures[m.baseColorTexture.texture];
  const Texture& data = d.textures[m.metallicRoughnessTexture.texture];
  ASSERT_EQ(colour.width, 2);
  ASSERT_EQ(colour.height, 1);
  EXPECT_NEAR(colour.texels[0].x, srgbToLinear(128 / 255.0), 1e-6);
  EXPECT_NEAR(colour.texels[0].w, 0.0, 1e-7);  // alpha is never sRGB-decoded
  EXPECT_NEAR(colour.texels[1].y, 1.0, 1e-6);
  EXPECT_NEAR(data.texels[0].y, 128 / 255.0, 1e-6);
  EXPECT_TRUE(colour.nearest);
  EXPECT_FALSE(colour.wrapRepeatS);
}

TEST(GltfMaterial, EmissiveStrengthFoldsIntoEmissive) {
  GltfBuilder b;
  b.doc["extensionsUsed"] = {"KHR_materials_emissive_strength"};
  b.doc["materials"] = {{{"emissiveFactor", {1, 0.5, 0}},
                         {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 10}}}}}}};
  b.node({{"mesh", b.square(0)}});
  Warnings w;
  const SceneDesc d = load(b, w);
  EXPECT_TRUE(w.all().empty());
  EXPECT_EQ(d.materials[0].emissive, (Vec3f{10, 5, 0}));
}

TEST(GltfMaterial, AlphaMaskCutsOutTransparentTexels) {
  GltfBuilder b;
  addPngImage(b);
  b.doc["materials"] = {{{"alphaMode", "MASK"},
                         {"alphaCutoff", 0.5},
                         {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
  b.node({{"mesh", b.square(0)}, {"translation", {0, 0, 1}}});
  b.node({{"mesh", b.square()}});  // opaque floor below
  Warnings w;
  const RenderScene scene(load(b, w));
  // u = x on the square: texel 0 (x < 0.5) has alpha 0, texel 1 alpha 1.
  const auto through = scene.intersect({{0.25f, 0.5f, 5}, {0, 0, -1}});
  const auto blocked = scene.intersect({{0.75f, 0.5f, 5}, {0, 0, -1}});
  ASSERT_TRUE(through && blocked);
  EXPECT_EQ(through->instance, 1);
  EXPECT_EQ(blocked->instance, 0);
}

TEST(GltfMaterial, GlbBufferViewImageFeedsTheMask) {
  GltfBuilder b;
  // The PNG bytes live in the binary chunk, as exporters write .glb files.
  const char* png = test::kTwoTexelPngBase64;
  std::vector<std::uint8_t> bytes;
  {
    const std::string table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::uint32_t acc = 0;
    int bits = 0;
    for (const char* c = png; *c && *c != '='; ++c) {
      acc = (acc << 6) | static_cast<std::uint32_t>(table.find(*c));
      bits += 6;
      if (bits >= 8) {
        bits -= 8;
        bytes.push_back(static_cast<std::uint8_t>(acc >> bits));
      }
    }
  }
  const int view = b.view(bytes.data(), bytes.size());
  b.doc["images"] = {{{"bufferView", view}, {"mimeType", "image/png"}}};
  b.doc["textures"] = {{{"source", 0}}};
  b.doc["materials"] = {
      {{"alphaMode", "MASK"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
  b.node({{"mesh", b.square(0)}});
  Warnings w;
  const RenderScene scene(loadGltf(test::writeFile(test::testDir() / "scene.glb", b.glb()), -1, w));
  EXPECT_TRUE(w.all().empty());
  EXPECT_FALSE(scene.intersect({{0.2f, 0.5f, 5}, {0, 0, -1}}));
  EXPECT_TRUE(scene.intersect({{0.8f, 0.5f, 5}, {0, 0, -1}}));
}

TEST(GltfMaterial, MissingOrCorruptImagesWarnAndKeepTheFactor) {
  GltfBuilder b;
  b.doc["images"] = {{{"uri", "missing.png"}}, {{"uri", "data:image/png;base64,AAAAAAAA"}}};
  b.doc["textures"] = {{{"source", 0}}, {{"source", 1}}, {{"source", 9}}};
  b.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}},
                         {"emissiveTexture", {{"index", 1}}},
                         {"normalTexture", {{"index", 2}}}}};
  b.node({{"mesh", b.square(0)}});
  Warnings w;
  const SceneDesc d = load(b, w);
  EXPECT_FALSE(d.materials[0].baseColorTexture.valid());
  EXPECT_FALSE(d.materials[0].emissiveTexture.valid());
  EXPECT_FALSE(d.materials[0].normalTexture.valid());
  EXPECT_TRUE(d.textures.empty());
  EXPECT_EQ(w.all().count("texture image 'missing.png' could not be read; using the material factor only"),
            1u);
  EXPECT_EQ(w.all().count("texture image '#1' could not be decoded; using the material factor only"), 1u);
  EXPECT_EQ(w.all().count("material '#0': texture 2 has no usable image; using the factor only"), 1u);
  EXPECT_EQ(w.all().size(), 3u);  // nothing more from tinygltf about the same images
}

// A tiny PNG or JPEG can declare a huge image (a 1 MB PNG of zeros declaring
// 16000x16000 took 5 GB); the header is read before decoding allocates, and
// such an image is an error naming it (an untrusted scene's resource limit).
TEST(GltfMaterial, ImagesDeclaringOverAHundredMegatexelsAreRefused) {
  // PNG signature, IHDR length and type, width 20000, height 10000: nothing decodable follows.
  const std::vector<std::uint8_t> png{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0,    13,
                                      'I',  'H', 'D', 'R', 0,    0,    0x4e, 0x20, 0, 0, 0x27, 0x10};
  // JPEG: SOI, an APP0 segment of 4 bytes, SOF0 with height 12000 and width 12000.
  const std::vector<std::uint8_t> jpeg{0xFF, 0xD8, 0xFF, 0xE0, 0,    4, 0, 0,    0xFF, 0xC0, 0,    17,
                                       8,    0x2e, 0xe0, 0x2e, 0xe0, 3, 1, 0x22, 0,    2,    0x11, 1};
  for (const auto& [name, bytes, size] :
       {std::tuple{"wide.png", png, "20000x10000"}, std::tuple{"square.jpg", jpeg, "12000x12000"}}) {
    GltfBuilder b;
    b.doc["images"] = {{{"uri", name}}};
    b.doc["textures"] = {{{"source", 0}}};
    b.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
    b.node({{"mesh", b.square(0)}});
    const std::string gltf = b.json();  // before the files: it resets the test directory
    const std::filesystem::path dir = test::testDir();
    test::writeFile(dir / name, bytes);
    Warnings w;
    try {
      loadGltf(test::writeFile(dir / "scene.gltf", gltf), -1, w);
      ADD_FAILURE() << name << " loaded";
    } catch (const InputError& e) {
      EXPECT_EQ(e.message(), "texture image '" + std::string(name) + "' declares " + size +
                                 " texels, more than the 128 Mtexels a texture may have");
    }
  }
}

TEST(GltfMaterial, BlendLoadsWithoutWarning) {
  GltfBuilder b;
  b.doc["materials"] = {{{"alphaMode", "BLEND"}}, {{"alphaMode", "BLEND"}}};
  b.node({{"mesh", b.square(0)}});
  b.node({{"mesh", b.square(1)}});
  Warnings w;
  const SceneDesc d = load(b, w);
  EXPECT_EQ(d.materials[1].alphaMode, AlphaMode::Blend);
  EXPECT_TRUE(w.all().empty());
}

TEST(GltfMaterial, UnsupportedFeaturesEachWarnOnce) {
  GltfBuilder b;
  b.doc["extensionsUsed"] = {"KHR_materials_iridescence", "KHR_materials_anisotropy"};
  b.doc["materials"] = {{{"extensions", {{"KHR_materials_iridescence", json::object()}}}}};
  const int pos = b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  const int uv = b.floats({0, 0, 1, 0, 0, 1}, "VEC2");
  const int colour = b.floats({1, 0, 0, 0, 1, 0, 0, 0, 1}, "VEC3");
  b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", pos}, {"TEXCOORD_2", uv}, {"COLOR_1", colour}}},
                           {"material", 0},
                           {"targets", {{{"POSITION", pos}}}}})}});
  b.doc["nodes"][0]["camera"] = 0;
  b.doc["cameras"] = {
      {{"type", "orthographic"}, {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"zfar", 10}, {"znear", 0.1}}}}};
  Warnings w;
  const SceneDesc d = load(b, w);
  EXPECT_TRUE(d.cameras.at(0).orthographic);
  EXPECT_EQ(w.all(), (std::set<std::string>{
                         "extension KHR_materials_anisotropy is not supported and is ignored",
                         "extension KHR_materials_iridescence is not supported and is ignored",
                         "extra UV sets (TEXCOORD_2 and up) are ignored",
                         "vertex colours beyond COLOR_0 are ignored",
                     }));
  EXPECT_FLOAT_EQ(d.cameras.at(0).xmag, 1.0f);
  EXPECT_FLOAT_EQ(d.cameras.at(0).ymag, 1.0f);
}

// An orthographic camera keeps xmag and ymag (its aspect ratio is theirs);
// one that is zero, or too small for a float, falls back to perspective.
TEST(GltfMaterial, OrthographicCamerasKeepTheirMagnifications) {
  for (const double xmag : {2.0, 0.0, 1e-50}) {
    GltfBuilder b;
    const int pos = b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
    b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", pos}}}})}});
    b.doc["nodes"][0]["camera"] = 0;
    b.doc["cameras"] = {{{"type", "orthographic"},
                         {"orthographic", {{"xmag", xmag}, {"ymag", 0.5}, {"zfar", 10}, {"znear", 0}}}}};
    Warnings w;
    const CameraDesc cam = load(b, w).cameras.at(0);
    if (xmag > 1) {
      EXPECT_TRUE(cam.orthographic);
      EXPECT_FLOAT_EQ(cam.xmag, 2.0f);
      EXPECT_FLOAT_EQ(cam.ymag, 0.5f);
      EXPECT_FLOAT_EQ(cam.aspectRatio.value_or(0), 4.0f);
      EXPECT_TRUE(w.all().empty());
    } else {
      EXPECT_FALSE(cam.orthographic) << xmag;
      EXPECT_EQ(w.all(),
                (std::set<std::string>{"camera 'node 0': orthographic xmag and ymag must be non-zero; "
                                       "rendering it as a perspective camera (yfov 39.6 degrees)"}));
    }
  }
}

TEST(GltfMaterial, LayerExtensionsLoadTheirFactorsAndTextures) {
  GltfBuilder b;
  addPngImage(b);
  b.doc["extensionsUsed"] = {"KHR_materials_ior",    "KHR_materials_specular",  "KHR_materials_transmission",
                             "KHR_materials_volume", "KHR_materials_clearcoat", "KHR_materials_sheen",
                             "KHR_texture_transform"};
  const json transformed = {
      {"index", 0},
      {"texCoord", 0},
      {"extensions", {{"KHR_texture_transform", {{"offset", {0.5, 0}}, {"texCoord", 1}}}}}};
  b.doc["materials"] = {
      {{"name", "glass"},
       {"extensions",
        {{"KHR_materials_ior", {{"ior", 1.33}}},
         {"KHR_materials_specular",
          {{"specularFactor", 0.5},
           {"specularColorFactor", {1, 0.5, 0.25}},
           {"specularTexture", {{"index", 0}}}}},
         {"KHR_materials_transmission", {{"transmissionFactor", 0.9}, {"transmissionTexture", transformed}}},
         {"KHR_materials_volume",
          {{"thicknessFactor", 0.02}, {"attenuationDistance", 0.5}, {"attenuationColor", {0.5, 1, 1}}}}}}},
      {{"name", "coated"},
       {"extensions",
        {{"KHR_materials_clearcoat",
          {{"clearcoatFactor", 1},
           {"clearcoatRoughnessFactor", 0.25},
           {"clearcoatNormalTexture", {{"index", 0}, {"scale", 0.5}}}}},
         {"KHR_materials_sheen",
          {{"sheenColorFactor", {0.5, 0.25, 1}},
           {"sheenRoughnessFactor", 0.75},
           {"sheenColorTexture", {{"index", 0}}}}}}}}};
  b.node({{"mesh", b.square(0)}});
  b.node({{"mesh", b.square(1)}});
  Warnings w;
  const SceneDesc d = load(b, w);
  EXPECT_TRUE(w.all().empty()) << *w.all().begin();
  const Material& glass = d.materials.at(0);
  EXPECT_FLOAT_EQ(glass.ior, 1.33f);
  EXPECT_FLOAT_EQ(glass.specular, 0.5f);
  EXPECT_EQ(glass.specularColor, (Vec3f{1, 0.5f, 0.25f}));
  EXPECT_TRUE(glass.specularTexture.valid());
  EXPECT_FLOAT_EQ(glass.transmission, 0.9f);
  ASSERT_TRUE(glass.transmissionTexture.valid());
  EXPECT_EQ(glass.transmissionTexture.texCoord, 1);  // the transform's texCoord wins
  EXPECT_EQ(glass.transmissionTexture.uv({0, 0}, {0.25f, 0.5f}), (Vec2f{0.75f, 0.5f}));
  EXPECT_FALSE(glass.thinWalled());
  // sigma = -ln(colour) / distance, per metre.
  EXPECT_NEAR(glass.attenuationCoefficient().x, std::log(2.0) / 0.5, 1e-5);
  EXPECT_EQ(glass.attenuationCoefficient().y, 0.0f);
  const Material& coated = d.materials.at(1);
  EXPECT_FLOAT_EQ(coated.clearcoat, 1);
  EXPECT_FLOAT_EQ(coated.clearcoatRoughness, 0.25f);
  EXPECT_TRUE(coated.clearcoatNormalTexture.valid());
  EXPECT_FLOAT_EQ(coated.clearcoatNormalScale, 0.5f);
  EXPECT_EQ(coated.sheenColor, (Vec3f{0.5f, 0.25f, 1}));
  EXPECT_FLOAT_EQ(coated.sheenRoughness, 0.75f);
  EXPECT_TRUE(coated.sheenColorTexture.valid());
  EXPECT_TRUE(coated.thinWalled());  // no volume
  // The sheen colour texture is sRGB, the clearcoat normal map linear: two decodings.
  EXPECT_NE(coated.sheenColorTexture.texture, coated.clearcoatNormalTexture.texture);
}

TEST(GltfMaterial, LayerExtensionValuesOutOfRangeWarnAndKeepDefaults) {
  GltfBuilder b;
  b.doc["materials"] = {{{"name", "bad"},
                         {"extensions",
                          {{"KHR_materials_ior", {{"ior", 0.5}}},
                           {"KHR_materials_transmission", {{"transmissionFactor", 2}}},
                           {"KHR_materials_sheen", {{"sheenColorFactor", {1, -1, 0}}}},
                           {"KHR_materials_clearcoat", {{"clearcoatTexture", {{"index", -3}}}}}}}}};
  b.node({{"mesh", b.square(0)}});
  Warnings w;
  const SceneDesc d = load(b, w);
  const Material& m = d.materials.at(0);
  EXPECT_FLOAT_EQ(m.ior, 1.5f);
  EXPECT_EQ(m.transmission, 0.0f);
  EXPECT_EQ(m.sheenColor, (Vec3f{0, 0, 0}));
  EXPECT_FALSE(m.clearcoatTexture.valid());
  EXPECT_EQ(w.all(),
            (std::set<std::string>{
                "material 'bad': KHR_materials_ior ior is not a number in [1, 10]; ignored",
                "material 'bad': KHR_materials_transmission transmissionFactor is not a number in [0, 1]; "
                "ignored",
                "material 'bad': KHR_materials_sheen sheenColorFactor is not three non-negative numbers; "
                "ignored",
                "material 'bad': KHR_materials_clearcoat clearcoatTexture has no valid texture index; "
                "ignored",
            }));
}

// --- KHR_lights_punctual: radiometric = photometric / 683 lm/W ---

GltfBuilder lightScene(const json& light, const json& node) {
  GltfBuilder b;
  b.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  b.doc["extensions"] = {{"KHR_lights_punctual", {{"lights", {light}}}}};
  b.node({{"mesh", b.square()}});
  json n = node;
  n["extensions"] = {{"KHR_lights_punctual", {{"light", 0}}}};
  b.node(n);
  return b;
}

TEST(GltfLights, PointCandelaToWattsPerSteradian) {
  Warnings w;
  const SceneDesc d = load(lightScene({{"type", "point"}, {"intensity", 683}, {"color", {1, 0.5, 0.25}}},
                                      {{"translation", {1, 2, 3}}}),
                           w);
  ASSERT_EQ(d.lights.size(), 1u);
  const PunctualLight& l = d.lights[0];
  EXPECT_EQ(l.type, PunctualLight::Type::Point);
  EXPECT_NEAR(l.intensity.x, 1.0f, 1e-6f);
  EXPECT_NEAR(l.intensity.y, 0.5f, 1e-6f);
  EXPECT_NEAR(l.intensity.z, 0.25f, 1e-6f);
  EXPECT_EQ(l.position, (Vec3f{1, 2, 3}));
  EXPECT_EQ(l.range, 0.0f);
}

TEST(GltfLights, BlenderWattsRoundTrip) {
  // Blender exports a P-watt point lamp as P * 683 / (4 pi) cd; Cycles renders
  // it as P / (4 pi) W/sr.
  const double watts = 100;
  Warnings w;
  const SceneDesc d =
      load(lightScene({{"type", "point"}, {"intensity", watts * 683 / (4 * kPi)}}, json::object()), w);
  EXPECT_NEAR(d.lights.at(0).intensity.y, watts / (4 * kPi), 1e-4);
}

TEST(GltfLights, DirectionalLuxToIrradianceAlongNodeMinusZ) {
  const double s = std::sqrt(0.5);
  Warnings w;
  const SceneDesc d =
      load(lightScene({{"type", "directional"}, {"intensity", 2 * 683}}, {{"rotation", {s, 0, 0, s}}}), w);
  const PunctualLight& l = d.lights.at(0);
  EXPECT_EQ(l.type, PunctualLight::Type::Directional);
  EXPECT_NEAR(l.intensity.x, 2.0f, 1e-6f);
  // +90 degrees about X turns local -Z into +Y.
  EXPECT_NEAR(l.direction.x, 0, 1e-6f);
  EXPECT_NEAR(l.direction.y, 1, 1e-6f);
  EXPECT_NEAR(l.direction.z, 0, 1e-6f);
}

TEST(GltfLights, SpotKeepsConesAndRange) {
  Warnings w;
  const SceneDesc d = load(lightScene({{"type", "spot"},
                                       {"intensity", 68.3},
                                       {"range", 12},
                                       {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.5}}}},
                                      json::object()),
                           w);
  const PunctualLight& l = d.lights.at(0);
  EXPECT_EQ(l.type, PunctualLight::Type::Spot);
  EXPECT_NEAR(l.intensity.z, 0.1f, 1e-7f);
  EXPECT_FLOAT_EQ(l.innerConeAngle, 0.2f);
  EXPECT_FLOAT_EQ(l.outerConeAngle, 0.5f);
  EXPECT_EQ(l.range, 12.0f);
  EXPECT_EQ(l.direction, (Vec3f{0, 0, -1}));
}

}  // namespace
}  // namespace lensrt
