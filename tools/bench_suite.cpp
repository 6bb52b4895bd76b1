// The measuring half of tools/bench (which builds the scenes, runs this
// program, perf and `lensrt`, and prints the table). Each subcommand prints
// one JSON object on stdout; times are wall-clock seconds (steady_clock).
//
//   bench_suite rays SCENE     record the rays of a pass (camera, bounce and shadow
//                              rays, through Integrator's RayObserver), trace them with
//                              Embree alone (rtcIntersect1/rtcOccluded1, 4/8/16-wide
//                              packets, rtcIntersect1M streams) and time the renderer
//                              on the same pass
//   bench_suite render SCENE   render once per camera model (best of --repeat), the
//                              camera alone per ray, 1 vs N threads, every ray counted,
//                              peak RSS against geometry, textures and Embree's bytes
//   bench_suite startup SCENE  glTF load, BVH build, lights, full-lens set-up
//
// Common flags: --env constant:0.5 --res 480x320 --spp 64 --depth 5 --threads 2
// and lensrt render's camera flags (--lens, --fstop, --focus, ...).
#include <embree3/rtcore.h>
#include <fcntl.h>
#include <fmt/core.h>
#include <sys/resource.h>
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <functional>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "api/camera_factory.h"
#include "api/camera_models.h"
#include "api/render_job.h"
#include "api/render_options.h"
#include "api/render_spec.h"
#include "app/option_flags.h"
#include "core/error.h"
#include "render/environment.h"
#include "render/integrator.h"
#include "render/lights.h"
#include "render/material_eval.h"
#include "render/ray_observer.h"
#include "render/renderer.h"
#include "render/sampler.h"
#include "scene/camera_selection.h"
#include "scene/gltf_loader.h"
#include "scene/render_scene.h"

namespace {

using namespace lensrt;
// Keys in the order written, so the table keeps the models in their order.
using json = nlohmann::ordered_json;

double wallSeconds(const std::function<void()>& f) {
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::int64_t peakRssBytes() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return std::int64_t(u.ru_maxrss) * 1024;
}

struct Options {
  std::string scene;
  std::string env = "constant:0.5";
  std::string res = "480x320";
  int spp = 64;
  int depth = 5;
  int threads = 2;
  int repeat = 1;
  int recordSpp = 2;
  std::string models = "pinhole,thin,thick,lens";
  bool countRays = false;
  bool scaling = false;
  std::string perfControl, perfAck;  // perf record's control and ack fifos
  RenderSpec spec;                   // its camera, shutter and flare: lensrt render's flags
};

// Everything a render needs but the camera, built step by step so each step can be timed.
struct Setup {
  double loadSeconds = 0, buildSeconds = 0, lightsSeconds = 0;
  int width = 0, height = 0;
  CameraDesc gltfCamera;
  std::unique_ptr<RenderScene> scene;
  std::unique_ptr<MaterialTable> materials;
  Environment environment;
  std::unique_ptr<LightSet> lights;
  IntegratorSettings integratorSettings;

  Setup(const Options& o, Warnings& warnings) {
    const Resolution r = parseResolution(o.res);
    width = r.width;
    height = r.height;
    SceneDesc desc;
    loadSeconds = wallSeconds([&] { desc = loadGltf(o.scene, -1, warnings); });
    gltfCamera = selectCamera(desc, "", float(width) / float(height));
    buildSeconds = wallSeconds([&] { scene = std::make_unique<RenderScene>(std::move(desc)); });
    environment = makeEnvironment(parseEnvironment(o.env));
    lightsSeconds = wallSeconds([&] {
      materials = std::make_unique<MaterialTable>(scene->desc());
      lights = std::make_unique<LightSet>(*materials, environment, scene->bounds());
    });
    integratorSettings.maxDepth = o.depth;
  }

  Integrator integrator(RayObserver* observer = nullptr) const {
    IntegratorSettings s = integratorSettings;
    s.observer = observer;
    return Integrator(*scene, *materials, *lights, environment, s);
  }

  std::unique_ptr<Camera> camera(const Options& o, const std::string& model, Warnings& warnings) const {
    CameraSpec c = o.spec.camera;
    for (const CameraModelInfo& m : cameraModels())
      if (m.name == model) c.model = m.model;
    FilmGeometry film;
    film.width = width;
    film.height = height;
    const HitDistance hit = [&](const Ray& ray) -> std::optional<double> {
      const auto h = scene->intersect(ray);
      return h ? std::optional<double>(h->t) : std::nullopt;
    };
    return makeCamera(CameraRequest{c, o.spec.shutter, o.spec.flare}, gltfCamera, film, hit, warnings);
  }

  json sizes() const {
    const SceneDesc& d = scene->desc();
    std::int64_t geometry = 0, textures = 0, triangles = 0;
    for (const Mesh& m : d.meshes) {
      geometry += std::int64_t(m.positions.size() * sizeof(Vec3f) + m.normals.size() * sizeof(Vec3f) +
                               m.tangents.size() * sizeof(Vec4f) + m.uvs.size() * sizeof(Vec2f) +
                               m.uvs1.size() * sizeof(Vec2f) + m.colors.size() * sizeof(Vec4f) +
                               m.indices.size() * sizeof(std::uint32_t));
    }
    for (const MeshInstance& i : d.instances) triangles += std::int64_t(d.meshes[i.mesh].triangleCount());
    for (const Texture& t : d.textures) textures += std::int64_t(t.texels.size() * sizeof(Vec4f));
    const RenderScene::Stats s = scene->stats();
    return {{"triangles", triangles},
            {"geometry_bytes", geometry},
            {"texture_bytes", textures},
            {"embree_bytes", s.embreeBytes},
            {"embree_geometries", s.bakedGeometries},
            {"embree_instances", s.embreeInstances}};
  }
};

// --- recording and tracing rays with Embree alone ----------------------------------------

struct CompactRay {
  float org[3], dir[3], tnear, tfar;
};

class Recorder final : public RayObserver {
 public:
  void traced(RayKind kind, const Ray& r) override {
    buffers_.local()[std::size_t(kind)].push_back({{r.origin.x, r.origin.y, r.origin.z},
                                                   {r.direction.x, r.direction.y, r.direction.z},
                                                   r.tMin,
                                                   r.tMax});
  }
  // Each thread's rays in the order it traced them (a tile's camera rays stay together).
  std::vector<CompactRay> rays(RayKind kind) const {
    std::vector<CompactRay> out;
    for (const auto& b : buffers_)
      out.insert(out.end(), b[std::size_t(kind)].begin(), b[std::size_t(kind)].end());
    return out;
  }

 private:
  tbb::enumerable_thread_specific<std::array<std::vector<CompactRay>, 3>> buffers_;
};

class Counter final : public RayObserver {
 public:
  void traced(RayKind kind, const Ray&) override { ++counts_.local()[std::size_t(kind)]; }
  std::uint64_t count(RayKind kind) const {
    std::uint64_t n = 0;
    for (const auto& c : counts_) n += c[std::size_t(kind)];
    return n;
  }

 private:
  tbb::enumerable_thread_specific<std::array<std::uint64_t, 3>> counts_{std::array<std::uint64_t, 3>{}};
};

void fill(RTCRay& r, const CompactRay& c) {
  r = RTCRay{};
  r.org_x = c.org[0];
  r.org_y = c.org[1];
  r.org_z = c.org[2];
  r.dir_x = c.dir[0];
  r.dir_y = c.dir[1];
  r.dir_z = c.dir[2];
  r.tnear = c.tnear;
  r.tfar = c.tfar;
  r.mask = 0xFFFFFFFFu;
}

template <class RayN>
void fillLane(RayN& r, int i, const CompactRay& c) {
  r.org_x[i] = c.org[0];
  r.org_y[i] = c.org[1];
  r.org_z[i] = c.org[2];
  r.dir_x[i] = c.dir[0];
  r.dir_y[i] = c.dir[1];
  r.dir_z[i] = c.dir[2];
  r.tnear[i] = c.tnear;
  r.tfar[i] = c.tfar;
  r.time[i] = 0;
  r.mask[i] = 0xFFFFFFFFu;
  r.id[i] = 0;
  r.flags[i] = 0;
}

template <int N>
struct Packet;
template <>
struct Packet<4> {
  using RayHit = RTCRayHit4;
  using Ray = RTCRay4;
  static void intersect(const int* v, RTCScene s, RTCIntersectContext* c, RayHit* r) {
    rtcIntersect4(v, s, c, r);
  }
  static void occluded(const int* v, RTCScene s, RTCIntersectContext* c, Ray* r) { rtcOccluded4(v, s, c, r); }
};
template <>
struct Packet<8> {
  using RayHit = RTCRayHit8;
  using Ray = RTCRay8;
  static void intersect(const int* v, RTCScene s, RTCIntersectContext* c, RayHit* r) {
    rtcIntersect8(v, s, c, r);
  }
  static void occluded(const int* v, RTCScene s, RTCIntersectContext* c, Ray* r) { rtcOccluded8(v, s, c, r); }
};
template <>
struct Packet<16> {
  using RayHit = RTCRayHit16;
  using Ray = RTCRay16;
  static void intersect(const int* v, RTCScene s, RTCIntersectContext* c, RayHit* r) {
    rtcIntersect16(v, s, c, r);
  }
  static void occluded(const int* v, RTCScene s, RTCIntersectContext* c, Ray* r) {
    rtcOccluded16(v, s, c, r);
  }
};

// Hits (or blocked rays) among n rays traced N at a time; a last partial
// packet repeats its last ray in the invalid lanes.
template <int N>
std::uint64_t tracePackets(RTCScene scene, const CompactRay* rays, std::size_t n, bool occlusion) {
  std::uint64_t hits = 0;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  alignas(64) int valid[N];
  for (std::size_t first = 0; first < n; first += N) {
    const int lanes = int(std::min<std::size_t>(N, n - first));
    for (int i = 0; i < N; ++i) valid[i] = i < lanes ? -1 : 0;
    if (occlusion) {
      alignas(64) typename Packet<N>::Ray r;
      for (int i = 0; i < N; ++i) fillLane(r, i, rays[first + std::size_t(std::min(i, lanes - 1))]);
      Packet<N>::occluded(valid, scene, &context, &r);
      for (int i = 0; i < lanes; ++i) hits += r.tfar[i] < 0;
    } else {
      alignas(64) typename Packet<N>::RayHit rh;
      for (int i = 0; i < N; ++i) {
        fillLane(rh.ray, i, rays[first + std::size_t(std::min(i, lanes - 1))]);
        rh.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
      }
      Packet<N>::intersect(valid, scene, &context, &rh);
      for (int i = 0; i < lanes; ++i) hits += rh.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID;
    }
  }
  return hits;
}

// Hits (or blocked rays) among n rays traced one way: "1" (rtcIntersect1 /
// rtcOccluded1 per ray, as the renderer does), "4", "8", "16" (packets) or
// "1M" (one stream call).
std::uint64_t traceChunk(RTCScene scene, const CompactRay* rays, std::size_t n, const std::string& mode,
                         bool occlusion, bool coherent) {
  std::uint64_t hits = 0;
  if (mode == "1") {
    for (std::size_t k = 0; k < n; ++k) {
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      if (occlusion) {
        RTCRay r;
        fill(r, rays[k]);
        rtcOccluded1(scene, &context, &r);
        hits += r.tfar < 0;
      } else {
        RTCRayHit rh{};
        fill(rh.ray, rays[k]);
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene, &context, &rh);
        hits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
      }
    }
  } else if (mode == "4") {
    hits = tracePackets<4>(scene, rays, n, occlusion);
  } else if (mode == "8") {
    hits = tracePackets<8>(scene, rays, n, occlusion);
  } else if (mode == "16") {
    hits = tracePackets<16>(scene, rays, n, occlusion);
  } else {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = coherent ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    if (occlusion) {
      std::vector<RTCRay> buffer(n);
      for (std::size_t k = 0; k < n; ++k) fill(buffer[k], rays[k]);
      rtcOccluded1M(scene, &context, buffer.data(), unsigned(n), sizeof(RTCRay));
      for (const RTCRay& r : buffer) hits += r.tfar < 0;
    } else {
      std::vector<RTCRayHit> buffer(n);
      for (std::size_t k = 0; k < n; ++k) {
        fill(buffer[k].ray, rays[k]);
        buffer[k].hit.geomID = RTC_INVALID_GEOMETRY_ID;
        buffer[k].hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
      }
      rtcIntersect1M(scene, &context, buffer.data(), unsigned(n), sizeof(RTCRayHit));
      for (const RTCRayHit& r : buffer) hits += r.hit.geomID != RTC_INVALID_GEOMETRY_ID;
    }
  }
  return hits;
}

// Best wall time of `repeat` runs tracing every ray on `threads` threads, in
// chunks of 256 rays in the recorded order (as the renderer's tiles hand them out).
json traceAll(RTCScene scene, const std::vector<CompactRay>& rays, const std::string& mode, bool occlusion,
              bool coherent, int threads, int repeat) {
  constexpr std::size_t kChunk = 256;
  const std::size_t chunks = (rays.size() + kChunk - 1) / kChunk;
  double best = std::numeric_limits<double>::infinity();
  std::uint64_t hits = 0;
  tbb::task_arena arena(threads);
  for (int r = 0; r < repeat; ++r) {
    std::atomic<std::uint64_t> total{0};
    const double s = wallSeconds([&] {
      arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunks),
                          [&](const tbb::blocked_range<std::size_t>& b) {
                            std::uint64_t h = 0;
                            for (std::size_t c = b.begin(); c != b.end(); ++c) {
                              const std::size_t first = c * kChunk, n = std::min(kChunk, rays.size() - first);
                              h += traceChunk(scene, rays.data() + first, n, mode, occlusion, coherent);
                            }
                            total.fetch_add(h, std::memory_order_relaxed);
                          });
      });
    });
    best = std::min(best, s);
    hits = total.load();
  }
  return {{"seconds", best},
          {"mrays_per_s", best > 0 ? double(rays.size()) / best / 1e6 : 0.0},
          {"hits", hits},
          {"rays", rays.size()}};
}

json runRays(const Options& o, Warnings& warnings) {
  const Setup setup(o, warnings);
  const std::string model = o.models.substr(0, o.models.find(','));
  const std::unique_ptr<Camera> camera = setup.camera(o, model, warnings);
  RenderSettings settings;
  settings.samplesPerPixel = o.recordSpp;
  settings.threads = o.threads;

  Recorder recorder;
  {
    const Integrator recording = setup.integrator(&recorder);
    renderImage(*camera, recording, settings);
  }
  RTCScene scene = setup.scene->embreeScene();
  const std::array<std::pair<RayKind, const char*>, 3> kinds{
      {{RayKind::Camera, "camera"}, {RayKind::Bounce, "bounce"}, {RayKind::Shadow, "shadow"}}};
  std::array<std::vector<CompactRay>, 3> recorded;
  for (std::size_t i = 0; i < kinds.size(); ++i) recorded[i] = recorder.rays(kinds[i].first);

  // The renderer on the very same pass (same seed: the same paths, bit for bit),
  // alternating with Embree alone on its rays one by one: on a shared machine
  // both then see the same load, so their ratio holds where two separate
  // measurements could read 24% or 50% for the same binary.
  const Integrator plain = setup.integrator();
  double rendererSeconds = std::numeric_limits<double>::infinity();
  double embreeSeconds = std::numeric_limits<double>::infinity();
  for (int r = 0; r < std::max(3, o.repeat); ++r) {
    rendererSeconds = std::min(rendererSeconds, wallSeconds([&] { renderImage(*camera, plain, settings); }));
    double seconds = 0;
    for (std::size_t i = 0; i < kinds.size(); ++i)
      seconds += traceAll(scene, recorded[i], "1", kinds[i].first == RayKind::Shadow,
                          kinds[i].first == RayKind::Camera, o.threads, 1)["seconds"]
                     .get<double>();
    embreeSeconds = std::min(embreeSeconds, seconds);
  }

  RTCDevice device = rtcGetSceneDevice(scene);
  json out;
  out["camera"] = camera->describe();
  out["record_spp"] = o.recordSpp;
  out["threads"] = o.threads;
  out["embree"] = {
      {"version", RTC_VERSION_STRING},
      {"native_ray4", rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY4_SUPPORTED) != 0},
      {"native_ray8", rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED) != 0},
      {"native_ray16", rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED) != 0},
      {"ray_stream", rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_RAY_STREAM_SUPPORTED) != 0}};
  rtcReleaseDevice(device);  // rtcGetSceneDevice retained it
  std::uint64_t total = 0;
  for (std::size_t i = 0; i < kinds.size(); ++i) {
    const auto& [kind, name] = kinds[i];
    const std::vector<CompactRay>& rays = recorded[i];
    total += rays.size();
    const bool occlusion = kind == RayKind::Shadow;
    json k;
    k["query"] = occlusion ? "occluded" : "intersect";
    for (const char* mode : {"1", "4", "8", "16", "1M"})
      k[mode] =
          traceAll(scene, rays, mode, occlusion, kind == RayKind::Camera, o.threads, std::max(2, o.repeat));
    out["kinds"][name] = k;
  }
  out["rays"] = total;
  out["renderer_seconds"] = rendererSeconds;
  out["embree_1ray_alternating_seconds"] = embreeSeconds;
  return out;
}

// --- renders per camera model -------------------------------------------------------------

// Seconds of the camera alone for every sample of the frame (one thread, a row
// of samples per generateRays call, as the renderer hands them over); the
// samples are drawn outside the timed calls.
double cameraAloneSeconds(const Camera& camera, int spp, std::uint64_t& passed) {
  const FilmGeometry& f = camera.film();
  std::vector<CameraSample> samples(std::size_t(f.width) * std::size_t(spp));
  std::vector<std::optional<CameraRay>> rays(samples.size());
  passed = 0;
  double seconds = 0;
  for (int y = 0; y < f.height; ++y) {
    for (int x = 0; x < f.width; ++x)
      for (int i = 0; i < spp; ++i) {
        const Sampler sampler(0, std::uint64_t(y) * std::uint64_t(f.width) + std::uint64_t(x),
                              std::uint32_t(i));
        CameraSample& s = samples[std::size_t(x) * std::size_t(spp) + std::size_t(i)];
        const Vec2f offset = sampler.get2D(kDimFilm);
        s.film = {float(x) + offset.x, float(y) + offset.y};
        s.lens = sampler.get2D(kDimLens);
      }
    seconds += wallSeconds([&] { camera.generateRays(samples, rays); });
    for (const auto& r : rays) passed += r.has_value();
  }
  return seconds;
}

// perf record --control: perf counts only while told to (around the renders).
class PerfControl {
 public:
  PerfControl(const std::string& control, const std::string& ack) {
    if (control.empty()) return;
    ctl_ = open(control.c_str(), O_WRONLY);
    ack_ = open(ack.c_str(), O_RDONLY);
    if (ctl_ < 0 || ack_ < 0) throw std::runtime_error("cannot open the perf control fifos");
  }
  ~PerfControl() {
    if (ctl_ >= 0) close(ctl_);
    if (ack_ >= 0) close(ack_);
  }
  PerfControl(const PerfControl&) = delete;
  PerfControl& operator=(const PerfControl&) = delete;
  void send(const char* command) {
    if (ctl_ < 0) return;
    const std::string line = std::string(command) + "\n";
    if (write(ctl_, line.data(), line.size()) != ssize_t(line.size()))
      throw std::runtime_error("perf control");
    char buffer[8];
    if (read(ack_, buffer, sizeof buffer) <= 0) throw std::runtime_error("perf ack");
  }

 private:
  int ctl_ = -1, ack_ = -1;
};

json runRender(const Options& o, Warnings& warnings) {
  const Setup setup(o, warnings);
  std::vector<std::string> models;
  std::stringstream list(o.models);
  for (std::string m; std::getline(list, m, ',');) models.push_back(m);
  std::vector<std::unique_ptr<Camera>> cameras;
  for (const std::string& m : models) cameras.push_back(setup.camera(o, m, warnings));
  const Integrator integrator = setup.integrator();
  RenderSettings settings;
  settings.samplesPerPixel = o.spp;
  settings.threads = o.threads;

  // Warm-up: TBB's threads and the BSDF's albedo table (built on first use)
  // are one-off costs of a process, not of a render.
  RenderSettings warmUp = settings;
  warmUp.samplesPerPixel = 1;
  renderImage(*cameras[0], integrator, warmUp);

  PerfControl perf(o.perfControl, o.perfAck);
  std::vector<double> best(models.size(), std::numeric_limits<double>::infinity());
  std::vector<RenderOutput> outputs(models.size());
  // Alternating models, so a burst of load on the shared machine hits all alike.
  for (int r = 0; r < o.repeat; ++r)
    for (std::size_t m = 0; m < models.size(); ++m) {
      perf.send("enable");
      const double s = wallSeconds([&] { outputs[m] = renderImage(*cameras[m], integrator, settings); });
      perf.send("disable");
      best[m] = std::min(best[m], s);
    }

  json out;
  out["spp"] = o.spp;
  out["threads"] = o.threads;
  out["width"] = setup.width;
  out["height"] = setup.height;
  out["depth"] = o.depth;
  for (std::size_t m = 0; m < models.size(); ++m) {
    std::uint64_t passed = 0;
    const double cam = cameraAloneSeconds(*cameras[m], o.spp, passed);
    const double samples = double(outputs[m].cameraSamples);
    out["models"][models[m]] = {{"describe", cameras[m]->describe()},
                                {"seconds", best[m]},
                                {"camera_samples", outputs[m].cameraSamples},
                                {"blocked", outputs[m].blockedCameraRays},
                                {"camera_alone_ns_per_ray", 1e9 * cam / samples},
                                {"camera_alone_passed", passed}};
  }
  if (o.countRays) {
    // Every ray of the first model's render, counted in a render of its own
    // (the timed ones run without an observer).
    Counter counter;
    const Integrator counting = setup.integrator(&counter);
    renderImage(*cameras[0], counting, settings);
    out["counted"] = {{"model", models[0]},
                      {"camera", counter.count(RayKind::Camera)},
                      {"bounce", counter.count(RayKind::Bounce)},
                      {"shadow", counter.count(RayKind::Shadow)}};
  }
  if (o.scaling) {
    RenderSettings one = settings;
    one.threads = 1;
    double s1 = std::numeric_limits<double>::infinity();
    for (int r = 0; r < o.repeat; ++r)
      s1 = std::min(s1, wallSeconds([&] { renderImage(*cameras[0], integrator, one); }));
    out["scaling"] = {{"model", models[0]}, {"threads_1", s1}, {"threads_n", best[0]}, {"n", o.threads}};
  }
  out["sizes"] = setup.sizes();
  out["peak_rss_bytes"] = peakRssBytes();
  return out;
}

json runStartup(const Options& o, Warnings& warnings) {
  const std::int64_t rssBefore = peakRssBytes();
  const Setup setup(o, warnings);
  const std::int64_t rssScene = peakRssBytes();
  std::unique_ptr<Camera> lens;
  const double lensSeconds = wallSeconds([&] { lens = setup.camera(o, "lens", warnings); });
  json out;
  out["load_s"] = setup.loadSeconds;
  out["bvh_build_s"] = setup.buildSeconds;
  out["lights_s"] = setup.lightsSeconds;
  out["lens_setup_s"] = lensSeconds;
  out["lens"] = lens->describe();
  out["sizes"] = setup.sizes();
  out["peak_rss_before_bytes"] = rssBefore;
  out["peak_rss_scene_bytes"] = rssScene;
  out["peak_rss_bytes"] = peakRssBytes();
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"The measuring half of tools/bench: prints JSON.", "bench_suite"};
  app.require_subcommand(1);
  Options o;
  o.spec.camera.lens = "dgauss-50mm";
  o.spec.camera.fNumber = 2.0;
  std::vector<CLI::App*> commands;
  std::vector<std::unique_ptr<OptionFlags>> flags;
  for (const char* name : {"rays", "render", "startup"}) {
    CLI::App* c = app.add_subcommand(name);
    c->add_option("scene", o.scene, "glTF scene")->required();
    c->add_option("--env", o.env, "environment, as lensrt render --env");
    c->add_option("--res", o.res, "WxH");
    c->add_option("--spp", o.spp, "samples per pixel")->check(CLI::PositiveNumber);
    c->add_option("--depth", o.depth, "maximum path depth")->check(CLI::NonNegativeNumber);
    c->add_option("--threads", o.threads, "render threads")->check(CLI::PositiveNumber);
    c->add_option("--repeat", o.repeat, "best of this many")->check(CLI::PositiveNumber);
    c->add_option("--record-spp", o.recordSpp, "rays: samples per pixel of the recorded pass")
        ->check(CLI::PositiveNumber);
    c->add_option("--models", o.models, "render: camera models, comma-separated (the first is counted)");
    c->add_flag("--count-rays", o.countRays, "render: count every ray of the first model's render");
    c->add_flag("--scaling", o.scaling, "render: the first model on one thread too");
    c->add_option("--perf-control", o.perfControl, "render: perf's control fifo (enabled around renders)");
    c->add_option("--perf-ack", o.perfAck, "render: perf's ack fifo");
    flags.push_back(std::make_unique<OptionFlags>(*c, o.spec, kRenderCommand,
                                                  std::vector<std::string>{"camera", "shutter", "flare"}));
    commands.push_back(c);
  }
  CLI11_PARSE(app, argc, argv);
  try {
    std::vector<std::string> messages;
    Warnings warnings([&](const std::string& m) { messages.push_back(m); });
    json out;
    if (commands[0]->parsed()) out = runRays(o, warnings);
    if (commands[1]->parsed()) out = runRender(o, warnings);
    if (commands[2]->parsed()) out = runStartup(o, warnings);
    out["warnings"] = messages;
    fmt::print("{}\n", out.dump());
  } catch (const std::exception& e) {
    fmt::print(stderr, "bench_suite: error: {}\n", e.what());
    return 1;
  }
  return 0;
}
