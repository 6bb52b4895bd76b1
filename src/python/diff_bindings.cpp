// lensrt.diff: `lensrt diff --json`'s statistics dict, for files or renders.
#include <fmt/core.h>
#include <pybind11/pybind11.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "api/image_comparison.h"
#include "api/output_file.h"
#include "core/error.h"
#include "image/image_io.h"
#include "image/output_formats.h"
#include "python/arguments.h"
#include "python/bindings.h"
#include "python/json_objects.h"
#include "python/render_result.h"

namespace lensrt::python {
namespace {

double threshold(py::handle value, const char* name, double lo, double hi, double fallback) {
  if (value.is_none()) return fallback;
  // The hard thresholds' default is inf, and they take it.
  const double v = py::isinstance<py::float_>(value) && std::isinf(value.cast<double>())
                       ? value.cast<double>()
                       : toDouble(value, name);
  if (!(v >= lo && v <= hi)) badArgument(name, fmt::format("a number from {:g} to {:g}", lo, hi), value);
  return v;
}

// A file (read here) or a RenderResult's image (its name says which render).
ComparedImage comparedImage(py::handle value, const char* name) {
  if (py::isinstance<PyRenderResult>(value)) {
    const RenderResult& r = value.cast<const PyRenderResult&>().result;
    return {name, r.image, r.metadata};
  }
  const std::string file = toPathText(value, name);
  ComparedImage c{file, {}, {}};
  c.image = readImage(file, &c.metadata);
  return c;
}

py::object diff(py::handle a, py::handle b, py::handle fail, py::handle failRelative, py::handle failPercent,
                py::handle hardFail, py::handle warn, py::handle warnRelative, py::handle warnPercent,
                py::handle hardWarn, py::handle relativeFloor, py::handle noiseAware, py::handle pixelAlpha,
                py::handle imageAlpha, py::handle varianceFloor, py::handle spp, py::handle heatmap,
                py::handle heatmapMax) {
  ComparisonOptions o;
  DiffThresholds& t = o.thresholds;
  constexpr double kHuge = 1e300;
  t.fail = threshold(fail, "fail", 0, kHuge, t.fail);
  t.failRelative = threshold(failRelative, "fail_relative", 0, kHuge, t.failRelative);
  t.failPercent = threshold(failPercent, "fail_percent", 0, 100, t.failPercent);
  t.hardFail = threshold(hardFail, "hard_fail", 0, INFINITY, t.hardFail);
  t.warn = threshold(warn, "warn", 0, kHuge, t.warn);
  t.warnRelative = threshold(warnRelative, "warn_relative", 0, kHuge, t.warnRelative);
  t.warnPercent = threshold(warnPercent, "warn_percent", 0, 100, t.warnPercent);
  t.hardWarn = threshold(hardWarn, "hard_warn", 0, INFINITY, t.hardWarn);
  t.relativeFloor = threshold(relativeFloor, "relative_floor", 0, kHuge, t.relativeFloor);
  o.noiseAware = toBool(noiseAware, "noise_aware");
  o.noise.pixelFalseAlarmRate = threshold(pixelAlpha, "pixel_alpha", 1e-12, 0.5, o.noise.pixelFalseAlarmRate);
  o.noise.imageFalseAlarmRate = threshold(imageAlpha, "image_alpha", 1e-12, 0.5, o.noise.imageFalseAlarmRate);
  o.noise.relativeFloor = threshold(varianceFloor, "variance_floor", 0, kHuge, o.noise.relativeFloor);
  if (!spp.is_none()) o.spp = int(toInteger(spp, "spp", 1, 1 << 24));
  if (!heatmap.is_none()) {
    o.heatmap = toPathText(heatmap, "heatmap");
    if (!isWritableImageExtension(o.heatmap))
      throw UsageError("--heatmap", "expects a " + outputExtensionList() + " file");
    createFolderFor(o.heatmap);
  }
  o.heatmapMax = threshold(heatmapMax, "heatmap_max", 0, kHuge, 0.0);
  const ComparedImage imageA = comparedImage(a, "a"), imageB = comparedImage(b, "b");
  const Comparison c = compareImages(imageA, imageB, o);
  if (!c.error.empty()) throw py::value_error(c.error);
  return toPython(c.json);
}

}  // namespace

void bindDiff(py::module_& m) {
  using py::arg;
  m.def("diff", &diff, arg("a"), arg("b"), py::kw_only(), arg("fail") = py::none(),
        arg("fail_relative") = py::none(), arg("fail_percent") = py::none(), arg("hard_fail") = py::none(),
        arg("warn") = py::none(), arg("warn_relative") = py::none(), arg("warn_percent") = py::none(),
        arg("hard_warn") = py::none(), arg("relative_floor") = py::none(), arg("noise_aware") = false,
        arg("pixel_alpha") = py::none(), arg("image_alpha") = py::none(), arg("variance_floor") = py::none(),
        arg("spp") = py::none(), arg("heatmap") = py::none(), arg("heatmap_max") = py::none(),
        R"doc(Compares two images, each a file (EXR, PNG, ...) or a RenderResult, and returns the
dict `lensrt diff --json` prints: per-channel and overall max/mean error, RMSE,
PSNR, the idiff-style verdict ("PASS", "WARN", "FAIL") and exitStatus, and with
noise_aware=True the noise-aware tests (both need aov=("variance",)).
Keywords are `lensrt diff`'s flags (fail, fail_relative, fail_percent, hard_fail,
warn, ..., pixel_alpha, image_alpha, variance_floor, spp, heatmap, heatmap_max);
None keeps the flag's default. Raises FileNotFoundError for a missing file and
ValueError for images that cannot be compared.)doc");
}

}  // namespace lensrt::python
