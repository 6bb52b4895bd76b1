#include "scene/scene_motion.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/constants.h"

namespace lensrt {
namespace {

// The rotation part of a transform's linear part, its columns made
// orthonormal (Gram-Schmidt: exact for a rotation times a scale, a fair
// estimate under shear).
std::array<Vec3d, 3> rotationColumns(const Transform& xf) {
  const Transform::Matrix& m = xf.matrix();
  std::array<Vec3d, 3> c;
  for (int i = 0; i < 3; ++i) c[i] = {m[0][i], m[1][i], m[2][i]};
  const auto unit = [](const Vec3d& v) {
    const double l = length(v);
    return l > 0 ? v / l : Vec3d{0, 0, 0};
  };
  c[0] = unit(c[0]);
  c[1] = unit(c[1] - c[0] * dot(c[0], c[1]));
  c[2] = unit(c[2] - c[0] * dot(c[0], c[2]) - c[1] * dot(c[1], c[2]));
  return c;
}

// The angle, in degrees, of the rotation taking a's orientation to b's.
double turnDegrees(const Transform& a, const Transform& b) {
  const std::array<Vec3d, 3> ra = rotationColumns(a), rb = rotationColumns(b);
  double trace = 0;  // of ra^T rb
  for (int i = 0; i < 3; ++i) trace += dot(ra[i], rb[i]);
  return std::acos(std::clamp((trace - 1.0) / 2.0, -1.0, 1.0)) * 180.0 / kPi;
}

bool sameMeshShape(const Mesh& a, const Mesh& b) {
  return a.positions.size() == b.positions.size() && a.indices == b.indices &&
         a.normals.size() == b.normals.size() && a.tangents.size() == b.tangents.size();
}

}  // namespace

int motionStepCount(const std::vector<std::map<int, Transform>>& probeWorlds) {
  if (probeWorlds.size() < 2) return 2;
  const std::size_t segments = probeWorlds.size() - 1;
  double mostDegrees = 0;
  bool curved = false;
  for (const auto& [node, first] : probeWorlds.front()) {
    const auto lastIt = probeWorlds.back().find(node);
    if (lastIt == probeWorlds.back().end()) continue;
    const Vec3d p0 = first.point(Vec3d{0, 0, 0}), p1 = lastIt->second.point(Vec3d{0, 0, 0});
    const double travel = length(p1 - p0);
    double degrees = 0;
    for (std::size_t j = 1; j <= segments; ++j) {
      const auto a = probeWorlds[j - 1].find(node), b = probeWorlds[j].find(node);
      if (a == probeWorlds[j - 1].end() || b == probeWorlds[j].end()) continue;
      degrees += turnDegrees(a->second, b->second);
      // Off the straight line at constant speed between the ends?
      const Vec3d expected = p0 + (p1 - p0) * (double(j) / double(segments));
      const Vec3d p = b->second.point(Vec3d{0, 0, 0});
      if (length(p - expected) > 1e-3 * travel + 1e-9 * (1.0 + length(p0))) curved = true;
    }
    mostDegrees = std::max(mostDegrees, degrees);
  }
  const int turning = 1 + static_cast<int>(std::ceil(mostDegrees / kMaxDegreesPerMotionStep - 1e-9));
  const int steps = std::max({2, turning, curved ? static_cast<int>(segments) + 1 : 2});
  return std::min(steps, kMaxMotionSteps);
}

void addMotion(SceneDesc& still, const std::vector<SceneDesc>& poses, Warnings& warnings) {
  if (poses.empty()) return;
  const std::size_t stillMeshes = still.meshes.size();
  for (const SceneDesc& pose : poses) {
    bool same = pose.instances.size() == still.instances.size() &&
                pose.cameras.size() == still.cameras.size() && pose.lights.size() == still.lights.size();
    for (std::size_t i = 0; same && i < pose.instances.size(); ++i)
      same = sameMeshShape(still.meshes[still.instances[i].mesh], pose.meshes[pose.instances[i].mesh]);
    if (!same) {
      warnings.warn(
          "the animation changes what the scene holds during the shutter (instances or "
          "triangles): rendering it without motion blur");
      return;
    }
  }
  // Per pose, its meshes' indices in still.meshes once appended (-1: not yet).
  std::vector<std::vector<int>> appended(poses.size());
  std::vector<std::vector<MeshInstance::Step>> motion(still.instances.size());
  bool anyMoves = false;
  for (std::size_t i = 0; i < still.instances.size(); ++i) {
    const MeshInstance& inst = still.instances[i];
    std::vector<MeshInstance::Step>& steps = motion[i];
    steps.push_back({inst.mesh, inst.worldFromObject});
    bool moves = false;
    for (std::size_t k = 0; k < poses.size(); ++k) {
      const MeshInstance& posed = poses[k].instances[i];
      const Mesh& m = poses[k].meshes[posed.mesh];
      const Mesh& base = still.meshes[inst.mesh];
      int mesh = inst.mesh;
      if (m.positions != base.positions || m.normals != base.normals || m.tangents != base.tangents) {
        std::vector<int>& map = appended[k];
        map.resize(poses[k].meshes.size(), -1);
        if (map[posed.mesh] < 0) {
          map[posed.mesh] = static_cast<int>(still.meshes.size());
          still.meshes.push_back(m);
        }
        mesh = map[posed.mesh];
      }
      moves = moves || mesh != inst.mesh || !(posed.worldFromObject == inst.worldFromObject);
      steps.push_back({mesh, posed.worldFromObject});
    }
    if (!moves) steps.clear();
    anyMoves = anyMoves || moves;
  }
  // Cameras, in the same order in every pose.
  std::vector<std::vector<Transform>> cameraMotion(still.cameras.size());
  for (std::size_t c = 0; c < still.cameras.size(); ++c) {
    bool moves = false;
    cameraMotion[c].push_back(still.cameras[c].worldFromCamera);
    for (const SceneDesc& pose : poses) {
      const Transform& at =
          c < pose.cameras.size() ? pose.cameras[c].worldFromCamera : still.cameras[c].worldFromCamera;
      moves = moves || !(at == still.cameras[c].worldFromCamera);
      cameraMotion[c].push_back(at);
    }
    if (!moves) cameraMotion[c].clear();
    anyMoves = anyMoves || moves;
  }
  // Punctual lights, in the same order in every pose.
  std::vector<std::vector<PunctualLight::Step>> lightMotion(still.lights.size());
  for (std::size_t l = 0; l < still.lights.size(); ++l) {
    const PunctualLight& light = still.lights[l];
    bool moves = false;
    lightMotion[l].push_back({light.position, light.direction});
    for (const SceneDesc& pose : poses) {
      const PunctualLight& at = pose.lights[l];
      moves = moves || !(at.position == light.position) || !(at.direction == light.direction);
      lightMotion[l].push_back({at.position, at.direction});
    }
    if (!moves) lightMotion[l].clear();
    anyMoves = anyMoves || moves;
  }
  if (!anyMoves) {
    still.meshes.resize(stillMeshes);
    return;
  }
  for (std::size_t i = 0; i < still.instances.size(); ++i) still.instances[i].motion = std::move(motion[i]);
  for (std::size_t c = 0; c < still.cameras.size(); ++c) still.cameras[c].motion = std::move(cameraMotion[c]);
  for (std::size_t l = 0; l < still.lights.size(); ++l) still.lights[l].motion = std::move(lightMotion[l]);
  still.motionSteps = static_cast<int>(poses.size()) + 1;
}

}  // namespace lensrt
