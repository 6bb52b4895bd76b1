// Camera cost: the full lens against the pinhole at the same samples per
// pixel on one scene (default scenes/dof_row.gltf). Renders each model
// `--repeat` times, alternating so machine load hits both alike, and prints
// the best time of each and their ratio (target: full lens <= 1.05x pinhole).
// With a lens that has dispersion data (and --dispersion on, the default) it
// also renders the full lens with --dispersion off: the cost of dispersion
// (target <= 1.10x).
//
//   bench_cameras [SCENE] [--spp 16] [--res 320x180] [--repeat 3] [--threads 0]
//                 [--save PREFIX] [camera flags of lensrt render, e.g. --lens dgauss-50mm --fstop 4]
#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <ctime>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "api/camera_factory.h"
#include "api/render_spec.h"
#include "app/option_flags.h"
#include "core/error.h"
#include "image/image_io.h"
#include "render/environment.h"
#include "render/integrator.h"
#include "render/lights.h"
#include "render/material_eval.h"
#include "render/renderer.h"
#include "scene/camera_selection.h"
#include "scene/gltf_loader.h"
#include "scene/render_scene.h"

namespace {

// Process CPU time (all threads): steadier than wall time on a shared machine.
double cpuSeconds(const std::function<void()>& f) {
  const std::clock_t t0 = std::clock();
  f();
  return double(std::clock() - t0) / CLOCKS_PER_SEC;
}

// CPU time of the camera alone: one ray per sample over the whole film, made
// one at a time (generateRay) or a row at a time (generateRays, as the renderer does).
double cameraSeconds(const lensrt::Camera& camera, int spp, bool batched, long& passed) {
  const lensrt::FilmGeometry& f = camera.film();
  passed = 0;
  std::vector<lensrt::CameraSample> samples(std::size_t(f.width) * spp);
  std::vector<std::optional<lensrt::CameraRay>> rays(samples.size());
  return cpuSeconds([&] {
    for (int y = 0; y < f.height; ++y) {
      for (int x = 0; x < f.width; ++x)
        for (int i = 0; i < spp; ++i) {
          const float u = float((i * 0.618034) - std::floor(i * 0.618034));
          const float v = (i + 0.5f) / float(spp);
          lensrt::CameraSample& s = samples[std::size_t(x) * spp + i];
          s.film = {x + u, y + v};
          s.lens = {v, u};
        }
      if (batched) {
        camera.generateRays(samples, rays);
      } else {
        for (std::size_t k = 0; k < samples.size(); ++k) rays[k] = camera.generateRay(samples[k]);
      }
      for (const auto& r : rays) passed += r.has_value();
    }
  });
}

}  // namespace

int main(int argc, char** argv) {
  using namespace lensrt;
  CLI::App app{"Time the full-lens camera against the pinhole on one scene.", "bench_cameras"};
  std::string scenePath = std::string(LENSRT_SOURCE_DIR) + "/scenes/dof_row.gltf";
  int spp = 16, width = 320, height = 180, repeat = 3, threads = 0;
  RenderSpec spec;
  spec.camera.lens = "dgauss-50mm";
  spec.camera.fNumber = 4.0;
  app.add_option("scene", scenePath, "glTF scene");
  app.add_option("--spp", spp, "samples per pixel")->check(CLI::PositiveNumber);
  app.add_option("--width", width, "image width")->check(CLI::PositiveNumber);
  app.add_option("--height", height, "image height")->check(CLI::PositiveNumber);
  app.add_option("--repeat", repeat, "renders per model (the best time counts)")->check(CLI::PositiveNumber);
  app.add_option("--threads", threads, "render threads (0: all)");
  std::string save;
  app.add_option("--save", save, "also write PREFIX_pinhole.png and PREFIX_lens.png (previews)");
  const OptionFlags flags(app, spec, kRenderCommand, {"camera", "shutter", "flare"});
  CLI11_PARSE(app, argc, argv);

  try {
    Warnings warnings([](const std::string& m) { fmt::print(stderr, "bench_cameras: warning: {}\n", m); });
    SceneDesc desc = loadGltf(scenePath, -1, warnings);
    const CameraDesc gltfCamera = selectCamera(desc, "", float(width) / float(height));
    const RenderScene scene(std::move(desc));
    const MaterialTable materials(scene.desc());
    const Environment environment;
    const LightSet lights(materials, environment, scene.bounds());
    const Integrator integrator(scene, materials, lights, environment, IntegratorSettings{});
    const HitDistance hit = [&](const Ray& r) -> std::optional<double> {
      const auto h = scene.intersect(r);
      return h ? std::optional<double>(h->t) : std::nullopt;
    };
    FilmGeometry film;
    film.width = width;
    film.height = height;
    CameraSpec pinholeOptions = spec.camera, lensOptions = spec.camera;
    pinholeOptions.model = CameraModel::Pinhole;
    lensOptions.model = CameraModel::Lens;
    CameraSpec flatOptions = lensOptions;  // the full lens at the d line only
    flatOptions.dispersion = false;
    const auto request = [&](const CameraSpec& c) { return CameraRequest{c, spec.shutter, spec.flare}; };
    std::unique_ptr<Camera> pinhole, lens, flat;
    const double buildSeconds =
        cpuSeconds([&] { lens = makeCamera(request(lensOptions), gltfCamera, film, hit, warnings); });
    pinhole = makeCamera(request(pinholeOptions), gltfCamera, film, hit, warnings);
    if (lens->tracesWavelengths()) flat = makeCamera(request(flatOptions), gltfCamera, film, hit, warnings);
    RenderSettings settings;
    settings.samplesPerPixel = spp;
    settings.threads = threads;
    double bestPinhole = std::numeric_limits<double>::infinity(), bestLens = bestPinhole,
           bestFlat = bestPinhole;
    for (int i = 0; i < repeat; ++i) {
      bestPinhole = std::min(bestPinhole, cpuSeconds([&] { renderImage(*pinhole, integrator, settings); }));
      bestLens = std::min(bestLens, cpuSeconds([&] { renderImage(*lens, integrator, settings); }));
      if (flat) bestFlat = std::min(bestFlat, cpuSeconds([&] { renderImage(*flat, integrator, settings); }));
    }
    if (!save.empty()) {
      writeImage(save + "_pinhole.png", renderImage(*pinhole, integrator, settings).image,
                 cameraMetadata(*pinhole, cameraExposure(pinholeOptions, spec.shutter)));
      writeImage(save + "_lens.png", renderImage(*lens, integrator, settings).image,
                 cameraMetadata(*lens, cameraExposure(lensOptions, spec.shutter)));
    }
    long pinholePassed = 0, lensPassed = 0, lensPassedOne = 0;
    const double camPinhole = cameraSeconds(*pinhole, spp, true, pinholePassed);
    const double camLens = cameraSeconds(*lens, spp, true, lensPassed);
    const double camLensOne = cameraSeconds(*lens, spp, false, lensPassedOne);
    const double samples = double(width) * height * spp;
    fmt::print("scene {} at {}x{}, {} spp, best of {}, CPU seconds\n", scenePath, width, height, spp, repeat);
    fmt::print("pinhole   render {:8.3f} s, camera alone {:6.3f} s ({:.0f} ns/ray)  {}\n", bestPinhole,
               camPinhole, 1e9 * camPinhole / samples, pinhole->describe());
    fmt::print("full lens render {:8.3f} s, camera alone {:6.3f} s ({:.0f} ns/ray, {:.1f}% pass)  {}\n",
               bestLens, camLens, 1e9 * camLens / samples, 100.0 * lensPassed / samples, lens->describe());
    fmt::print("full lens camera one ray at a time: {:.0f} ns/ray ({:.2f}x the batched rays)\n",
               1e9 * camLensOne / samples, camLensOne / camLens);
    fmt::print("full lens set-up (focus, exit pupil bounds): {:.3f} s\n", buildSeconds);
    fmt::print("ratio full lens / pinhole: {:.3f}\n", bestLens / bestPinhole);
    if (flat)
      fmt::print("full lens --dispersion off render {:8.3f} s; ratio dispersion on / off: {:.3f}\n", bestFlat,
                 bestLens / bestFlat);
  } catch (const CLI::ParseError& e) {
    fmt::print(stderr, "bench_cameras: error: {}\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    fmt::print(stderr, "bench_cameras: error: {}\n", e.what());
    return 1;
  }
  return 0;
}
