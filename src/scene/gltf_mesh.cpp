#include "scene/gltf_mesh.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <string>

#include "scene/gltf_accessor.h"
#include "scene/gltf_values.h"

namespace lensrt::gltf {
namespace {

template <class V, int N>
std::vector<V> group(const std::vector<float>& flat) {
  std::vector<V> out(flat.size() / N);
  for (std::size_t i = 0; i < out.size(); ++i) {
    if constexpr (N == 2) out[i] = {flat[2 * i], flat[2 * i + 1]};
    if constexpr (N == 3) out[i] = {flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]};
    if constexpr (N == 4) out[i] = {flat[4 * i], flat[4 * i + 1], flat[4 * i + 2], flat[4 * i + 3]};
  }
  return out;
}

const char* modeName(int mode) {
  switch (mode) {
    case TINYGLTF_MODE_POINTS:
      return "POINTS";
    case TINYGLTF_MODE_LINE:
      return "LINES";
    case TINYGLTF_MODE_LINE_LOOP:
      return "LINE_LOOP";
    case 3:
      return "LINE_STRIP";
    default:
      return nullptr;
  }
}

// Warns about vertex attributes that change the look but are not rendered.
void warnIgnoredAttributes(const Context& ctx, const tinygltf::Primitive& prim) {
  for (const auto& [name, accessor] : prim.attributes) {
    if (name.rfind("TEXCOORD_", 0) == 0 && name != "TEXCOORD_0" && name != "TEXCOORD_1")
      ctx.warnings.warn("extra UV sets (TEXCOORD_2 and up) are ignored");
    else if (name.rfind("COLOR_", 0) == 0 && name != "COLOR_0")
      ctx.warnings.warn("vertex colours beyond COLOR_0 are ignored");
  }
  for (const auto& [name, value] : prim.extensions)
    if (!isSupportedExtension(name)) ctx.warnUnsupportedExtension(name);
}

// A material slot reading TEXCOORD_1 on a primitive without one reads (0, 0).
void warnMissingUvSet(const Context& ctx, const tinygltf::Primitive& prim, const std::string& label) {
  if (prim.material < 0 || prim.attributes.count("TEXCOORD_1")) return;
  const tinygltf::Material& m = ctx.model.materials[static_cast<std::size_t>(prim.material)];
  const auto reads1 = [](const auto& info) {
    int texCoord = info.texCoord;
    const auto ext = info.extensions.find("KHR_texture_transform");
    if (ext != info.extensions.end())
      if (const std::optional<double> t = numberMember(ext->second, "texCoord"); t && isIndex(*t))
        texCoord = static_cast<int>(*t);
    return info.index >= 0 && texCoord == 1;
  };
  if (reads1(m.pbrMetallicRoughness.baseColorTexture) ||
      reads1(m.pbrMetallicRoughness.metallicRoughnessTexture) || reads1(m.normalTexture) ||
      reads1(m.emissiveTexture))
    ctx.warnings.warn(label +
                      ": its material reads TEXCOORD_1, which the primitive does not have; using (0, 0)");
}

// Triangle k of a strip or fan as the glTF spec orders its vertices (keeps
// the winding of the first triangle).
std::array<std::uint32_t, 3> stripTriangle(const std::vector<std::uint32_t>& v, std::size_t k) {
  if (k % 2 == 0) return {v[k], v[k + 1], v[k + 2]};
  return {v[k], v[k + 2], v[k + 1]};
}
std::array<std::uint32_t, 3> fanTriangle(const std::vector<std::uint32_t>& v, std::size_t k) {
  return {v[k + 1], v[k + 2], v[0]};
}

// COLOR_0 as the spec allows it: VEC3 or VEC4 of floats or normalized
// unsigned bytes or shorts; anything else is ignored with a warning (nullopt).
std::optional<int> colourComponents(const Context& ctx, int index, const std::string& label) {
  if (index < 0 || static_cast<std::size_t>(index) >= ctx.model.accessors.size())
    return 4;  // readFloats reports it
  const tinygltf::Accessor& a = ctx.model.accessors[static_cast<std::size_t>(index)];
  const bool vec = a.type == TINYGLTF_TYPE_VEC3 || a.type == TINYGLTF_TYPE_VEC4;
  const bool component = a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
                         (a.normalized && (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                           a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT));
  if (vec && component) return a.type == TINYGLTF_TYPE_VEC3 ? 3 : 4;
  ctx.warnings.warn(
      label + ": COLOR_0 is not a VEC3 or VEC4 of floats or normalized unsigned bytes or shorts; ignored");
  return std::nullopt;
}

bool degenerate(const std::vector<Vec3f>& p, const std::array<std::uint32_t, 3>& t) {
  if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return true;
  const Vec3d a(p[t[0]]), b(p[t[1]]), c(p[t[2]]);
  return lengthSquared(cross(b - a, c - a)) == 0.0;
}

const tinygltf::Mesh& meshAt(const Context& ctx, int index) {
  if (index < 0 || static_cast<std::size_t>(index) >= ctx.model.meshes.size())
    ctx.fail("mesh " + std::to_string(index) + " does not exist");
  return ctx.model.meshes[static_cast<std::size_t>(index)];
}

}  // namespace

// Adds the morph targets' deltas, in proportion to their weights, to the
// positions, normals and tangents just read (glTF 2.0 3.7.2.2).
void applyMorphTargets(const Context& ctx, const tinygltf::Primitive& prim,
                       const std::vector<double>& weights, const std::string& label, Mesh& mesh) {
  const std::size_t n = mesh.positions.size();
  for (std::size_t t = 0; t < prim.targets.size() && t < weights.size(); ++t) {
    const float w = float(weights[t]);
    if (w == 0.0f) continue;
    const auto delta = [&](const char* attribute) -> std::vector<Vec3f> {
      const auto it = prim.targets[t].find(attribute);
      if (it == prim.targets[t].end()) return {};
      const std::string what = label + " morph target " + std::to_string(t) + " " + attribute;
      std::vector<Vec3f> d = group<Vec3f, 3>(readFloats(ctx, it->second, 3, what.c_str()));
      if (d.size() != n)
        ctx.fail(what + " has " + std::to_string(d.size()) + " elements, POSITION has " + std::to_string(n));
      return d;
    };
    const std::vector<Vec3f> dp = delta("POSITION"), dn = delta("NORMAL"), dt = delta("TANGENT");
    for (std::size_t i = 0; i < dp.size(); ++i) mesh.positions[i] += dp[i] * w;
    for (std::size_t i = 0; i < dn.size() && i < mesh.normals.size(); ++i) mesh.normals[i] += dn[i] * w;
    for (std::size_t i = 0; i < dt.size() && i < mesh.tangents.size(); ++i) {
      mesh.tangents[i].x += dt[i].x * w;
      mesh.tangents[i].y += dt[i].y * w;
      mesh.tangents[i].z += dt[i].z * w;
    }
  }
  // Blended normals are no longer unit (the specification leaves that to us).
  for (Vec3f& normal : mesh.normals)
    if (const float l = length(normal); l > 0) normal = normal * (1.0f / l);
}

// Blends each vertex by its joints' matrices (JOINTS_n, WEIGHTS_n for every
// set n the primitive has) into world space; normals and tangents by the
// blended matrix's linear part, renormalised.
void applySkin(const Context& ctx, const tinygltf::Primitive& prim,
               const std::vector<Transform::Matrix>& joints, const std::string& label, Mesh& mesh) {
  const std::size_t n = mesh.positions.size();
  std::vector<Transform::Matrix> blend(n, Transform::Matrix{});
  std::vector<double> total(n, 0.0);
  for (int set = 0;; ++set) {
    const auto j = prim.attributes.find("JOINTS_" + std::to_string(set));
    const auto w = prim.attributes.find("WEIGHTS_" + std::to_string(set));
    if (j == prim.attributes.end() || w == prim.attributes.end()) break;
    const std::string what = label + " JOINTS_" + std::to_string(set);
    const std::vector<float> index = readFloats(ctx, j->second, 4, what.c_str());
    const std::vector<float> weight =
        readFloats(ctx, w->second, 4, (label + " WEIGHTS_" + std::to_string(set)).c_str());
    if (index.size() != 4 * n || weight.size() != 4 * n) ctx.fail(what + ": not one set of 4 per vertex");
    for (std::size_t v = 0; v < n; ++v)
      for (std::size_t k = 0; k < 4; ++k) {
        const double wk = weight[4 * v + k];
        if (wk == 0.0) continue;
        const float joint = index[4 * v + k];
        if (!(joint >= 0 && std::size_t(joint) < joints.size()))
          ctx.fail(fmt::format("{}: joint {} of vertex {} is not one of the skin's {} joints", what, joint, v,
                               joints.size()));
        const Transform::Matrix& m = joints[std::size_t(joint)];
        for (std::size_t r = 0; r < 4; ++r)
          for (std::size_t c = 0; c < 4; ++c) blend[v][r][c] += wk * m[r][c];
        total[v] += wk;
      }
  }
  const auto apply = [](const Transform::Matrix& m, const Vec3f& p, double w) {
    return Vec3f(Vec3d{m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3] * w,
                       m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3] * w,
                       m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3] * w});
  };
  // Weights meant to sum to 1 miss by the rounding of their integer types
  // (1/255 for bytes) quietly; a vertex missing by more is named once.
  std::size_t off = 0, first = n;
  for (std::size_t v = 0; v < n; ++v)
    if (total[v] > 0 && std::abs(total[v] - 1.0) > 0.01 && off++ == 0) first = v;
  if (off > 0)
    ctx.warnings.warn(
        fmt::format("{}: the joint weights of {} vertices do not sum to 1 (vertex {}: {:g}); "
                    "they are normalised",
                    label, off, first, total[first]));
  for (std::size_t v = 0; v < n; ++v) {
    if (!(total[v] > 0)) continue;  // no weight: the vertex keeps its bind pose
    Transform::Matrix& m = blend[v];
    for (auto& row : m)
      for (double& x : row) x /= total[v];
    mesh.positions[v] = apply(m, mesh.positions[v], 1.0);
    if (v < mesh.normals.size()) {
      const Vec3f d = apply(m, mesh.normals[v], 0.0);
      if (const float l = length(d); l > 0) mesh.normals[v] = d * (1.0f / l);
    }
    if (v < mesh.tangents.size()) {
      const Vec4f t = mesh.tangents[v];
      const Vec3f d = apply(m, Vec3f{t.x, t.y, t.z}, 0.0);
      if (const float l = length(d); l > 0) mesh.tangents[v] = {d.x / l, d.y / l, d.z / l, t.w};
    }
  }
}

std::vector<int> convertMesh(const Context& ctx, int index, std::vector<Mesh>& meshes, MeshStats& stats,
                             const std::vector<double>& morphWeights,
                             const std::vector<Transform::Matrix>* joints) {
  const tinygltf::Mesh& gm = meshAt(ctx, index);
  // (Not "#" + std::to_string: GCC 12 warns falsely about it, bug 105329.)
  const std::string baseName = gm.name.empty() ? std::string("#").append(std::to_string(index)) : gm.name;
  std::vector<int> result;
  for (std::size_t p = 0; p < gm.primitives.size(); ++p) {
    const tinygltf::Primitive& prim = gm.primitives[p];
    const std::string name = gm.primitives.size() > 1 ? baseName + "/" + std::to_string(p) : baseName;
    const std::string label = "mesh '" + name + "'";
    if (const char* other = modeName(prim.mode)) {
      ctx.warnings.warn(std::string("primitive mode ") + other + " is not rendered (skipped)");
      continue;
    }
    if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        prim.mode != TINYGLTF_MODE_TRIANGLE_FAN) {
      ctx.warnings.warn("primitive mode " + std::to_string(prim.mode) + " is invalid (skipped)");
      continue;
    }
    warnIgnoredAttributes(ctx, prim);
    const auto position = prim.attributes.find("POSITION");
    if (position == prim.attributes.end()) {
      ctx.warnings.warn(label + ": a primitive without POSITION is skipped");
      continue;
    }
    if (prim.material < -1 || prim.material >= static_cast<int>(ctx.model.materials.size()))
      ctx.fail(label + ": material " + std::to_string(prim.material) + " does not exist");

    Mesh mesh;
    mesh.name = name;
    mesh.material = prim.material;
    mesh.positions = group<Vec3f, 3>(readFloats(ctx, position->second, 3, (label + " POSITION").c_str()));
    const std::size_t n = mesh.positions.size();
    for (const Vec3f& v : mesh.positions) {
      if (!isFinite(v)) ctx.fail(label + ": vertex position is NaN or infinite");
      if (std::abs(v.x) > kMaxCoordinate || std::abs(v.y) > kMaxCoordinate || std::abs(v.z) > kMaxCoordinate)
        ctx.fail(label + ": vertex coordinate beyond 1e15");
    }
    const auto optional = [&](const char* attr, int components) {
      const auto it = prim.attributes.find(attr);
      if (it == prim.attributes.end()) return std::vector<float>{};
      std::vector<float> v = readFloats(ctx, it->second, components, (label + " " + attr).c_str());
      if (v.size() != n * static_cast<std::size_t>(components))
        ctx.fail(label + ": " + attr + " has " + std::to_string(v.size() / components) +
                 " elements, POSITION has " + std::to_string(n));
      return v;
    };
    mesh.normals = group<Vec3f, 3>(optional("NORMAL", 3));
    mesh.tangents = group<Vec4f, 4>(optional("TANGENT", 4));
    if ((!morphWeights.empty() && !prim.targets.empty()) || joints) {
      if (!morphWeights.empty()) applyMorphTargets(ctx, prim, morphWeights, label, mesh);
      if (joints) applySkin(ctx, prim, *joints, label, mesh);
      for (const Vec3f& v : mesh.positions)
        if (!isFinite(v) || std::abs(v.x) > kMaxCoordinate || std::abs(v.y) > kMaxCoordinate ||
            std::abs(v.z) > kMaxCoordinate)
          ctx.fail(label + ": a morphed or skinned vertex position is not finite or beyond 1e15");
    }
    mesh.uvs = group<Vec2f, 2>(optional("TEXCOORD_0", 2));
    mesh.uvs1 = group<Vec2f, 2>(optional("TEXCOORD_1", 2));
    if (const auto colour = prim.attributes.find("COLOR_0"); colour != prim.attributes.end()) {
      if (const std::optional<int> c = colourComponents(ctx, colour->second, label)) {
        // Float colours are meant to lie in [0, 1]; NaN would poison every path through the surface.
        std::vector<float> v = optional("COLOR_0", *c);
        for (float& x : v) x = std::isnan(x) ? 1.0f : std::clamp(x, 0.0f, 1.0f);
        if (*c == 4) {
          mesh.colors = group<Vec4f, 4>(v);
        } else {
          for (const Vec3f& rgb : group<Vec3f, 3>(v)) mesh.colors.push_back({rgb.x, rgb.y, rgb.z, 1});
        }
      }
    }
    warnMissingUvSet(ctx, prim, label);

    std::vector<std::uint32_t> vertices;
    if (prim.indices >= 0) {
      vertices = readIndices(ctx, prim.indices, (label + " indices").c_str());
      for (const std::uint32_t i : vertices)
        if (i >= n)
          ctx.fail(label + ": index " + std::to_string(i) + " beyond the vertex count " + std::to_string(n));
    } else {
      vertices.resize(n);
      std::iota(vertices.begin(), vertices.end(), 0u);
    }
    std::size_t triangles = 0;
    if (prim.mode == TINYGLTF_MODE_TRIANGLES) {
      triangles = vertices.size() / 3;
    } else if (vertices.size() >= 3) {
      triangles = vertices.size() - 2;
    }
    mesh.indices.reserve(3 * triangles);
    for (std::size_t k = 0; k < triangles; ++k) {
      std::array<std::uint32_t, 3> t;
      if (prim.mode == TINYGLTF_MODE_TRIANGLES)
        t = {vertices[3 * k], vertices[3 * k + 1], vertices[3 * k + 2]};
      else if (prim.mode == TINYGLTF_MODE_TRIANGLE_STRIP)
        t = stripTriangle(vertices, k);
      else
        t = fanTriangle(vertices, k);
      if (degenerate(mesh.positions, t)) {
        ++stats.degenerateTriangles;
        continue;
      }
      mesh.indices.insert(mesh.indices.end(), t.begin(), t.end());
    }
    if (mesh.indices.empty()) continue;
    stats.triangles += mesh.triangleCount();
    result.push_back(static_cast<int>(meshes.size()));
    meshes.push_back(std::move(mesh));
  }
  return result;
}

std::vector<double> morphWeights(const Context& ctx, const tinygltf::Node& node, int mesh) {
  const tinygltf::Mesh& gm = meshAt(ctx, mesh);
  std::size_t targets = 0;
  for (const tinygltf::Primitive& prim : gm.primitives) targets = std::max(targets, prim.targets.size());
  const std::vector<double>& weights = !node.weights.empty() ? node.weights : gm.weights;
  if (targets == 0) return {};
  if (!weights.empty() && weights.size() != targets)
    ctx.fail(fmt::format("mesh {} has {} morph targets but {} weights", mesh, targets, weights.size()));
  for (const double w : weights)
    if (!std::isfinite(w)) ctx.fail(fmt::format("mesh {}: a morph target weight is not finite", mesh));
  return weights;
}

}  // namespace lensrt::gltf
