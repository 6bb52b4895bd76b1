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
#include <cstdlib>
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
#include "image/image_io.h"
#include "python/arguments.h"
#include "python/bindings.h"
#include "python/keywords.h"
#include "python/render_result.h"
#include "python/warning_list.h"

namespace lensrt::python {
namespace {

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
    options.time.spanSeconds = ShutterSpec{}.spanSeconds();
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
    RenderRequest request;
    RenderSpec& spec = request.spec;
    // The scene's own settings (the identity's), as it was loaded.
    const SceneLoadOptions& loaded = scene_->options();
    spec.scene.file = loaded.file;
    spec.scene.sceneIndex = loaded.sceneIndex;
    spec.scene.access.allowExternalFiles = loaded.limits.allowExternalFiles;
    spec.time.seconds = loaded.time.seconds;
    spec.time.animation = loaded.time.animation;
    // Each keyword through its row of the option table; the rows given,
    // for the warnings of settings that do nothing.
    std::vector<const Option*> rows;
    py::object callback = py::none();
    for (const auto& [key, value] : given) {
      const std::string name = py::str(key);
      if (name == "progress") {
        callback = py::reinterpret_borrow<py::object>(value);
        continue;
      }
      if (name == "camera_to_world") {
        if (!value.is_none()) spec.worldFromCamera = toPose(value);
        continue;
      }
      const Option* row = renderKeyword(name);
      if (!row) throw py::value_error("unknown option '" + name + "' (see help(lensrt.Scene.render))");
      setKeyword(spec, *row, value);
      if (!value.is_none()) rows.push_back(row);
    }
    if (!callback.is_none() && !PyCallable_Check(callback.ptr()))
      badArgument("progress", "a callable progress(done_spp, total_spp) or None", callback);
    // A moving scene recorded over another shutter is posed again from the
    // file this scene was read from (parsed once).
    if (!scene_->geometry().desc().pose.empty() && spec.shutter.spanSeconds() != loaded.time.spanSeconds) {
      if (!posedFrom_) posedFrom_ = std::make_shared<PosedFrom>(loaded);
      const std::shared_ptr<PosedFrom> from = posedFrom_;
      request.repose = [from, seconds = loaded.time.seconds](double span) {
        const std::lock_guard lock(from->mutex);
        return from->sequence.at(seconds, span);
      };
    }
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
    for (const std::string& message : unusedSettings(spec, rows)) warnings.sink().warn(inKeywords(message));
    auto out = std::make_unique<PyRenderResult>();
    {
      const py::gil_scoped_release release;
      out->result = lensrt::render(scene_, request, warnings.sink(), progress);
    }
    if (pending) throw *pending;
    if (out->result.droppedSamples > 0)
      warnings.sink().warn(
          fmt::format("{} samples with NaN or infinite radiance were dropped", out->result.droppedSamples));
    // The library's warnings name the command line's flags (--env none,
    // --sensor): in Python, the keywords (env='none', sensor).
    std::vector<std::string> said;
    for (const std::string& w : warnings.messages()) said.push_back(inKeywords(w));
    WarningList::emit(file(), said);
    return out;
  }

 private:
  PyScene(std::shared_ptr<const Scene> scene, std::shared_ptr<PosedFrom> from)
      : scene_(std::move(scene)), posedFrom_(std::move(from)) {}

  std::shared_ptr<const Scene> scene_;
  // Made by the first at(), or by a render over another span.
  mutable std::shared_ptr<PosedFrom> posedFrom_;
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
          "Every channel by its EXR name (R, G, B, A, depth.Z and Z in metres, normal.X/Y/Z, albedo.R/G/B,\n"
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

  m.def(
      "read",
      [](py::handle path) {
        const std::string file = toPathText(path, "path");
        auto out = std::make_unique<PyRenderResult>();
        RenderResult& r = out->result;
        r.image = readImage(file, &r.metadata);
        if (const auto it = r.metadata.find("lensrt:spp"); it != r.metadata.end())
          r.samplesPerPixel = std::atoi(it->second.c_str());
        if (const auto it = r.metadata.find("lensrt:camera"); it != r.metadata.end()) r.camera = it->second;
        return out;
      },
      arg("path"),
      "Reads an image lensrt wrote (an EXR of `lensrt render`, a frame of --frames) as a RenderResult:\n"
      "its channels by name (the AOVs' too) and its header (metadata). Raises FileNotFoundError or\n"
      "ValueError naming the file.");
  m.def("_render_stub", &renderStub,
        "Scene.render's keyword lines of the stub, from the option table (tools/gen-reference).");
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
      .def("render", &PyScene::render, renderDocstring().c_str());
}

}  // namespace lensrt::python
