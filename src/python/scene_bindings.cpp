// lensrt.Scene and lensrt.RenderResult: a glTF scene loaded once, rendered
// through any of the four camera models into numpy arrays that view the
// render's own pixels (no copy), with the command line's bits.
#include <fmt/core.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "api/keyframes.h"
#include "api/output_file.h"
#include "api/render_options.h"
#include "api/render_request.h"
#include "api/scene.h"
#include "api/scene_sequence.h"
#include "core/error.h"
#include "core/transform.h"
#include "python/arguments.h"
#include "python/bindings.h"
#include "python/render_result.h"
#include "python/warning_list.h"

namespace lensrt::python {
namespace {

// How far a pose's 3x3 part may be from a rotation (float32 poses pass).
constexpr double kRigidTolerance = 1e-4;

Transform toPose(py::handle value) {
  const auto m = toFiniteMatrix(value, "camera_to_world", 4, 4);
  const auto at = [&](int r, int c) { return m.at(r, c); };
  Transform::Matrix matrix{};
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) matrix[r][c] = at(r, c);
  bool rigid = at(3, 0) == 0 && at(3, 1) == 0 && at(3, 2) == 0 && at(3, 3) == 1;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double dot = 0;
      for (int k = 0; k < 3; ++k) dot += at(k, i) * at(k, j);
      rigid = rigid && std::abs(dot - (i == j ? 1.0 : 0.0)) < kRigidTolerance;
    }
  const double det = at(0, 0) * (at(1, 1) * at(2, 2) - at(1, 2) * at(2, 1)) -
                     at(0, 1) * (at(1, 0) * at(2, 2) - at(1, 2) * at(2, 0)) +
                     at(0, 2) * (at(1, 0) * at(2, 1) - at(1, 1) * at(2, 0));
  if (!rigid || det < 0)
    throw py::value_error(
        "camera_to_world: expected a rigid 4 x 4 pose (an orthonormal, right-handed 3 x 3 rotation, a "
        "translation in metres, last row 0 0 0 1); the camera looks down its -Z axis with +Y up (glTF's "
        "convention; for an OpenCV pose negate its Y and Z columns)");
  return Transform(matrix);
}

std::optional<Resolution> toResolution(py::handle value) {
  if (value.is_none()) return std::nullopt;
  if (py::isinstance<py::str>(value)) return parseResolution(value.cast<std::string>());
  if (py::isinstance<py::int_>(value) && !py::isinstance<py::bool_>(value))
    return Resolution{int(toInteger(value, "res", 1, 1 << 16)), 0};
  if (py::isinstance<py::sequence>(value) && py::len(value) == 2) {
    const py::sequence s = py::reinterpret_borrow<py::sequence>(value);
    return Resolution{int(toInteger(s[0], "res", 1, 1 << 16)), int(toInteger(s[1], "res", 1, 1 << 16))};
  }
  badArgument("res", "(width, height) in pixels, a width, or 'WxH'", value);
}

std::string toEnvironment(py::handle value) {
  if (value.is_none()) return "";
  if (py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value))
    return fmt::format("constant:{:.9g}", toDouble(value, "env"));
  return toPathText(value, "env");
}

std::string toFocusPixel(py::handle value) {
  if (value.is_none()) return "";
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::sequence>(value) && py::len(value) == 2) {
    const py::sequence s = py::reinterpret_borrow<py::sequence>(value);
    return fmt::format("{:.17g},{:.17g}", toDouble(s[0], "focus_pixel"), toDouble(s[1], "focus_pixel"));
  }
  badArgument("focus_pixel", "(x, y) in pixels", value);
}

std::string toShutter(py::handle value) {
  if (value.is_none()) return "";
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  return fmt::format("{:.17g}", toDouble(value, "shutter"));
}

std::optional<PixelRegion> toCrop(py::handle value) {
  if (value.is_none()) return std::nullopt;
  if (!py::isinstance<py::sequence>(value) || py::isinstance<py::str>(value) || py::len(value) != 4)
    badArgument("crop", "(x0, x1, y0, y1) in pixels, x1 and y1 exclusive", value);
  const py::sequence s = py::reinterpret_borrow<py::sequence>(value);
  const PixelRegion r{int(toInteger(s[0], "crop", 0, 1 << 16)), int(toInteger(s[1], "crop", 1, 1 << 16)),
                      int(toInteger(s[2], "crop", 0, 1 << 16)), int(toInteger(s[3], "crop", 1, 1 << 16))};
  if (r.x1 <= r.x0 || r.y1 <= r.y0) badArgument("crop", "x0 < x1 and y0 < y1", value);
  return r;
}

// An H x W (x channels) float32 view of channels [first, first + count) of the
// interleaved image, kept alive by `owner`.
py::array channelView(py::object owner, int first, int count) {
  const Image& image = owner.cast<const PyRenderResult&>().result.image;
  const auto item = py::ssize_t(sizeof(float));
  const auto stride = py::ssize_t(image.channelCount()) * item;
  float* data = const_cast<float*>(image.pixels.data()) + first;
  std::vector<py::ssize_t> shape{image.height, image.width}, strides{stride * image.width, stride};
  if (count > 1) {
    shape.push_back(count);
    strides.push_back(item);
  }
  return py::array(py::dtype::of<float>(), shape, strides, data, owner);
}

// The parsed file behind Scene.at(): shared by a scene and every scene posed
// from it, so the file is read once however many moments are posed.
struct PosedFrom {
  explicit PosedFrom(const SceneLoadOptions& options)
      : warnings(options.file), sequence(options, warnings.sink()) {}
  std::mutex mutex;  // one pose at a time: the GIL is released while posing
  WarningList warnings;
  std::size_t emitted = 0;  // warnings already issued
  SceneSequence sequence;
};

class PyScene {
 public:
  PyScene(py::handle file, py::handle sceneIndex, py::handle allowExternalFiles, py::handle maxTextureMiB,
          py::handle time, py::handle animation) {
    SceneLoadOptions options;
    options.file = toPathText(file, "file");
    if (!sceneIndex.is_none()) options.sceneIndex = int(toInteger(sceneIndex, "scene_index", 0, 1 << 20));
    SceneAccessArgs access;
    access.allowExternalFiles = toBool(allowExternalFiles, "allow_external_files");
    if (!maxTextureMiB.is_none())
      access.maxTextureMiB = std::uint64_t(toInteger(maxTextureMiB, "max_texture_memory", 1, 1LL << 40));
    options.limits = sceneReadLimits(access);
    options.time.seconds = toDouble(time, "time");
    if (!animation.is_none()) options.time.animation = py::str(animation);
    // Posed over the default shutter, as lensrt render does; render() poses
    // it again for another shutter or a rolling shutter.
    options.time.spanSeconds = recordedSpanSeconds(CameraOptions{});
    WarningList warnings(options.file);
    {
      const py::gil_scoped_release release;
      scene_ = std::make_shared<const Scene>(options, warnings.sink());
    }
    warnings.emit();
  }

  const std::string& file() const { return scene_->options().file; }

  // The same file posed at another moment: parsed once for this scene and
  // every scene posed from it (their materials and textures are copied).
  PyScene at(py::handle time) {
    const double seconds = toDouble(time, "time");
    if (!posedFrom_) posedFrom_ = std::make_shared<PosedFrom>(scene_->options());
    const std::shared_ptr<PosedFrom> from = posedFrom_;
    std::shared_ptr<const Scene> posed;
    std::vector<std::string> fresh;
    {
      const py::gil_scoped_release release;
      const std::lock_guard lock(from->mutex);
      // This pose's warnings, issued once the GIL is held again (with an
      // error, the error alone).
      const auto takeFresh = [&] {
        const std::vector<std::string>& all = from->warnings.messages();
        fresh.assign(all.begin() + std::ptrdiff_t(from->emitted), all.end());
        from->emitted = all.size();
      };
      try {
        posed = from->sequence.at(seconds);
      } catch (...) {
        takeFresh();
        throw;
      }
      takeFresh();
    }
    WarningList::emit(file(), fresh);
    return PyScene(std::move(posed), from);
  }

  std::unique_ptr<PyRenderResult> render(const py::kwargs& given) const {
    // Every keyword, with the command line's defaults (`lensrt render --help`).
    static const std::vector<std::string> known = {"camera",
                                                   "lens",
                                                   "fstop",
                                                   "focus",
                                                   "focus_pixel",
                                                   "sensor",
                                                   "res",
                                                   "spp",
                                                   "min_spp",
                                                   "noise_threshold",
                                                   "seed",
                                                   "aov",
                                                   "env",
                                                   "env_rotate",
                                                   "env_intensity",
                                                   "max_depth",
                                                   "camera_node",
                                                   "camera_to_world",
                                                   "threads",
                                                   "crop",
                                                   "blades",
                                                   "blade_rotation",
                                                   "aperture_mask",
                                                   "focal_length",
                                                   "exposure",
                                                   "shutter",
                                                   "shutter_curve",
                                                   "rolling_shutter",
                                                   "readout",
                                                   "iso",
                                                   "dispersion",
                                                   "coatings",
                                                   "flare",
                                                   "flare_bounces",
                                                   "barrel_reflectance",
                                                   "film",
                                                   "spectral",
                                                   "sensor_response",
                                                   "white_balance",
                                                   "output_space",
                                                   "noise",
                                                   "sensor_params",
                                                   "raw",
                                                   "cfa",
                                                   "progress",
                                                   "light_sampler"};
    for (const auto& [key, value] : given) {
      const std::string name = py::str(key);
      if (std::find(known.begin(), known.end(), name) == known.end())
        throw py::value_error("unknown option '" + name + "' (see help(lensrt.Scene.render))");
    }
    // Every keyword read is noted: one accepted but never read is a bug
    // (raw= once was), caught below before any work.
    std::vector<std::string> read;
    const auto get = [&](const char* name) -> py::object {
      read.emplace_back(name);
      return given.contains(name) ? py::reinterpret_borrow<py::object>(given[name]) : py::none();
    };
    RenderRequest request;
    CameraOptions& c = request.camera;
    c.lensDir = LENSRT_LENS_DIR;
    if (const py::object v = get("camera"); !v.is_none()) c.model = toText(v, "camera");
    if (const py::object v = get("lens"); !v.is_none()) c.lens = toPathText(v, "lens");
    // A number, or keyframes "SECONDS:N,..." read at the scene's time.
    if (const py::object v = get("fstop"); py::isinstance<py::str>(v) && isKeyframes(toText(v, "fstop")))
      c.fNumberKeyframes = toText(v, "fstop");
    else
      c.fNumber = toOptionalDouble(v, "fstop");
    // "auto", "inf", or metres as text or a number.
    if (const py::object v = get("focus"); !v.is_none()) c.focus = toDistanceText(v, "focus");
    c.focusPixel = toFocusPixel(get("focus_pixel"));
    if (const py::object v = get("sensor"); !v.is_none()) c.sensor = toSensorText(v, "sensor");
    if (const py::object v = get("blades"); !v.is_none()) c.blades = int(toInteger(v, "blades", 0, 64));
    if (const py::object v = get("blade_rotation"); !v.is_none())
      c.bladeRotationDegrees = toDouble(v, "blade_rotation");
    if (const py::object v = get("aperture_mask"); !v.is_none())
      c.apertureMask = toPathText(v, "aperture_mask");
    c.focalLengthMm = toOptionalDouble(get("focal_length"), "focal_length");
    if (const py::object v = get("exposure"); !v.is_none()) c.exposure = toText(v, "exposure");
    c.shutter = toShutter(get("shutter"));
    if (const py::object v = get("shutter_curve"); !v.is_none()) c.shutterCurve = toText(v, "shutter_curve");
    c.rollingShutter = toShutter(get("rolling_shutter"));
    if (const py::object v = get("readout"); !v.is_none()) c.readout = toText(v, "readout");
    c.iso = toOptionalDouble(get("iso"), "iso");
    if (const py::object v = get("dispersion"); !v.is_none())
      c.dispersion = py::isinstance<py::bool_>(v) ? (v.cast<bool>() ? "on" : "off") : toText(v, "dispersion");
    if (const py::object v = get("coatings"); !v.is_none()) c.coatings = toText(v, "coatings");
    if (const py::object v = get("flare"); !v.is_none())
      c.flare = py::isinstance<py::bool_>(v) ? (v.cast<bool>() ? "on" : "off") : toText(v, "flare");
    if (const py::object v = get("flare_bounces"); !v.is_none())
      c.flareBounces = int(toInteger(v, "flare_bounces", 0, 4));
    if (const py::object v = get("barrel_reflectance"); !v.is_none())
      c.barrelReflectance = toDouble(v, "barrel_reflectance");
    if (const py::object v = get("film"); !v.is_none()) c.film = toText(v, "film");
    if (const py::object v = get("spectral"); !v.is_none())
      c.spectral = py::isinstance<py::bool_>(v) ? (v.cast<bool>() ? "on" : "off") : toText(v, "spectral");
    if (const py::object v = get("sensor_response"); !v.is_none())
      c.sensorResponse = toPathText(v, "sensor_response");
    if (const py::object v = get("white_balance"); !v.is_none())
      c.whiteBalance = py::isinstance<py::int_>(v) || py::isinstance<py::float_>(v)
                           ? fmt::format("{:g}", toDouble(v, "white_balance"))
                           : toText(v, "white_balance");
    if (const py::object v = get("output_space"); !v.is_none()) c.outputSpace = toText(v, "output_space");
    if (const py::object v = get("noise"); !v.is_none())
      c.noise = py::isinstance<py::bool_>(v) ? (v.cast<bool>() ? "on" : "off") : toText(v, "noise");
    if (const py::object v = get("sensor_params"); !v.is_none())
      c.sensorParams = toPathText(v, "sensor_params");
    if (const py::object v = get("raw"); !v.is_none()) request.raw.file = toPathText(v, "raw");
    if (const py::object v = get("cfa"); !v.is_none()) request.raw.cfa = toText(v, "cfa");

    FrameOptions& f = request.frame;
    if (const py::object v = get("camera_node"); !v.is_none())
      f.cameraNode = py::isinstance<py::int_>(v) ? std::to_string(toInteger(v, "camera_node", 0, 1 << 30))
                                                 : toText(v, "camera_node");
    if (const py::object v = get("camera_to_world"); !v.is_none()) f.worldFromCamera = toPose(v);
    f.resolution = toResolution(get("res"));
    EnvironmentArgs env;
    env.environment = toEnvironment(get("env"));
    if (const py::object v = get("env_rotate"); !v.is_none()) env.rotationDegrees = toDouble(v, "env_rotate");
    if (const py::object v = get("env_intensity"); !v.is_none()) env.intensity = toDouble(v, "env_intensity");
    if (std::abs(env.rotationDegrees) > 360) throw UsageError("--env-rotate", "expected -360 to 360 degrees");
    if (env.intensity < 0) throw UsageError("--env-intensity", "expected a radiance scale >= 0");
    f.environment = environmentSpec(env);
    if (const py::object v = get("max_depth"); !v.is_none())
      f.maxDepth = int(toInteger(v, "max_depth", 0, 1024));
    if (const py::object v = get("light_sampler"); !v.is_none()) {
      const std::string name = toText(v, "light_sampler");
      const std::optional<LightSampling> sampling = parseLightSampling(name);
      if (!sampling) throw UsageError("--light-sampler", "expected tree or power, got '" + name + "'");
      f.lightSampling = *sampling;
    }

    RenderSettings& s = request.settings;
    if (const py::object v = get("spp"); !v.is_none())
      s.samplesPerPixel = int(toInteger(v, "spp", 1, 1 << 24));
    double noiseThreshold = 0;
    if (const py::object v = get("noise_threshold"); !v.is_none()) {
      noiseThreshold = toDouble(v, "noise_threshold");
      if (!(noiseThreshold > 0))
        throw UsageError("--noise-threshold",
                         fmt::format("expected a number > 0 (the relative standard error at which a pixel "
                                     "stops), got {}",
                                     noiseThreshold));
    }
    std::optional<int> minSpp;
    if (const py::object v = get("min_spp"); !v.is_none()) minSpp = int(toInteger(v, "min_spp", 1, 1 << 24));
    s.adaptive = adaptiveSampling(noiseThreshold, minSpp, s.samplesPerPixel);
    if (const py::object v = get("seed"); !v.is_none())
      s.seed = std::uint64_t(toInteger(v, "seed", 0, std::numeric_limits<long long>::max()));
    if (const py::object v = get("threads"); !v.is_none()) s.threads = int(toInteger(v, "threads", 0, 4096));
    s.aovs = parseAovs(toTextList(get("aov"), "aov"));
    s.aovs.spp = s.adaptive.has_value();
    s.region = toCrop(get("crop"));
    const py::object callback = get("progress");
    for (const std::string& name : known)
      if (std::find(read.begin(), read.end(), name) == read.end())
        throw std::logic_error("lensrt.Scene.render: keyword '" + name + "' is accepted but never read");
    if (!callback.is_none() && !PyCallable_Check(callback.ptr()))
      badArgument("progress", "a callable progress(done_spp, total_spp) or None", callback);
    // The EXR's lensrt:command_line: the call, as Python would print it.
    std::string call;
    for (const auto& [key, value] : given)
      if (std::string(py::str(key)) != "progress")
        call += (call.empty() ? "" : ", ") + std::string(py::str(key)) + "=" + std::string(py::repr(value));
    request.commandLine.append("lensrt.Scene(").append(py::repr(py::str(file()))).append(").render(");
    request.commandLine.append(call).append(")");

    // The render runs without the GIL; between passes the progress callback
    // and Python's signal handlers (Ctrl-C: KeyboardInterrupt) run with it.
    std::optional<py::error_already_set> pending;
    const RenderProgress progress = [&](int done, int total) {
      const py::gil_scoped_acquire gil;
      if (pending) return false;
      if (PyErr_CheckSignals() != 0) {
        pending.emplace();
        return false;
      }
      if (callback.is_none()) return true;
      try {
        const py::object answer = callback(done, total);
        return !(py::isinstance<py::bool_>(answer) && !answer.cast<bool>());
      } catch (py::error_already_set& e) {
        pending.emplace(std::move(e));
        return false;
      }
    };
    WarningList warnings(file());
    auto out = std::make_unique<PyRenderResult>();
    {
      const py::gil_scoped_release release;
      out->result = lensrt::render(scene_, request, warnings.sink(), progress);
    }
    if (pending) throw *pending;
    if (out->result.droppedSamples > 0)
      warnings.sink().warn(
          fmt::format("{} samples with NaN or infinite radiance were dropped", out->result.droppedSamples));
    warnings.emit();
    return out;
  }

 private:
  PyScene(std::shared_ptr<const Scene> scene, std::shared_ptr<PosedFrom> from)
      : scene_(std::move(scene)), posedFrom_(std::move(from)) {}

  std::shared_ptr<const Scene> scene_;
  std::shared_ptr<PosedFrom> posedFrom_;  // made by the first at()
};

}  // namespace

void bindScene(py::module_& m) {
  using py::arg;
  py::class_<PyRenderResult>(m, "RenderResult",
                             "A render: its pixels as float32 numpy views, and its metadata.")
      .def_property_readonly(
          "rgb", [](py::object self) { return channelView(self, 0, 3); },
          "Linear RGB radiance (or irradiance), an H x W x 3 float32 array viewing the render (no copy).")
      .def_property_readonly(
          "channels",
          [](py::object self) {
            const Image& image = self.cast<const PyRenderResult&>().result.image;
            py::dict d;
            for (std::size_t c = 0; c < image.channels.size(); ++c)
              d[py::str(image.channels[c])] = channelView(self, int(c), 1);
            return d;
          },
          "Every channel by its EXR name (R, G, B, A, depth.Z in metres, normal.X/Y/Z, albedo.R/G/B,\n"
          "variance.R/G/B), each an H x W float32 array viewing the render (no copy).")
      .def_property_readonly(
          "metadata",
          [](const PyRenderResult& r) {
            py::dict d;
            for (const auto& [k, v] : r.result.metadata) d[py::str(k)] = v;
            return d;
          },
          "The EXR header's lensrt:* attributes (camera, settings, seed, timing, ...), as str.")
      .def_property_readonly(
          "seconds", [](const PyRenderResult& r) { return r.result.seconds; }, "Render time in seconds.")
      .def_property_readonly(
          "spp", [](const PyRenderResult& r) { return r.result.samplesPerPixel; },
          "Samples per pixel done (fewer than asked when the progress callback stopped it).")
      .def_property_readonly(
          "finished", [](const PyRenderResult& r) { return r.result.finished; },
          "False when the progress callback stopped the render early.")
      .def_property_readonly(
          "camera", [](const PyRenderResult& r) { return r.result.camera; }, "The camera, described.")
      .def(
          "write",
          [](const PyRenderResult& r, py::handle path) {
            const std::string file = toPathText(path, "path");
            checkOutputFile(file);
            writeOutputImage(file, r.result.image, r.result.metadata);
          },
          arg("path"),
          "Writes the image as `lensrt render -o` would: .exr (every channel, float, with the metadata),\n"
          ".png/.jpg (an sRGB preview), .tif/.jp2/.webp/.dpx (through lensrt's OpenImageIO plugin, found\n"
          "in the package folder). Missing folders are created.")
      .def("__repr__", [](const PyRenderResult& r) {
        return fmt::format("<lensrt.RenderResult {}x{}, {} spp, {}>", r.result.image.width,
                           r.result.image.height, r.result.samplesPerPixel, r.result.camera);
      });

  py::class_<PyScene>(m, "Scene", R"doc(A glTF 2.0 scene (.gltf/.glb), loaded once and rendered many times.

file: the scene. scene_index: which glTF scene (None: the file's default).
allow_external_files: let the scene read files outside its folder (only for
scenes you trust). max_texture_memory: MiB its textures may take (None: half
this machine's memory). Raises FileNotFoundError for a missing file and
ValueError for a broken one. The GIL is released while it loads.)doc")
      .def(py::init<py::handle, py::handle, py::handle, py::handle, py::handle, py::handle>(), arg("file"),
           arg("scene_index") = py::none(), arg("allow_external_files") = false,
           arg("max_texture_memory") = py::none(), arg("time") = 0.0, arg("animation") = py::none(),
           R"doc(Loads a glTF scene and builds its BVH once. time: the moment (seconds) its animations
pose the nodes, cameras and lights at (lensrt render --time); animation: a name or
index to play one of them (None: all).)doc")
      .def_property_readonly("file", &PyScene::file, "The scene file (str).")
      .def("at", &PyScene::at, arg("time"),
           R"doc(The same scene posed at another moment (seconds): the file is read once for this
scene and every scene posed from it, each pose keeps the animation chosen and
builds its own BVH (as lensrt render --frames does). For a sequence:
[scene.at(f / 24).render(...) for f in range(240)].)doc")
      .def("__repr__", [](const PyScene& s) { return "lensrt.Scene('" + s.file() + "')"; })
      .def("render", &PyScene::render,
           R"doc(render(camera="pinhole", lens=None, fstop=None, focus="auto", focus_pixel=None,
       sensor="full-frame", res=None, spp=16, noise_threshold=None, min_spp=None, seed=0,
       aov=(), env=None, env_rotate=0,
       env_intensity=1, max_depth=8, light_sampler="tree", camera_node=None, camera_to_world=None, threads=0,
       crop=None, blades=0, blade_rotation=0, aperture_mask=None, focal_length=None,
       exposure="normalized", shutter=None, shutter_curve="box", rolling_shutter=None,
       readout="top-down", iso=None, dispersion="on", coatings=None,
       flare="off", flare_bounces=2, barrel_reflectance=0, film=None, spectral="on", sensor_response=None,
       white_balance=None,
       output_space="srgb", noise="off", sensor_params=None, raw=None, cfa="RGGB",
       progress=None) -> RenderResult

Renders the scene as `lensrt render` does, with the same bits for the same
settings and seed. Keywords only, each the flag of the same name:
  camera: "pinhole", "thin", "thick" or "lens" (the full lens).
  lens: a library name (e.g. "dgauss-50mm") or a lens file; the simpler models
    then take its focal length, f-number and pupils.
  fstop: f-number (None: the lens wide open, or f/2.8 without a lens), or
    keyframes "SECONDS:N,..." read at the scene's time.
  focus: distance in metres, "inf", or "auto" (what focus_pixel sees; default).
  focus_pixel: (x, y) raster pixel for focus="auto" (None: the centre).
  sensor: "full-frame", "aps-c", "mft", "1in", "WxH" in mm, or a (w, h) pair in mm.
  res: (width, height) in pixels, or a width (height from the camera's aspect);
    None: 640 wide.
  spp: samples per pixel (>= 1); with noise_threshold, the most a pixel takes.
  noise_threshold: adaptive sampling, a pixel stops once the relative standard
    error of its mean is below this (e.g. 0.01); the image gains an "spp"
    channel. min_spp: the samples every pixel takes first (default 16).
  seed: random seed (>= 0).
  aov: extra channels, a sequence or comma-separated string of "depth"
    (metres), "normal", "albedo", "variance" (of the pixel mean).
  env: None (the scene's light, else a default sky), "none", "constant:V",
    "constant:R,G,B", a number V (constant radiance in W/(sr m^2)), or a lat-long
    .exr/.hdr map. env_rotate: degrees about +Y. env_intensity: a scale.
  max_depth: scattering events per path. threads: 0 for all cores.
  light_sampler: "tree" (a light tree: by what each light can give the shading
    point) or "power" (by power alone), how next-event estimation picks a light.
  camera_node: glTF node name or index of the camera (None: the first one).
  camera_to_world: a 4 x 4 rigid pose (metres) replacing that camera's; the
    camera looks down its -Z axis with +Y up (glTF).
  crop: (x0, x1, y0, y1) pixels to render, x1 and y1 exclusive.
  blades, blade_rotation (deg), aperture_mask (a grey-scale image file),
  focal_length (mm), exposure ("normalized" or "physical"), shutter (seconds:
  the exposure, and the motion blur of an animated scene; 0 an instant),
  shutter_curve ("box" or "trapezoid:F"), rolling_shutter (the readout in
  seconds, None: a global shutter), readout ("top-down", "bottom-up",
  "left-right", "right-left"),
  iso, dispersion ("on"/"off" or bool), coatings ("none", "single", "multi"),
  flare ("on"/"off" or bool: stray light in the full lens), flare_bounces (0, 2, 4),
  barrel_reflectance (the barrel's diffuse reflectance, 0 <= K < 1, with flare),
  film ("radiance" or "irradiance"): as the flags of `lensrt render --help`.
  spectral: "on"/True (default) carries light at four wavelengths per sample
    (colours upsampled to spectra, the CIE 1931 observer, sRGB); "off"/False
    carries RGB. sensor_response: "cie1931" (default), a camera name or a .csv
    file. white_balance: "none", "auto" or a colour temperature in K (a number).
    output_space: "srgb", "rec2020", "acescg", "xyz" or "camera".
  noise: "on"/True reads the exposure out through a sensor (shot, dark and read
    noise, PRNU/DSNU, full well, ISO gain, ADC); channels noiseless.R/G/B keep
    the render. sensor_params: a preset ("default", "full-frame", "smartphone",
    "machine-vision") or a sensor .json file (see the README).
  raw: also write the raw file, a .dng of the colour filter mosaic (cfa: "RGGB",
    "BGGR", "GRBG" or "GBRG"), as `lensrt render --raw` does.
  progress: callable(done_spp, total_spp) called between passes (which double
    from 1 spp up to about a second each); returning False stops the render
    there (RenderResult.finished is then False).
The GIL is released while rendering; Ctrl-C raises KeyboardInterrupt at the
end of the pass in flight. Bad options raise ValueError with the command
line's message; missing files FileNotFoundError.)doc");
}

}  // namespace lensrt::python
