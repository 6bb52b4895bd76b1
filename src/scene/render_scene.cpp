#include "scene/render_scene.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>
#include <vector>

#include "core/error.h"
#include "scene/embree_config.h"
#include "scene/embree_handles.h"
#include "scene/rigid_motion.h"
#include "scene/surface_alpha.h"

namespace lensrt {
namespace {

// Zero-scale placements have no area (and no inverse for normals): nothing to
// hit. Nearly singular ones neither (a scale like 1e-38; found by fuzz_gltf),
// nor products whose singular factor (a node scaled by 1e-40 under one scaled
// by 1e20) left a determinant that looks fine but no inverse.
bool degenerate(const Transform& xf) {
  const double det = xf.determinant3x3();
  if (!(std::abs(det) > 1e-30) || !std::isfinite(det) || !xf.invertible()) return true;
  const Transform inverse = xf.inverse();
  const Transform::Matrix& inv = inverse.matrix();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c)
      if (!std::isfinite(inv[r][c])) return true;
  return false;
}

// Largest |entry| of the 3x3 linear part.
double maxLinear(const Transform::Matrix& m) {
  double v = 0;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) v = std::max(v, std::abs(m[r][c]));
  return v;
}

// Embree inverts an instance transform in float and moves each ray into the
// instance's space; its rays must stay within |x| < 1.8e18 (ray.valid(), an
// assertion abort otherwise). A placement that scales by more than 1e6 or less
// than 1e-6, or would map a ray from `reach` (the largest coordinate a ray
// starts from) beyond 1e17, is baked into world space instead, which costs
// memory but nothing else (found by fuzz_gltf: unnormalised instance scales
// of 1e-18..1e37 on a flat mesh).
bool instanceable(const Transform& xf, double reach) {
  const Transform::Matrix& m = xf.matrix();
  const double forward = maxLinear(m), inverse = maxLinear(xf.inverse().matrix());
  const double translation = std::max({std::abs(m[0][3]), std::abs(m[1][3]), std::abs(m[2][3])});
  return forward <= 1e6 && inverse <= 1e6 && 3.0 * inverse * (reach + translation) <= 1e17;
}

// An instance's transform at `time` in [0, 1], as Embree interpolates its steps.
Transform transformAt(RTCGeometry instance, float time) {
  float xfm[12];
  rtcGetGeometryTransform(instance, std::clamp(time, 0.0f, 1.0f), RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm);
  Transform::Matrix m{};
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 3; ++r) m[r][c] = xfm[c * 3 + r];
  m[3][3] = 1;
  return Transform(m);
}

// Embree reports errors through a callback; C code cannot carry exceptions, so
// the callback keeps the message and `check` throws it after the failed call.
struct ErrorSlot {
  std::mutex mutex;
  std::string message;
};

void recordError(void* user, RTCError code, const char* str) {
  auto* slot = static_cast<ErrorSlot*>(user);
  const std::scoped_lock lock(slot->mutex);
  if (slot->message.empty()) slot->message = str ? str : "error code " + std::to_string(code);
}

std::string embreeErrorName(RTCError code) {
  switch (code) {
    case RTC_ERROR_NONE:
      return "no error reported";
    case RTC_ERROR_INVALID_ARGUMENT:
      return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION:
      return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY:
      return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU:
      return "unsupported CPU";
    case RTC_ERROR_CANCELLED:
      return "cancelled";
    default:
      return "unknown error " + std::to_string(code);
  }
}

// Everything the alpha filter needs, reachable from Embree's geometry user pointer.
struct AlphaMask {
  const SceneDesc* scene = nullptr;
  const Mesh* mesh = nullptr;
  const Material* material = nullptr;

  float alphaAt(unsigned prim, float u, float v) const {
    return surfaceAlpha(*scene, *mesh, *material, prim, u, v);
  }
};

// Embree hands the context of a query to the filter: this one carries the key
// of the world ray that stochastic transparency hashes.
struct QueryContext {
  RTCIntersectContext embree;  // first member: Embree sees a plain context
  std::uint64_t rayKey = 0;
};

std::uint64_t mix64(std::uint64_t x) {  // splitmix64's finaliser
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ull;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

std::uint64_t rayKey(const Ray& ray) {
  std::uint64_t h = 0x9e3779b97f4a7c15ull;
  for (const float f : {ray.origin.x, ray.origin.y, ray.origin.z, ray.direction.x, ray.direction.y,
                        ray.direction.z, ray.tMin}) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &f, sizeof bits);
    h = mix64(h ^ bits);
  }
  return h;
}

// A uniform number in [0, 1) for one ray meeting one triangle of one placement.
float transparencyDraw(std::uint64_t key, unsigned geomID, unsigned instID, unsigned prim) {
  const std::uint64_t h = mix64(
      key ^ mix64((std::uint64_t{geomID} << 32 | instID) ^ (std::uint64_t{prim} * 0x9e3779b97f4a7c15ull)));
  return static_cast<float>(h >> 40) * 0x1.0p-24f;
}

// Shared by intersection and occlusion: rejecting a candidate makes Embree go on.
void alphaFilter(const RTCFilterFunctionNArguments* args) {
  const auto* mask = static_cast<const AlphaMask*>(args->geometryUserPtr);
  const auto* context = reinterpret_cast<const QueryContext*>(args->context);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    const unsigned prim = RTCHitN_primID(args->hit, args->N, i);
    const float alpha =
        mask->alphaAt(prim, RTCHitN_u(args->hit, args->N, i), RTCHitN_v(args->hit, args->N, i));
    const bool opaque = mask->material->alphaMode == AlphaMode::Blend
                            ? transparencyDraw(context->rayKey, RTCHitN_geomID(args->hit, args->N, i),
                                               RTCHitN_instID(args->hit, args->N, i, 0), prim) < alpha
                            : alpha >= mask->material->alphaCutoff;
    if (!opaque) args->valid[i] = 0;
  }
}

// Embree's memory monitor: counts what the device allocates (never refuses).
bool countEmbreeBytes(void* user, ssize_t bytes, bool /*post*/) {
  static_cast<std::atomic<std::int64_t>*>(user)->fetch_add(bytes, std::memory_order_relaxed);
  return true;
}

// What a top-level Embree geometry ID stands for.
struct GeometryRecord {
  int instance = -1;
  int mesh = -1;
  bool mirrored = false;
  // A baked mesh's world-space vertices (x, y, z per vertex) as Embree holds
  // them: the very floats hitAt would compute with the instance transform.
  // Null for an Embree instance (its vertices are in object space).
  const float* worldVertices = nullptr;
  // A moving instance's world-space vertices at each time step (Embree's
  // vertex buffers, in slot order); empty when still.
  std::vector<const float*> stepVertices;
  // A rigidly moving instance: its Embree instance (held by the top scene),
  // which gives its transform at a ray's time as Embree interpolates it.
  RTCGeometry rigidMotion = nullptr;
};

}  // namespace

struct RenderScene::Impl {
  SceneDesc desc;
  ErrorSlot errors;
  std::optional<std::string> config;  // LENSRT_EMBREE_CONFIG
  // Before the device: Embree reports frees while the scenes are released.
  std::atomic<std::int64_t> embreeBytes{0};
  EmbreeDevice device;
  std::vector<EmbreeScene> sharedScenes;  // by mesh index, only for shared meshes
  EmbreeScene top;
  std::vector<AlphaMask> masks;  // by mesh index; stable, Embree points into it
  bool blendMasks = false;       // some mask is AlphaMode::Blend: its filter needs the ray's key
  std::vector<GeometryRecord> records;
  Stats stats;

  void check(const char* what) {
    if (rtcGetDeviceError(device.get()) == RTC_ERROR_NONE) return;
    const std::scoped_lock lock(errors.mutex);
    // An acceleration structure named in LENSRT_EMBREE_CONFIG is Embree's to
    // judge: its refusal names the variable.
    throw InputError(
        desc.sourceFile,
        std::string("Embree failed to ") + what + ": " + errors.message +
            (config ? std::string(" (") + kEmbreeConfigVariable + "='" + *config + "')" : std::string()));
  }

  void validate() const;
  void buildMasks();
  // `vertices` receives Embree's vertex buffer (world space when baked).
  EmbreeGeometry newTriangles(int meshIndex, const Transform* bake, const float** vertices);
  // A moving instance, baked at each of its time steps (Embree interpolates
  // linearly between them at the ray's time).
  EmbreeGeometry newMovingTriangles(const MeshInstance& inst, std::vector<const float*>& stepVertices);
  void finishTriangles(RTCGeometry geom, int meshIndex);
  void build();
  SurfaceHit hitAt(const GeometryRecord& rec, unsigned prim, float u, float v, float t, const Vec3f& dir,
                   float time) const;
};

void RenderScene::Impl::validate() const {
  for (const Mesh& m : desc.meshes) {
    const std::string label = "mesh '" + m.name + "': ";
    if (m.indices.size() % 3 != 0)
      throw InputError(desc.sourceFile, label + "index count is not a multiple of 3");
    for (const std::uint32_t i : m.indices)
      if (i >= m.positions.size())
        throw InputError(desc.sourceFile, label + "index " + std::to_string(i) + " beyond vertex count " +
                                              std::to_string(m.positions.size()));
    for (const Vec3f& p : m.positions)
      if (!isFinite(p)) throw InputError(desc.sourceFile, label + "non-finite vertex position");
    if (!m.normals.empty() && m.normals.size() != m.positions.size())
      throw InputError(desc.sourceFile, label + "normal count differs from position count");
    if (!m.tangents.empty() && m.tangents.size() != m.positions.size())
      throw InputError(desc.sourceFile, label + "tangent count differs from position count");
    if (!m.uvs.empty() && m.uvs.size() != m.positions.size())
      throw InputError(desc.sourceFile, label + "uv count differs from position count");
    if (!m.uvs1.empty() && m.uvs1.size() != m.positions.size())
      throw InputError(desc.sourceFile, label + "TEXCOORD_1 count differs from position count");
    if (!m.colors.empty() && m.colors.size() != m.positions.size())
      throw InputError(desc.sourceFile, label + "colour count differs from position count");
    if (m.material < -1 || m.material >= static_cast<int>(desc.materials.size()))
      throw InputError(desc.sourceFile, label + "material index out of range");
  }
  for (const Material& mat : desc.materials)
    for (const TextureRef* ref :
         {&mat.baseColorTexture, &mat.metallicRoughnessTexture, &mat.normalTexture, &mat.emissiveTexture})
      if (ref->texture >= static_cast<int>(desc.textures.size()))
        throw InputError(desc.sourceFile, "material '" + mat.name + "': texture index out of range");
  for (const MeshInstance& inst : desc.instances) {
    if (inst.mesh < 0 || inst.mesh >= static_cast<int>(desc.meshes.size()))
      throw InputError(desc.sourceFile, "instance of mesh " + std::to_string(inst.mesh) + " out of range");
    if (!inst.moves()) continue;
    if (static_cast<int>(inst.motion.size()) != desc.motionSteps || desc.motionSteps < 2 ||
        desc.motionSteps > 129)
      throw InputError(desc.sourceFile, "a moving instance's time steps do not match the scene's");
    const Mesh& still = desc.meshes[inst.mesh];
    for (const MeshInstance::Step& step : inst.motion)
      if (step.mesh < 0 || step.mesh >= static_cast<int>(desc.meshes.size()) ||
          desc.meshes[step.mesh].positions.size() != still.positions.size() ||
          desc.meshes[step.mesh].normals.size() != still.normals.size() ||
          desc.meshes[step.mesh].tangents.size() != still.tangents.size() ||
          desc.meshes[step.mesh].indices != still.indices)
        throw InputError(desc.sourceFile, "a moving instance's time step has another mesh shape");
  }
}

void RenderScene::Impl::buildMasks() {
  masks.resize(desc.meshes.size());
  for (std::size_t i = 0; i < desc.meshes.size(); ++i) {
    const Mesh& m = desc.meshes[i];
    if (m.material < 0) continue;
    const Material& mat = desc.materials[m.material];
    if (mat.alphaMode == AlphaMode::Opaque) continue;
    masks[i] = {&desc, &m, &mat};
    if (mat.alphaMode == AlphaMode::Blend) blendMasks = true;
  }
}

EmbreeGeometry RenderScene::Impl::newTriangles(int meshIndex, const Transform* bake,
                                               const float** vertexBuffer) {
  const Mesh& m = desc.meshes[meshIndex];
  EmbreeGeometry geom(rtcNewGeometry(device.get(), RTC_GEOMETRY_TYPE_TRIANGLE));
  check("create a triangle geometry");
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geom.get(), RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), m.positions.size()));
  check("allocate a vertex buffer");
  *vertexBuffer = vertices;
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    const Vec3f p = bake ? bake->point(m.positions[i]) : m.positions[i];
    vertices[3 * i] = p.x;
    vertices[3 * i + 1] = p.y;
    vertices[3 * i + 2] = p.z;
  }
  finishTriangles(geom.get(), meshIndex);
  return geom;
}

EmbreeGeometry RenderScene::Impl::newMovingTriangles(const MeshInstance& inst,
                                                     std::vector<const float*>& stepVertices) {
  EmbreeGeometry geom(rtcNewGeometry(device.get(), RTC_GEOMETRY_TYPE_TRIANGLE));
  check("create a triangle geometry");
  rtcSetGeometryTimeStepCount(geom.get(), static_cast<unsigned>(inst.motion.size()));
  check("set the time steps of a moving mesh");
  stepVertices.clear();
  for (std::size_t k = 0; k < inst.motion.size(); ++k) {
    const Mesh& m = desc.meshes[inst.motion[k].mesh];
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geom.get(), RTC_BUFFER_TYPE_VERTEX,
                                                                 static_cast<unsigned>(k), RTC_FORMAT_FLOAT3,
                                                                 3 * sizeof(float), m.positions.size()));
    check("allocate a vertex buffer");
    stepVertices.push_back(vertices);
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
      const Vec3f p = inst.motion[k].worldFromObject.point(m.positions[i]);
      // The loader checked the opening pose alone; the animation may carry a mesh off later.
      if (!(std::abs(p.x) <= 1e15f && std::abs(p.y) <= 1e15f && std::abs(p.z) <= 1e15f))
        throw InputError(desc.sourceFile,
                         "mesh '" + m.name + "' moves beyond 1e15 during the shutter (check the animation)");
      vertices[3 * i] = p.x;
      vertices[3 * i + 1] = p.y;
      vertices[3 * i + 2] = p.z;
    }
  }
  finishTriangles(geom.get(), inst.mesh);
  return geom;
}

// The index buffer, the alpha filter and the commit, for still and moving meshes alike.
void RenderScene::Impl::finishTriangles(RTCGeometry geom, int meshIndex) {
  const Mesh& m = desc.meshes[meshIndex];
  auto* indices = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
      geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t), m.triangleCount()));
  check("allocate an index buffer");
  std::copy(m.indices.begin(), m.indices.end(), indices);
  rtcSetGeometryBuildQuality(geom, RTC_BUILD_QUALITY_HIGH);
  if (masks[meshIndex].mesh) {
    rtcSetGeometryUserData(geom, &masks[meshIndex]);
    rtcSetGeometryIntersectFilterFunction(geom, alphaFilter);
    rtcSetGeometryOccludedFilterFunction(geom, alphaFilter);
  }
  rtcCommitGeometry(geom);
  check("commit a triangle geometry");
}

void RenderScene::Impl::build() {
  validate();
  buildMasks();
  // LENSRT_EMBREE_CONFIG goes to rtcNewDevice (e.g. "isa=sse4.2"), checked
  // first: Embree picks its kernels by the CPU's instruction set, so CI runs
  // the scene and render suites once more held to a lower ISA than the machine's.
  config = embreeConfigFromEnvironment();
  device.reset(rtcNewDevice(config ? config->c_str() : nullptr));
  if (!device) {
    const std::string why = embreeErrorName(rtcGetDeviceError(nullptr));
    throw InputError(desc.sourceFile, config ? std::string("cannot create the Embree device with ") +
                                                   kEmbreeConfigVariable + "='" + *config + "' (" + why + ")"
                                             : "cannot create the Embree device (" + why + ")");
  }
  rtcSetDeviceErrorFunction(device.get(), recordError, &errors);
  rtcSetDeviceMemoryMonitorFunction(device.get(), countEmbreeBytes, &embreeBytes);

  const auto newScene = [&] {
    EmbreeScene s(rtcNewScene(device.get()));
    check("create a scene");
    // Robust traversal: no missed hits on shared edges, the renderer relies on watertightness.
    rtcSetSceneFlags(s.get(), RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(s.get(), RTC_BUILD_QUALITY_HIGH);
    return s;
  };

  // Rays start on the geometry, at a camera or at the default view (a few
  // scene radii out): a generous bound on their coordinates.
  const Bounds3f world = desc.worldBounds();
  double reach = 1.0;
  for (int a = 0; a < 3; ++a)
    reach = std::max({reach, std::abs(double(world.lo[a])), std::abs(double(world.hi[a]))});
  for (const CameraDesc& c : desc.cameras) {
    const Vec3d eye = c.worldFromCamera.point(Vec3d(0, 0, 0));
    reach = std::max({reach, std::abs(eye.x), std::abs(eye.y), std::abs(eye.z)});
  }
  reach *= 8.0;

  // Per instance: skipped (degenerate), baked into world space, or placed as an Embree instance.
  enum class Placement { Skip, Bake, Instance, RigidMotion };
  std::vector<Placement> placement(desc.instances.size(), Placement::Skip);
  std::vector<int> uses(desc.meshes.size(), 0);
  std::vector<bool> movesRigidly(desc.meshes.size(), false);  // a shared scene for its instances
  std::vector<std::vector<RTCQuaternionDecomposition>> rigidSteps(desc.instances.size());
  for (std::size_t i = 0; i < desc.instances.size(); ++i) {
    const MeshInstance& inst = desc.instances[i];
    if (desc.meshes[inst.mesh].triangleCount() == 0) continue;
    if (inst.moves()) {
      // A mesh that keeps its shape and turns moves as an Embree instance
      // whose rotation Embree slerps (a true arc). A deforming one is baked
      // at each time step, and so is one that only slides (a baked mesh
      // costs rays less than a moving instance: 1.15x against 1.5x the still
      // render's instructions in tools/bench's scene) and an emitter (the
      // light sampler poses emitters linearly between steps).
      const int material = desc.meshes[inst.mesh].material;
      bool rigid = material < 0 || !desc.materials[material].isEmissive(), turns = false;
      std::vector<Transform> steps;
      for (const MeshInstance::Step& step : inst.motion) {
        rigid = rigid && step.mesh == inst.mesh && !degenerate(step.worldFromObject) &&
                instanceable(step.worldFromObject, reach);
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c)
            turns = turns || step.worldFromObject.matrix()[r][c] != inst.worldFromObject.matrix()[r][c];
        steps.push_back(step.worldFromObject);
      }
      rigid = rigid && turns;
      auto decomposed = rigid ? rigidMotionSteps(steps) : std::nullopt;
      placement[i] = decomposed ? Placement::RigidMotion : Placement::Bake;
      if (decomposed) {
        rigidSteps[i] = std::move(*decomposed);
        movesRigidly[inst.mesh] = true;
      }
      continue;
    }
    if (degenerate(inst.worldFromObject)) continue;
    placement[i] = instanceable(inst.worldFromObject, reach) ? Placement::Instance : Placement::Bake;
    if (placement[i] == Placement::Instance) ++uses[inst.mesh];
  }
  // A mesh placed once is baked too.
  for (std::size_t i = 0; i < desc.instances.size(); ++i)
    if (placement[i] == Placement::Instance && uses[desc.instances[i].mesh] < 2)
      placement[i] = Placement::Bake;

  sharedScenes.resize(desc.meshes.size());
  for (std::size_t i = 0; i < desc.meshes.size(); ++i) {
    if (uses[i] < 2 && !movesRigidly[i]) continue;
    sharedScenes[i] = newScene();
    const float* objectVertices = nullptr;
    EmbreeGeometry geom = newTriangles(static_cast<int>(i), nullptr, &objectVertices);
    rtcAttachGeometryByID(sharedScenes[i].get(), geom.get(), 0);
    check("attach a shared mesh");
    rtcCommitScene(sharedScenes[i].get());
    check("build a shared mesh");
    ++stats.sharedMeshes;
  }

  top = newScene();
  for (std::size_t i = 0; i < desc.instances.size(); ++i) {
    const MeshInstance& inst = desc.instances[i];
    if (placement[i] == Placement::Skip) continue;
    EmbreeGeometry geom;
    const float* worldVertices = nullptr;
    std::vector<const float*> stepVertices;
    if (placement[i] == Placement::RigidMotion) {
      geom.reset(rtcNewGeometry(device.get(), RTC_GEOMETRY_TYPE_INSTANCE));
      check("create an instance");
      rtcSetGeometryInstancedScene(geom.get(), sharedScenes[inst.mesh].get());
      rtcSetGeometryTimeStepCount(geom.get(), static_cast<unsigned>(rigidSteps[i].size()));
      for (std::size_t k = 0; k < rigidSteps[i].size(); ++k)
        rtcSetGeometryTransformQuaternion(geom.get(), static_cast<unsigned>(k), &rigidSteps[i][k]);
      rtcCommitGeometry(geom.get());
      check("commit a moving instance");
      ++stats.embreeInstances;
    } else if (inst.moves()) {
      geom = newMovingTriangles(inst, stepVertices);
      ++stats.bakedGeometries;
    } else if (placement[i] == Placement::Bake) {
      geom = newTriangles(inst.mesh, &inst.worldFromObject, &worldVertices);
      ++stats.bakedGeometries;
    } else {
      geom.reset(rtcNewGeometry(device.get(), RTC_GEOMETRY_TYPE_INSTANCE));
      check("create an instance");
      rtcSetGeometryInstancedScene(geom.get(), sharedScenes[inst.mesh].get());
      float xfm[12];
      const Transform::Matrix& m = inst.worldFromObject.matrix();
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 3; ++r) xfm[c * 3 + r] = static_cast<float>(m[r][c]);
      rtcSetGeometryTransform(geom.get(), 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm);
      rtcCommitGeometry(geom.get());
      check("commit an instance");
      ++stats.embreeInstances;
    }
    const auto id = static_cast<unsigned>(records.size());
    rtcAttachGeometryByID(top.get(), geom.get(), id);
    check("attach a geometry");
    records.push_back({static_cast<int>(i), inst.mesh, inst.worldFromObject.determinant3x3() < 0.0,
                       worldVertices, std::move(stepVertices),
                       placement[i] == Placement::RigidMotion ? geom.get() : nullptr});
  }
  rtcCommitScene(top.get());
  check("build the scene");
}

SurfaceHit RenderScene::Impl::hitAt(const GeometryRecord& rec, unsigned prim, float u, float v, float t,
                                    const Vec3f& dir, float time) const {
  const MeshInstance& inst = desc.instances[rec.instance];
  const Mesh& m = desc.meshes[rec.mesh];
  const std::uint32_t* idx = &m.indices[3 * static_cast<std::size_t>(prim)];
  const float w = 1 - u - v;
  const auto interp3 = [&](const std::vector<Vec3f>& a) {
    return a[idx[0]] * w + a[idx[1]] * u + a[idx[2]] * v;
  };
  // A moving instance: the two time steps around the ray's time, and how
  // far between them, as Embree interpolates (linearly in the vertices).
  std::size_t step = 0;
  float between = 0;
  if (!rec.stepVertices.empty()) {
    const float f = std::clamp(time, 0.0f, 1.0f) * float(rec.stepVertices.size() - 1);
    step = std::min(static_cast<std::size_t>(f), rec.stepVertices.size() - 2);
    between = f - float(step);
  }
  // A rigidly moving instance: its placement at the ray's time, as Embree
  // interpolated it (slerp of the rotation) to find the hit.
  // (A reference otherwise: a copy would cost every hit of every scene.)
  std::optional<Transform> timed;
  if (rec.rigidMotion) timed = transformAt(rec.rigidMotion, time);
  const Transform& xf = timed ? *timed : inst.worldFromObject;
  // A vertex attribute's world vector at the hit, interpolated in time too.
  const auto stepped = [&](const auto& attribute, const auto& toWorld) {
    const Vec3f a = toWorld(xf, attribute(m));
    if (rec.stepVertices.empty()) return a;
    const Vec3f a0 =
        toWorld(inst.motion[step].worldFromObject, attribute(desc.meshes[inst.motion[step].mesh]));
    const Vec3f a1 =
        toWorld(inst.motion[step + 1].worldFromObject, attribute(desc.meshes[inst.motion[step + 1].mesh]));
    return a0 * (1 - between) + a1 * between;
  };

  SurfaceHit hit;
  hit.t = t;
  hit.primitive = prim;
  hit.barycentric = {u, v};
  hit.instance = rec.instance;
  hit.material = m.material;
  const auto world = [&](std::uint32_t i) {
    if (!rec.stepVertices.empty()) {
      const float* p0 = rec.stepVertices[step] + 3 * static_cast<std::size_t>(i);
      const float* p1 = rec.stepVertices[step + 1] + 3 * static_cast<std::size_t>(i);
      return Vec3f{p0[0], p0[1], p0[2]} * (1 - between) + Vec3f{p1[0], p1[1], p1[2]} * between;
    }
    if (!rec.worldVertices) return xf.point(m.positions[i]);
    const float* p = rec.worldVertices + 3 * static_cast<std::size_t>(i);
    return Vec3f{p[0], p[1], p[2]};
  };
  const Vec3f p0 = world(idx[0]), p1 = world(idx[1]), p2 = world(idx[2]);
  hit.position = p0 * w + p1 * u + p2 * v;
  hit.objectPosition = interp3(m.positions);
  // glTF: counter-clockwise is the front unless the world transform mirrors.
  Vec3f ng = cross(p1 - p0, p2 - p0);
  if (rec.mirrored) ng = -ng;
  // (value_or would normalise the fallback at every hit.)
  if (const auto n = unitVector(ng))
    hit.geometricNormal = *n;
  else
    hit.geometricNormal = normalize(-dir);

  hit.shadingNormal = hit.geometricNormal;
  if (!m.normals.empty()) {
    const Vec3f n = stepped([&](const Mesh& mesh) { return interp3(mesh.normals); },
                            [](const Transform& x, const Vec3f& a) { return x.normal(a); });
    if (const auto unit = unitVector(n)) hit.shadingNormal = *unit;
    if (dot(hit.shadingNormal, hit.geometricNormal) < 0) hit.shadingNormal = -hit.shadingNormal;
  }
  if (!m.tangents.empty()) {
    const Vec4f& t0 = m.tangents[idx[0]];
    const Vec3f tv = stepped(
        [&](const Mesh& mesh) {
          return mesh.tangents[idx[0]].xyz() * w + mesh.tangents[idx[1]].xyz() * u +
                 mesh.tangents[idx[2]].xyz() * v;
        },
        [](const Transform& x, const Vec3f& a) { return x.vector(a); });
    if (const auto tn = unitVector(tv)) {
      // A mirror flips cross(normal, tangent), so the handedness flips with it.
      const float handedness = (t0.w < 0 ? -1.0f : 1.0f) * (rec.mirrored ? -1.0f : 1.0f);
      hit.tangent = {tn->x, tn->y, tn->z, handedness};
    }
  }
  if (!m.uvs.empty()) hit.uv = m.uvs[idx[0]] * w + m.uvs[idx[1]] * u + m.uvs[idx[2]] * v;
  if (!m.uvs1.empty()) hit.uv1 = m.uvs1[idx[0]] * w + m.uvs1[idx[1]] * u + m.uvs1[idx[2]] * v;
  if (!m.colors.empty()) {
    // Embree's barycentrics can stray just outside the triangle (far-away
    // rays; found by mutating the fuzz seed): keep colours in [0, 1].
    const Vec4f &c0 = m.colors[idx[0]], &c1 = m.colors[idx[1]], &c2 = m.colors[idx[2]];
    const auto mix = [&](float a, float b, float c) { return std::clamp(a * w + b * u + c * v, 0.0f, 1.0f); };
    hit.color = {mix(c0.x, c1.x, c2.x), mix(c0.y, c1.y, c2.y), mix(c0.z, c1.z, c2.z), mix(c0.w, c1.w, c2.w)};
  }
  return hit;
}

RenderScene::RenderScene(SceneDesc desc) : impl_(std::make_unique<Impl>()) {
  impl_->desc = std::move(desc);
  impl_->build();
}

RenderScene::~RenderScene() = default;

std::optional<SurfaceHit> RenderScene::intersect(const Ray& ray) const {
  QueryContext context;
  rtcInitIntersectContext(&context.embree);
  context.rayKey = impl_->blendMasks ? rayKey(ray) : 0;  // only stochastic transparency reads it
  RTCRayHit rh{};
  rh.ray.org_x = ray.origin.x;
  rh.ray.org_y = ray.origin.y;
  rh.ray.org_z = ray.origin.z;
  rh.ray.dir_x = ray.direction.x;
  rh.ray.dir_y = ray.direction.y;
  rh.ray.dir_z = ray.direction.z;
  rh.ray.tnear = ray.tMin;
  rh.ray.tfar = ray.tMax;
  rh.ray.mask = 0xFFFFFFFFu;
  rh.ray.time = ray.time;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->top.get(), &context.embree, &rh);
  // Embree's float arithmetic can overflow on extreme geometry (fuzz_gltf: a
  // hit at t = inf through an instance): a hit that is not finite is no hit.
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID || !std::isfinite(rh.ray.tfar)) return std::nullopt;
  // Instanced hits name the top-level instance in instID; baked ones in geomID.
  const unsigned topId = rh.hit.instID[0] != RTC_INVALID_GEOMETRY_ID ? rh.hit.instID[0] : rh.hit.geomID;
  SurfaceHit hit = impl_->hitAt(impl_->records[topId], rh.hit.primID, rh.hit.u, rh.hit.v, rh.ray.tfar,
                                ray.direction, ray.time);
  if (!isFinite(hit.position)) return std::nullopt;
  return hit;
}

bool RenderScene::occluded(const Ray& ray) const {
  QueryContext context;
  rtcInitIntersectContext(&context.embree);
  context.rayKey = impl_->blendMasks ? rayKey(ray) : 0;  // only stochastic transparency reads it
  RTCRay r{};
  r.org_x = ray.origin.x;
  r.org_y = ray.origin.y;
  r.org_z = ray.origin.z;
  r.dir_x = ray.direction.x;
  r.dir_y = ray.direction.y;
  r.dir_z = ray.direction.z;
  r.tnear = ray.tMin;
  r.tfar = ray.tMax;
  r.mask = 0xFFFFFFFFu;
  r.time = ray.time;
  rtcOccluded1(impl_->top.get(), &context.embree, &r);
  return r.tfar == -kInfinityF;  // Embree marks a blocked ray this way
}

const SceneDesc& RenderScene::desc() const {
  return impl_->desc;
}

SceneDesc RenderScene::releaseDesc() && {
  SceneDesc desc = std::move(impl_->desc);
  impl_.reset();
  return desc;
}

Bounds3f RenderScene::bounds() const {
  RTCBounds b;
  rtcGetSceneBounds(impl_->top.get(), &b);
  Bounds3f out;
  if (impl_->records.empty() || !(b.lower_x <= b.upper_x)) return out;
  out.lo = {b.lower_x, b.lower_y, b.lower_z};
  out.hi = {b.upper_x, b.upper_y, b.upper_z};
  return out;
}

RenderScene::Stats RenderScene::stats() const {
  Stats s = impl_->stats;
  s.embreeBytes = impl_->embreeBytes.load(std::memory_order_relaxed);
  return s;
}

RTCSceneTy* RenderScene::embreeScene() const {
  return impl_->top.get();
}

}  // namespace lensrt
