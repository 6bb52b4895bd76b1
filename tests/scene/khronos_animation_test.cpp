// The Khronos animated sample assets kept in tests/assets/khronos (BoxAnimated,
// AnimatedMorphCube, RiggedSimple, SimpleSkin, AnimatedTriangle) posed by the
// loader at moments between keyframes, against a pose computed here from the
// file alone: this file reads the JSON and the binary buffer (GLB BIN chunk or
// base64 data: URIs) itself and applies the glTF 2.0 formulas (node T * R * S
// and parent * child; LINEAR with slerp for rotations, STEP and CUBICSPLINE as
// in the specification's Appendix C; morph targets base + sum w_i delta_i;
// skins sum_j w_j (jointWorld_j * inverseBind_j) v, the skinned node's own
// transform ignored). Every vertex of every mesh is compared, by index: the
// loader keeps POSITION's order (gltf_mesh.cpp reads the accessor as it is and
// only drops degenerate triangles, never vertices). None of the five assets
// uses CUBICSPLINE, so a small synthetic file checks the specification's
// tangents (out-tangent of key k and in-tangent of key k + 1, both scaled by
// t_{k+1} - t_k) through the same reference, for a translation, a rotation and
// morph weights.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "gltf_test_builder.h"
#include "scene/gltf_loader.h"

namespace lensrt {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

// ---------------------------------------------------------------------------
// The reference: a glTF reader and poser of its own, sharing no code with the
// loader (no tinygltf, no scene/ helpers).
namespace ref {

using M4 = std::array<std::array<double, 4>, 4>;  // [row][column]
using Q = std::array<double, 4>;                  // x, y, z, w

M4 identity() {
  M4 m{};
  for (int i = 0; i < 4; ++i) m[i][i] = 1;
  return m;
}

M4 operator*(const M4& a, const M4& b) {
  M4 m{};
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      for (int k = 0; k < 4; ++k) m[r][c] += a[r][k] * b[k][c];
  return m;
}

Vec3d transformPoint(const M4& m, const Vec3d& p) {
  return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
          m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
          m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]};
}

// glTF stores matrices column by column.
M4 fromColumnMajor(const double* v) {
  M4 m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m[r][c] = v[4 * c + r];
  return m;
}

// T * R * S for a unit quaternion q.
M4 trs(const Vec3d& t, const Q& q, const Vec3d& s) {
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  const double x = q[0] / n, y = q[1] / n, z = q[2] / n, w = q[3] / n;
  const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                          {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                          {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
  const double sc[3] = {s.x, s.y, s.z};
  M4 m = identity();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m[i][j] = r[i][j] * sc[j];
  m[0][3] = t.x;
  m[1][3] = t.y;
  m[2][3] = t.z;
  return m;
}

Vec3d vec3(const json& v) {
  return {v[0].get<double>(), v[1].get<double>(), v[2].get<double>()};
}

std::vector<std::uint8_t> readBytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::uint8_t> base64Decode(const std::string& text) {
  std::vector<std::uint8_t> out;
  std::uint32_t bits = 0;
  int count = 0;
  for (const char ch : text) {
    int v;
    if (ch >= 'A' && ch <= 'Z')
      v = ch - 'A';
    else if (ch >= 'a' && ch <= 'z')
      v = ch - 'a' + 26;
    else if (ch >= '0' && ch <= '9')
      v = ch - '0' + 52;
    else if (ch == '+')
      v = 62;
    else if (ch == '/')
      v = 63;
    else
      break;  // '=' padding
    bits = (bits << 6) | std::uint32_t(v);
    if ((count += 6) >= 8) {
      count -= 8;
      out.push_back(std::uint8_t(bits >> count));
    }
  }
  return out;
}

std::uint32_t le32(const std::vector<std::uint8_t>& b, std::size_t at) {
  return std::uint32_t(b.at(at)) | std::uint32_t(b.at(at + 1)) << 8 | std::uint32_t(b.at(at + 2)) << 16 |
         std::uint32_t(b.at(at + 3)) << 24;
}

struct Asset {
  json doc;
  std::vector<std::vector<std::uint8_t>> buffers;
};

// A .glb (12-byte header, JSON chunk, BIN chunk) or a .gltf whose buffers are
// data: URIs (the two layouts the five assets use).
Asset read(const fs::path& file) {
  const std::vector<std::uint8_t> bytes = readBytes(file);
  Asset a;
  std::vector<std::uint8_t> bin;
  if (bytes.size() >= 20 && std::memcmp(bytes.data(), "glTF", 4) == 0) {
    const std::uint32_t jsonLength = le32(bytes, 12);
    EXPECT_EQ(le32(bytes, 16), 0x4E4F534Au);  // "JSON"
    a.doc = json::parse(bytes.begin() + 20, bytes.begin() + 20 + jsonLength);
    const std::size_t binAt = 20 + jsonLength;
    if (binAt + 8 <= bytes.size()) {
      EXPECT_EQ(le32(bytes, binAt + 4), 0x004E4942u);  // "BIN\0"
      bin.assign(bytes.begin() + std::ptrdiff_t(binAt + 8),
                 bytes.begin() + std::ptrdiff_t(binAt + 8 + le32(bytes, binAt)));
    }
  } else {
    a.doc = json::parse(bytes.begin(), bytes.end());
  }
  for (const json& buffer : a.doc["buffers"]) {
    if (!buffer.contains("uri")) {
      a.buffers.push_back(bin);
      continue;
    }
    const std::string uri = buffer["uri"].get<std::string>();
    const std::size_t comma = uri.find(";base64,");
    EXPECT_EQ(uri.rfind("data:", 0), 0u) << "only data: URIs here";
    a.buffers.push_back(base64Decode(uri.substr(comma + 8)));
  }
  return a;
}

// Accessor `index` as doubles, components per element in a row.
std::vector<double> accessor(const Asset& a, const json& index) {
  const json& acc = a.doc["accessors"].at(index.get<std::size_t>());
  EXPECT_FALSE(acc.contains("sparse")) << "no sparse accessors in these assets";
  static const std::map<std::string, int> kComponents = {
      {"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4}, {"MAT4", 16}};
  const int components = kComponents.at(acc["type"].get<std::string>());
  const int type = acc["componentType"].get<int>();
  const std::size_t size = type == 5126 || type == 5125 ? 4 : type == 5123 || type == 5122 ? 2 : 1;
  const std::size_t count = acc["count"].get<std::size_t>();
  std::vector<double> out(count * std::size_t(components), 0.0);
  if (!acc.contains("bufferView")) return out;
  const json& view = a.doc["bufferViews"].at(acc["bufferView"].get<std::size_t>());
  const std::vector<std::uint8_t>& buffer = a.buffers.at(view["buffer"].get<std::size_t>());
  const std::size_t stride = view.value("byteStride", std::size_t(components) * size);
  const std::size_t start =
      view.value("byteOffset", std::size_t(0)) + acc.value("byteOffset", std::size_t(0));
  const bool normalized = acc.value("normalized", false);
  for (std::size_t e = 0; e < count; ++e)
    for (std::size_t c = 0; c < std::size_t(components); ++c) {
      const std::uint8_t* p = &buffer.at(start + e * stride + c * size);
      double v = 0;
      if (type == 5126) {
        float f;
        std::memcpy(&f, p, 4);
        v = f;
      } else if (type == 5125) {
        v = double(std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 |
                   std::uint32_t(p[3]) << 24);
      } else if (type == 5123) {
        v = double(std::uint16_t(p[0] | p[1] << 8));
        if (normalized) v /= 65535.0;
      } else if (type == 5121) {
        v = p[0];
        if (normalized) v /= 255.0;
      } else {
        ADD_FAILURE() << "component type " << type << " not handled by the reference";
      }
      out[e * std::size_t(components) + c] = v;
    }
  return out;
}

Q normalized(Q q) {
  const double l = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (double& x : q) x /= l;
  return q;
}

// Appendix C's slerp: a = arccos |d|, s = sign d (the short way). It assumes
// unit quaternions, and keys are stored as float, often rounded further
// (AnimatedTriangle and SimpleSkin store 0.707 for sqrt(1/2), 1.5e-4 off unit
// length, which would put arccos off by 6e-5): the keys are normalised first.
Q slerp(Q a, Q b, double u) {
  a = normalized(a);
  b = normalized(b);
  const double d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
  const double s = d < 0 ? -1.0 : 1.0;
  const double angle = std::acos(std::min(1.0, std::abs(d)));
  Q q;
  if (angle < 1e-9) {
    for (int i = 0; i < 4; ++i) q[i] = (1 - u) * a[i] + u * s * b[i];
  } else {
    const double ka = std::sin(angle * (1 - u)) / std::sin(angle),
                 kb = s * std::sin(angle * u) / std::sin(angle);
    for (int i = 0; i < 4; ++i) q[i] = ka * a[i] + kb * b[i];
  }
  return q;
}

// Sampler `s` at time t: `width` numbers (4 for a rotation, the target count
// for weights). Held at the first and last keyframes outside them.
std::vector<double> sample(const Asset& a, const json& sampler, double t, bool rotation) {
  const std::vector<double> times = accessor(a, sampler["input"]);
  const std::vector<double> values = accessor(a, sampler["output"]);
  const std::string interpolation = sampler.value("interpolation", "LINEAR");
  const bool cubic = interpolation == "CUBICSPLINE";
  const std::size_t n = times.size(), per = cubic ? 3 : 1, width = values.size() / (n * per);
  EXPECT_EQ(values.size(), n * per * width);
  // Part 0, 1, 2 of keyframe k: in-tangent a_k, value v_k, out-tangent b_k (CUBICSPLINE).
  const auto at = [&](std::size_t k, std::size_t part, std::size_t c) {
    return values[(k * per + (cubic ? part : 0)) * width + c];
  };
  std::vector<double> out(width);
  const auto key = [&](std::size_t k) {
    for (std::size_t c = 0; c < width; ++c) out[c] = at(k, 1, c);
    return out;
  };
  if (t <= times.front()) return key(0);
  if (t >= times.back()) return key(n - 1);
  std::size_t k = 0;
  while (!(t < times[k + 1])) ++k;
  const double td = times[k + 1] - times[k], u = (t - times[k]) / td;
  if (interpolation == "STEP") return key(k);
  if (interpolation == "LINEAR") {
    if (rotation) {
      const Q q = slerp({at(k, 1, 0), at(k, 1, 1), at(k, 1, 2), at(k, 1, 3)},
                        {at(k + 1, 1, 0), at(k + 1, 1, 1), at(k + 1, 1, 2), at(k + 1, 1, 3)}, u);
      return {q.begin(), q.end()};
    }
    for (std::size_t c = 0; c < width; ++c) out[c] = (1 - u) * at(k, 1, c) + u * at(k + 1, 1, c);
    return out;
  }
  EXPECT_TRUE(cubic) << interpolation;
  // v(u) = (2u^3 - 3u^2 + 1) v_k + td (u^3 - 2u^2 + u) b_k + (-2u^3 + 3u^2) v_k+1 + td (u^3 - u^2) a_k+1.
  const double u2 = u * u, u3 = u2 * u;
  for (std::size_t c = 0; c < width; ++c)
    out[c] = (2 * u3 - 3 * u2 + 1) * at(k, 1, c) + td * (u3 - 2 * u2 + u) * at(k, 2, c) +
             (-2 * u3 + 3 * u2) * at(k + 1, 1, c) + td * (u3 - u2) * at(k + 1, 0, c);
  if (rotation) {
    const double l = std::sqrt(out[0] * out[0] + out[1] * out[1] + out[2] * out[2] + out[3] * out[3]);
    for (double& x : out) x /= l;
  }
  return out;
}

// Every mesh node's vertices in world space at time t (animated = false: the
// file's rest pose, no animation at all), by glTF mesh name.
std::map<std::string, std::vector<Vec3d>> pose(const Asset& a, double t, bool animated = true) {
  const json& nodes = a.doc["nodes"];
  struct Local {
    Vec3d t{0, 0, 0}, s{1, 1, 1};
    Q r{0, 0, 0, 1};
    std::vector<double> weights;
    bool hasWeights = false;
  };
  std::vector<Local> local(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const json& n = nodes[i];
    if (n.contains("translation")) local[i].t = vec3(n["translation"]);
    if (n.contains("rotation")) local[i].r = n["rotation"].get<Q>();
    if (n.contains("scale")) local[i].s = vec3(n["scale"]);
    if (n.contains("weights")) {
      local[i].weights = n["weights"].get<std::vector<double>>();
      local[i].hasWeights = true;
    }
  }
  if (animated)
    for (const json& animation : a.doc.value("animations", json::array()))
      for (const json& channel : animation["channels"]) {
        const json& sampler = animation["samplers"].at(channel["sampler"].get<std::size_t>());
        const std::size_t node = channel["target"]["node"].get<std::size_t>();
        const std::string path = channel["target"]["path"].get<std::string>();
        const std::vector<double> v = sample(a, sampler, t, path == "rotation");
        Local& l = local.at(node);
        if (path == "translation") l.t = {v[0], v[1], v[2]};
        if (path == "rotation") l.r = {v[0], v[1], v[2], v[3]};
        if (path == "scale") l.s = {v[0], v[1], v[2]};
        if (path == "weights") {
          l.weights = v;
          l.hasWeights = true;
        }
      }
  // World matrices: parent * child from the default scene's roots down.
  std::vector<M4> world(nodes.size(), identity());
  const auto visit = [&](const auto& self, std::size_t i, const M4& parent) -> void {
    const json& n = nodes[i];
    if (n.contains("matrix")) {
      const std::vector<double> m = n["matrix"].get<std::vector<double>>();
      world[i] = parent * fromColumnMajor(m.data());
    } else {
      world[i] = parent * trs(local[i].t, local[i].r, local[i].s);
    }
    for (const json& child : n.value("children", json::array()))
      self(self, child.get<std::size_t>(), world[i]);
  };
  const json& scene = a.doc["scenes"].at(a.doc.value("scene", std::size_t(0)));
  for (const json& root : scene["nodes"]) visit(visit, root.get<std::size_t>(), identity());

  std::map<std::string, std::vector<Vec3d>> result;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const json& n = nodes[i];
    if (!n.contains("mesh")) continue;
    const json& mesh = a.doc["meshes"].at(n["mesh"].get<std::size_t>());
    EXPECT_EQ(mesh["primitives"].size(), 1u) << "the reference poses one primitive per mesh";
    const json& prim = mesh["primitives"][0];
    const std::vector<double> base = accessor(a, prim["attributes"]["POSITION"]);
    std::vector<Vec3d> p(base.size() / 3);
    for (std::size_t v = 0; v < p.size(); ++v) p[v] = {base[3 * v], base[3 * v + 1], base[3 * v + 2]};
    // Morph targets: the node's weights (animated or its own), else the mesh's.
    if (prim.contains("targets")) {
      std::vector<double> w = local[i].hasWeights
                                  ? local[i].weights
                                  : mesh.value("weights", std::vector<double>(prim["targets"].size()));
      EXPECT_EQ(w.size(), prim["targets"].size());
      for (std::size_t k = 0; k < prim["targets"].size(); ++k) {
        const std::vector<double> d = accessor(a, prim["targets"][k]["POSITION"]);
        for (std::size_t v = 0; v < p.size(); ++v) p[v] += Vec3d{d[3 * v], d[3 * v + 1], d[3 * v + 2]} * w[k];
      }
    }
    if (n.contains("skin")) {
      // Joint matrices world(joint) * inverseBind; the node's own transform does not apply.
      const json& skin = a.doc["skins"].at(n["skin"].get<std::size_t>());
      std::vector<M4> joints;
      const std::vector<double> ibm = skin.contains("inverseBindMatrices")
                                          ? accessor(a, skin["inverseBindMatrices"])
                                          : std::vector<double>{};
      for (std::size_t j = 0; j < skin["joints"].size(); ++j)
        joints.push_back(world.at(skin["joints"][j].get<std::size_t>()) *
                         (ibm.empty() ? identity() : fromColumnMajor(&ibm[16 * j])));
      std::vector<Vec3d> skinned(p.size(), Vec3d{0, 0, 0});
      for (int set = 0; prim["attributes"].contains("JOINTS_" + std::to_string(set)); ++set) {
        const std::vector<double> j = accessor(a, prim["attributes"]["JOINTS_" + std::to_string(set)]);
        const std::vector<double> w = accessor(a, prim["attributes"]["WEIGHTS_" + std::to_string(set)]);
        for (std::size_t v = 0; v < p.size(); ++v)
          for (std::size_t k = 0; k < 4; ++k)
            if (w[4 * v + k] != 0)
              skinned[v] += transformPoint(joints.at(std::size_t(j[4 * v + k])), p[v]) * w[4 * v + k];
      }
      p = skinned;
    } else {
      for (Vec3d& v : p) v = transformPoint(world[i], v);
    }
    const std::string name = mesh.value("name", "#" + std::to_string(n["mesh"].get<std::size_t>()));
    EXPECT_EQ(result.count(name), 0u) << "each mesh once in these assets";
    result[name] = std::move(p);
  }
  return result;
}

}  // namespace ref

// ---------------------------------------------------------------------------

fs::path asset(const std::string& name, const std::string& file) {
  return fs::path(LENSRT_TEST_DATA_DIR) / "assets/khronos" / name / file;
}

// The loader's world-space vertices of the instance showing mesh `name`.
std::vector<Vec3d> loaded(const SceneDesc& d, const std::string& name) {
  std::vector<Vec3d> out;
  int found = 0;
  for (const MeshInstance& instance : d.instances) {
    const Mesh& mesh = d.meshes.at(std::size_t(instance.mesh));
    if (mesh.name != name) continue;
    ++found;
    for (const Vec3f& p : mesh.positions) out.push_back(instance.worldFromObject.point(Vec3d(p.x, p.y, p.z)));
  }
  EXPECT_EQ(found, 1) << "instances of mesh '" << name << "'";
  return out;
}

double distance(const Vec3d& a, const Vec3d& b) {
  return length(a - b);
}

// Loads `file` at each time and compares every vertex of every mesh with the
// reference pose within 1e-5 m. Each time must move some vertex by at least
// `minMove` from the rest pose, so the comparison can tell a pose from none.
void expectPosesMatch(const fs::path& file, const std::vector<double>& times, double minMove) {
  ASSERT_TRUE(fs::exists(file)) << file;
  const ref::Asset a = ref::read(file);
  const auto rest = ref::pose(a, 0, false);
  for (const double t : times) {
    SCOPED_TRACE("t = " + std::to_string(t));
    Warnings w;
    const SceneDesc d = loadGltf(file, -1, w, {}, AnimationTime{t, ""});
    const auto want = ref::pose(a, t);
    double moved = 0;
    for (const auto& [name, expected] : want) {
      const std::vector<Vec3d> got = loaded(d, name);
      ASSERT_EQ(got.size(), expected.size()) << name;
      double worst = 0;
      std::size_t worstVertex = 0;
      for (std::size_t v = 0; v < got.size(); ++v) {
        moved = std::max(moved, distance(expected[v], rest.at(name)[v]));
        if (const double e = distance(got[v], expected[v]); e > worst) {
          worst = e;
          worstVertex = v;
        }
      }
      EXPECT_LE(worst, 1e-5) << "mesh '" << name << "' vertex " << worstVertex << ": loader ("
                             << got[worstVertex].x << ", " << got[worstVertex].y << ", " << got[worstVertex].z
                             << "), glTF formulas (" << expected[worstVertex].x << ", "
                             << expected[worstVertex].y << ", " << expected[worstVertex].z << ")";
    }
    EXPECT_GE(moved, minMove) << "the pose at this time is too close to the rest pose to test anything";
  }
}

// A LINEAR rotation about z, 0 to 360 degrees over 1 s in five keys (slerp).
TEST(KhronosAnimation, AnimatedTriangleMatchesTheSpecificationsSlerp) {
  expectPosesMatch(asset("AnimatedTriangle", "AnimatedTriangle.gltf"), {0.3, 0.85}, 0.3);
  // And the reference itself against the closed form: at t = 0.3 the turn is
  // 90 + 0.05 / 0.25 x 90 = 108 degrees (slerp turns at constant speed).
  const auto p = ref::pose(ref::read(asset("AnimatedTriangle", "AnimatedTriangle.gltf")), 0.3);
  const double angle = 108 * std::numbers::pi / 180;
  EXPECT_NEAR(p.begin()->second[1].x, std::cos(angle), 1e-6);
  EXPECT_NEAR(p.begin()->second[1].y, std::sin(angle), 1e-6);
}

// Two channels of different lengths (rotation of the inner box's node over
// [1.25, 2.5] s, translation of its grandparent over [0, 3.71] s) through a
// three-node hierarchy; the rotation's two keys are 180 degrees apart, with
// a dot product of -4.5e-11, so the short-way sign decides the direction.
TEST(KhronosAnimation, BoxAnimatedMatchesTheHierarchyAndBothChannels) {
  expectPosesMatch(asset("BoxAnimated", "BoxAnimated.glb"), {1.8, 3.0}, 0.3);
}

// Two morph targets whose weights are animated (LINEAR, two per keyframe) on
// a node rotated and scaled by 100.
TEST(KhronosAnimation, AnimatedMorphCubeMatchesTheWeightedTargets) {
  expectPosesMatch(asset("AnimatedMorphCube", "AnimatedMorphCube.glb"), {1.01, 2.77}, 0.5);
}

// A two-joint skin under two matrix nodes; the second joint's translation,
// rotation and scale are animated (LINEAR, 50 keys).
TEST(KhronosAnimation, RiggedSimpleMatchesTheJointMatrices) {
  expectPosesMatch(asset("RiggedSimple", "RiggedSimple.glb"), {0.61, 1.5}, 0.5);
}

// A two-joint skin whose second joint turns about z (LINEAR, 12 keys).
TEST(KhronosAnimation, SimpleSkinMatchesTheJointMatrices) {
  expectPosesMatch(asset("SimpleSkin", "SimpleSkin.gltf"), {1.3, 3.7}, 0.2);
}

// CUBICSPLINE (none of the Khronos five uses it): a translation, a rotation
// and two morph weights over keys at 0.5, 1.5 and 3.5 s (intervals 1 and 2, so
// a tangent not scaled by the interval, or scaled by the wrong one, shows),
// with in- and out-tangents that differ at every key (so swapping a_k and
// b_k, or using b_k+1 for a_k+1, shows).
TEST(KhronosAnimation, CubicSplineTangentsFollowTheSpecification) {
  test::GltfBuilder b;
  const int pos = b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  const int t0 = b.floats({0, 0, 0, 0, 0.5f, 0, 0, 0, 0}, "VEC3");
  const int t1 = b.floats({0, 0, 0, 0, 0, 0, 0, 0, 0.75f}, "VEC3");
  const int mesh =
      b.mesh({{"attributes", {{"POSITION", pos}}}, {"targets", {{{"POSITION", t0}}, {{"POSITION", t1}}}}});
  b.doc["meshes"][0]["weights"] = {0, 0};
  const int node = b.node({{"mesh", mesh}});
  const int times = b.floats({0.5f, 1.5f, 3.5f}, "SCALAR");
  // Per key: in-tangent, value, out-tangent.
  const int translation = b.floats({0.3f,  -0.2f, 0.1f, 0, 0,  0, 1,     2,    -1,  //
                                    -0.5f, 0.4f,  2,    1, 1,  0, 0.25f, -1,   3,   //
                                    2,     0,     -2,   3, -1, 2, 0.7f,  0.7f, 0.7f},
                                   "VEC3");
  // Rotations about z by 0, 60 and 150 degrees, tangents in quaternion units per second.
  const float c30 = float(std::cos(std::numbers::pi / 6)), s30 = 0.5f;
  const float c75 = float(std::cos(5 * std::numbers::pi / 12)),
              s75 = float(std::sin(5 * std::numbers::pi / 12));
  const int rotation = b.floats({0, 0, 0.1f, 0,     0, 0, 0,   1,   0, 0, 0.6f, -0.2f,  //
                                 0, 0, 0.3f, -0.1f, 0, 0, s30, c30, 0, 0, 0.2f, -0.4f,  //
                                 0, 0, 0.5f, 0.3f,  0, 0, s75, c75, 0, 0, 0,    0},
                                "VEC4");
  // Two weights per element: in-tangents, values, out-tangents.
  const int weights = b.floats({0, 0, 0, 0, 1, -0.5f,              //
                                0.4f, 0.2f, 1, 0.5f, -0.3f, 0.6f,  //
                                0.1f, 0.1f, 0.2f, 1, 0, 0},
                               "SCALAR");
  b.doc["animations"] =
      json::array({{{"samplers",
                     {{{"input", times}, {"output", translation}, {"interpolation", "CUBICSPLINE"}},
                      {{"input", times}, {"output", rotation}, {"interpolation", "CUBICSPLINE"}},
                      {{"input", times}, {"output", weights}, {"interpolation", "CUBICSPLINE"}}}},
                    {"channels",
                     {{{"sampler", 0}, {"target", {{"node", node}, {"path", "translation"}}}},
                      {{"sampler", 1}, {"target", {{"node", node}, {"path", "rotation"}}}},
                      {{"sampler", 2}, {"target", {{"node", node}, {"path", "weights"}}}}}}}});
  const fs::path file = test::writeFile(test::testDir() / "cubic.gltf", b.json());
  expectPosesMatch(file, {0.9, 1.2, 2.1, 3.1}, 0.5);

  // The reference's spline against the formula written out once by hand:
  // translation x at t = 2.1 lies in [1.5, 3.5], td = 2, u = 0.3; v_k = 1,
  // b_k = 0.25, v_k+1 = 3, a_k+1 = 2.
  const double u = 0.3, td = 2;
  const double x = (2 * u * u * u - 3 * u * u + 1) * 1 + td * (u * u * u - 2 * u * u + u) * 0.25 +
                   (-2 * u * u * u + 3 * u * u) * 3 + td * (u * u * u - u * u) * 2;
  const ref::Asset a = ref::read(file);
  EXPECT_NEAR(ref::sample(a, a.doc["animations"][0]["samplers"][0], 2.1, false)[0], x, 1e-6);
}

}  // namespace
}  // namespace lensrt
