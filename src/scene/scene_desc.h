// The neutral scene description: what a loader (glTF today) produces and what
// the render-time scene (Embree) consumes. Plain data, world units are metres.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/bounds.h"
#include "core/transform.h"
#include "core/vec.h"
#include "image/texture.h"

namespace lensrt {

// KHR_texture_transform as the 2x3 matrix T * R * S the extension defines:
// uv' = (m[0] u + m[1] v + m[2], m[3] u + m[4] v + m[5]).
struct UvTransform {
  float m[6] = {1, 0, 0, 0, 1, 0};
  static UvTransform fromOffsetRotationScale(Vec2f offset, float rotation, Vec2f scale);
  Vec2f apply(Vec2f uv) const { return {m[0] * uv.x + m[1] * uv.y + m[2], m[3] * uv.x + m[4] * uv.y + m[5]}; }
};

struct TextureRef {
  int texture = -1;  // index into SceneDesc::textures, -1: none
  int texCoord = 0;  // which UV set: 0 = TEXCOORD_0, 1 = TEXCOORD_1
  UvTransform transform;
  bool valid() const { return texture >= 0; }
  // The texture coordinate this slot reads at a point with the given UV sets.
  Vec2f uv(Vec2f uv0, Vec2f uv1) const { return transform.apply(texCoord == 1 ? uv1 : uv0); }
};

enum class AlphaMode { Opaque, Mask, Blend };

// glTF metallic-roughness material.
struct Material {
  std::string name;
  Vec4f baseColor{1, 1, 1, 1};  // linear RGBA factor
  TextureRef baseColorTexture;
  float metallic = 1.0f;
  float roughness = 1.0f;
  TextureRef metallicRoughnessTexture;  // G = roughness, B = metallic
  TextureRef normalTexture;
  float normalScale = 1.0f;
  Vec3f emissive{0, 0, 0};  // linear RGB factor, already times emissiveStrength
  TextureRef emissiveTexture;
  AlphaMode alphaMode = AlphaMode::Opaque;
  float alphaCutoff = 0.5f;
  bool doubleSided = false;

  // KHR_materials_ior and KHR_materials_specular (the dielectric's Fresnel).
  float ior = 1.5f;
  float specular = 1.0f;
  TextureRef specularTexture;  // A
  Vec3f specularColor{1, 1, 1};
  TextureRef specularColorTexture;  // RGB, sRGB
  // KHR_materials_transmission: share of the dielectric that transmits.
  float transmission = 0.0f;
  TextureRef transmissionTexture;  // R
  // KHR_materials_volume: thickness 0 (or no volume) is a thin-walled sheet;
  // otherwise the mesh bounds a medium absorbing by Beer-Lambert with
  // sigma = -ln(attenuationColor) / attenuationDistance (the path tracer uses
  // the real geometry, so the thickness texture is not needed).
  float thickness = 0.0f;
  Vec3f attenuationColor{1, 1, 1};
  float attenuationDistance = std::numeric_limits<float>::infinity();
  // KHR_materials_dispersion: 20 / the Abbe number (0: none). The index at a
  // wavelength is ior + (ior - 1) / V (523655 nm^2 / l^2 - 1.5168), V = 20 /
  // dispersion (the extension's linear model through the d line).
  float dispersion = 0.0f;
  float iorAt(float nm) const;
  // KHR_materials_clearcoat.
  float clearcoat = 0.0f;
  TextureRef clearcoatTexture;  // R
  float clearcoatRoughness = 0.0f;
  TextureRef clearcoatRoughnessTexture;  // G
  TextureRef clearcoatNormalTexture;
  float clearcoatNormalScale = 1.0f;
  // KHR_materials_sheen.
  Vec3f sheenColor{0, 0, 0};
  TextureRef sheenColorTexture;  // RGB, sRGB
  float sheenRoughness = 0.0f;
  TextureRef sheenRoughnessTexture;  // A

  bool thinWalled() const { return !(thickness > 0); }
  // Absorption coefficient per metre inside a volume (zero: none).
  Vec3f attenuationCoefficient() const;
  bool isEmissive() const { return emissive.x > 0 || emissive.y > 0 || emissive.z > 0; }
};

// One glTF primitive, already converted to an indexed triangle list.
struct Mesh {
  std::string name;
  std::vector<Vec3f> positions;
  std::vector<Vec3f> normals;          // empty or one per position
  std::vector<Vec4f> tangents;         // empty or one per position (w = handedness)
  std::vector<Vec2f> uvs;              // empty or one per position (TEXCOORD_0)
  std::vector<Vec2f> uvs1;             // empty or one per position (TEXCOORD_1)
  std::vector<Vec4f> colors;           // empty or one per position (COLOR_0, linear RGBA)
  std::vector<std::uint32_t> indices;  // 3 per triangle
  int material = -1;                   // -1: the glTF default material
  std::size_t triangleCount() const { return indices.size() / 3; }
};

// A placement of a mesh in the world. Meshes used more than once (or through
// EXT_mesh_gpu_instancing) become Embree instances of one shared geometry.
struct MeshInstance {
  int mesh = 0;
  Transform worldFromObject;  // at the shutter's opening
  // Motion blur: the placement at evenly spaced moments over the recorded
  // span (SceneDesc::motionSteps of them, the first being mesh and
  // worldFromObject); a deforming mesh (skin, morph targets) gives each step
  // a mesh of its own with the same triangles. Empty: the instance is still.
  struct Step {
    int mesh = 0;
    Transform worldFromObject;
  };
  std::vector<Step> motion{};
  int node = -1;  // the glTF node that places it (SceneDesc::nodeNames), -1: none
  bool moves() const { return !motion.empty(); }
};

// Radiometric punctual lights (converted from glTF's photometric units by the
// loader; the rule is in the README): intensity in W/sr for point and spot,
// irradiance in W/m^2 for directional, per RGB channel.
struct PunctualLight {
  enum class Type { Point, Spot, Directional };
  std::string name;
  Type type = Type::Point;
  Rgb intensity{1, 1, 1};
  Vec3f position;             // world, point and spot
  Vec3f direction{0, 0, -1};  // world, unit, the direction light travels (spot, directional)
  float innerConeAngle = 0.0f;
  float outerConeAngle = 0.7853981634f;
  float range = 0.0f;  // 0: infinite
  // Motion blur: where the light is and points at each of the scene's
  // motion steps (the first being position and direction); empty: still.
  struct Step {
    Vec3f position, direction;
  };
  std::vector<Step> motion{};
};

struct CameraDesc {
  std::string name;        // the node's name, or the glTF camera's when the node has none
  std::string cameraName;  // the glTF camera object's own name
  int node = -1;
  Transform worldFromCamera;  // looks down -Z, +Y up
  bool orthographic = false;
  float xmag = 0.0f, ymag = 0.0f;    // half the view's width and height (orthographic), metres
  float yfov = 0.6911f;              // radians (perspective)
  std::optional<float> aspectRatio;  // width / height if the file gives one
  float znear = 0.01f;
  // Motion blur: worldFromCamera at each of the scene's motion steps (the
  // first being worldFromCamera); empty when the camera is still.
  std::vector<Transform> motion{};
};

struct SceneDesc {
  std::string sourceFile;
  std::vector<Mesh> meshes;
  std::vector<MeshInstance> instances;
  std::vector<Material> materials;
  std::vector<Texture> textures;
  std::vector<PunctualLight> lights;
  std::vector<CameraDesc> cameras;  // in the order the default scene's traversal finds them
  // Every glTF node's name, by node index ("node<i>" where the file gives
  // none): the ID AOVs' names.
  std::vector<std::string> nodeNames;
  // The moment the nodes are posed at, "time=1.25 animation=all", when the
  // file has animations; empty when it has none (part of a render's identity).
  std::string pose;
  // Time steps of the moving instances and cameras (their `motion`), spread
  // evenly over the span the scene was loaded for; 0 when nothing moves.
  int motionSteps = 0;

  Bounds3f worldBounds() const;
};

}  // namespace lensrt
