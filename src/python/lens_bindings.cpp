// lensrt.Lens: a lens from the library or a file, its first-order data
// (`lens info --json`), its surfaces, exact ray traces and the curves of
// `lens plot`, as numbers and numpy arrays.
#include <fmt/core.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "api/camera_models.h"
#include "api/lens_calibration.h"
#include "api/lens_ghosts.h"
#include "api/lens_info.h"
#include "api/lens_loading.h"
#include "api/lens_view.h"
#include "api/option_parsers.h"
#include "api/render_options.h"
#include "api/standalone_camera.h"
#include "api/lens_wave.h"
#include "core/constants.h"
#include "optics/coating.h"
#include "optics/distortion.h"
#include "optics/focus.h"
#include "optics/ghosts.h"
#include "optics/lens_system.h"
#include "optics/mtf.h"
#include "optics/psf.h"
#include "optics/relative_illumination.h"
#include "optics/spot_diagram.h"
#include "python/arguments.h"
#include "python/bindings.h"
#include "python/json_objects.h"
#include "python/warning_list.h"

namespace lensrt::python {
namespace {

std::optional<Coating> toCoating(py::handle value) {
  if (value.is_none()) return std::nullopt;
  const std::string name = toText(value, "coatings");
  const std::optional<Coating> coating = parseCoating(name);
  if (!coating) throw py::value_error("coatings: expected 'none', 'single' or 'multi', got '" + name + "'");
  return coating;
}

// res: "WxH" or (width, height) in pixels.
std::pair<int, int> toRasterSize(py::handle value) {
  if (py::isinstance<py::str>(value)) {
    const Resolution r = parseResolution(value.cast<std::string>());
    if (r.height == 0) badArgument("res", "'WxH' or (width, height) in pixels", value);
    return {r.width, r.height};
  }
  if (py::isinstance<py::sequence>(value) && py::len(value) == 2) {
    const py::sequence s = py::reinterpret_borrow<py::sequence>(value);
    return {int(toInteger(s[0], "res", 2, 65536)), int(toInteger(s[1], "res", 2, 65536))};
  }
  badArgument("res", "'WxH' or (width, height) in pixels", value);
}

double toWavelength(py::handle value) {
  const double wavelength = toDouble(value, "wavelength_nm");
  if (!(wavelength >= 360.0 && wavelength <= 830.0))
    throw py::value_error(fmt::format("wavelength_nm: expected 360 to 830 nm, got {:g}", wavelength));
  return wavelength;
}

// Rows [0, n) in chunks on every core, without the GIL.
template <class F>
void forRows(py::ssize_t n, F&& f) {
  const py::gil_scoped_release release;
  constexpr py::ssize_t kChunk = 1024;
  tbb::parallel_for(py::ssize_t(0), (n + kChunk - 1) / kChunk, [&](py::ssize_t chunk) {
    for (py::ssize_t i = chunk * kChunk; i < std::min(n, (chunk + 1) * kChunk); ++i) f(i);
  });
}

class PyLens {
 public:
  explicit PyLens(py::handle spec) : lens_(loadUserLens(toPathText(spec, "lens"), LENSRT_LENS_DIR)) {}

  const UserLens& user() const { return lens_; }

  // The lens stopped down and focused, with the sensor that sets the field.
  LensView view(py::handle fstop, py::handle focus, py::handle sensor, py::handle coatings,
                WarningList& warnings) const {
    LensViewOptions o;
    o.fNumber = toOptionalDouble(fstop, "fstop");
    o.focus = toDistanceText(focus, "focus");
    o.sensor = toSensorText(sensor, "sensor");
    const std::optional<Coating> coating = toCoating(coatings);
    o.coatings = coating ? coatingName(*coating) : "";
    return prepareLensView(lens_, o, warnings.sink());
  }

  py::object ghosts(py::handle coatings) const {
    const Coating coating = toCoating(coatings).value_or(Coating::None);
    requireRealImage(lens_);
    return toPython(withLensErrors(lens_, [&] {
      return lensGhostsJson(lens_.prescription, coating, strongestGhosts(lens_.prescription, coating));
    }));
  }

  py::object info(py::handle fstop, py::handle focus, py::handle sensor, py::handle coc,
                  py::handle coatings) const {
    const Vec2d size = parseSensorSize(toSensorText(sensor, "sensor"));
    LensInfoSettings settings;
    settings.sensorWidthMm = size.x;
    settings.sensorHeightMm = size.y;
    settings.fNumber = toOptionalDouble(fstop, "fstop");
    checkFNumber(settings.fNumber);
    settings.focusMetres = parseFocusMetres(toDistanceText(focus, "focus"));
    settings.circleOfConfusionMm = toOptionalDouble(coc, "coc");
    if (settings.circleOfConfusionMm && !(*settings.circleOfConfusionMm > 0))
      throw UsageError("--coc", "must be positive");
    settings.coating = toCoating(coatings).value_or(Coating::None);
    WarningList warnings;
    requireRealImage(lens_);
    const nlohmann::json json = withLensErrors(lens_, [&] {
      const LensInfo info = lensInfo(lens_.prescription, settings, warnings.sink());
      return lensInfoJson(info, warnings.messages());
    });
    warnings.emit();
    return toPython(json);
  }

  // The camera a render with these keywords makes (Scene.render's names).
  CameraSpec cameraOptions(py::handle camera, py::handle sensor, py::handle focus, py::handle fstop) const {
    CameraSpec o;
    o.lensDir = LENSRT_LENS_DIR;
    o.lens = lens_.label;
    const std::string model = toText(camera, "camera");
    bool known = false;
    for (const CameraModelInfo& m : cameraModels())
      if (m.name == model) o.model = m.model, known = true;
    if (!known)
      throw py::value_error("camera: expected 'lens', 'thick', 'thin' or 'pinhole', got '" + model + "'");
    o.sensorMm = parseSensor(toSensorText(sensor, "sensor"));
    o.focusMetres = parseFocusDistance(toDistanceText(focus, "focus"));
    o.fNumber = toOptionalDouble(fstop, "fstop");
    return o;
  }

  StandaloneCamera projection(py::handle pose, py::handle res, py::handle focus, py::handle sensor,
                              py::handle fstop, py::handle camera) const {
    const Transform worldFromCamera = pose.is_none() ? Transform() : toPose(pose);
    const auto [width, height] = toRasterSize(res);
    WarningList warnings;
    StandaloneCamera c = makeStandaloneCamera(cameraOptions(camera, sensor, focus, fstop), width, height,
                                              worldFromCamera, warnings.sink());
    warnings.emit();
    return c;
  }

  py::object project(py::handle pointsIn, py::handle pose, py::handle res, py::handle focus,
                     py::handle sensor, py::handle fstop, py::handle wavelengthIn, py::handle camera) const {
    const auto points = toFiniteMatrix(pointsIn, "world_points", 3);
    const double wavelength = toWavelength(wavelengthIn);
    const StandaloneCamera c = projection(pose, res, focus, sensor, fstop, camera);
    const py::ssize_t n = points.shape(0);
    py::array_t<double> pixels({n, py::ssize_t(2)});
    py::array_t<bool> visible(n);
    py::array_t<std::uint8_t> status(n);
    const double* p = points.data();
    double* px = pixels.mutable_data();
    bool* v = visible.mutable_data();
    std::uint8_t* s = status.mutable_data();
    forRows(n, [&](py::ssize_t i) {
      const ProjectedPoint q = c.camera->project({p[3 * i], p[3 * i + 1], p[3 * i + 2]}, wavelength);
      px[2 * i] = q.raster.x, px[2 * i + 1] = q.raster.y;
      v[i] = q.visibility == Visibility::Visible;
      s[i] = std::uint8_t(q.visibility);
    });
    return py::module_::import("lensrt").attr("Projection")(pixels, visible, status);
  }

  py::object unproject(py::handle pixelsIn, py::handle pose, py::handle res, py::handle focus,
                       py::handle sensor, py::handle fstop, py::handle wavelengthIn,
                       py::handle camera) const {
    const auto pixels = toFiniteMatrix(pixelsIn, "pixels", 2);
    const double wavelength = toWavelength(wavelengthIn);
    const StandaloneCamera c = projection(pose, res, focus, sensor, fstop, camera);
    const py::ssize_t n = pixels.shape(0);
    py::array_t<double> origins({n, py::ssize_t(3)}), directions({n, py::ssize_t(3)});
    py::array_t<bool> visible(n);
    py::array_t<std::uint8_t> status(n);
    const double* p = pixels.data();
    double* o = origins.mutable_data();
    double* d = directions.mutable_data();
    bool* v = visible.mutable_data();
    std::uint8_t* s = status.mutable_data();
    forRows(n, [&](py::ssize_t i) {
      const ProjectedRay r = c.camera->unproject({p[2 * i], p[2 * i + 1]}, wavelength);
      o[3 * i] = r.origin.x, o[3 * i + 1] = r.origin.y, o[3 * i + 2] = r.origin.z;
      d[3 * i] = r.direction.x, d[3 * i + 1] = r.direction.y, d[3 * i + 2] = r.direction.z;
      v[i] = r.visibility == Visibility::Visible;
      s[i] = std::uint8_t(r.visibility);
    });
    return py::module_::import("lensrt").attr("Unprojection")(origins, directions, visible, status);
  }

  py::object calibrate(py::handle res, py::handle focus, py::handle sensor, py::handle fstop,
                       py::handle model, py::handle wavelength, py::handle camera,
                       py::handle maxResidual) const {
    CalibrationRequest request;
    request.camera = cameraOptions(camera, sensor, focus, fstop);
    std::tie(request.width, request.height) = toRasterSize(res);
    const std::string name = toText(model, "model");
    const std::optional<OpenCvModel> m = parseOpenCvModel(name);
    if (!m)
      throw py::value_error("model: expected 'opencv', 'opencv4', 'full-opencv' or 'fisheye', got '" + name +
                            "'");
    request.model = *m;
    request.wavelengthNm = toWavelength(wavelength);
    request.maxResidualPx = toDouble(maxResidual, "max_residual");
    WarningList warnings;
    nlohmann::json json;
    {
      const py::gil_scoped_release release;
      json = calibrationJson(calibrateLens(request, warnings.sink()));
    }
    warnings.emit();
    return toPython(json);
  }

  py::list surfaces() const {
    py::list out;
    double z = 0.0;
    for (const Surface& s : lens_.prescription.surfaces) {
      py::dict d;
      d["radius_mm"] = s.radius;
      d["thickness_mm"] = s.thickness;
      d["aperture_diameter_mm"] = s.apertureDiameter;
      d["z_mm"] = z;
      d["stop"] = s.isStop;
      d["n_d"] = s.medium.nd;
      d["v_d"] = s.medium.vd;
      d["glass"] = s.medium.isAir() ? std::string("air") : s.medium.glass;
      d["conic"] = s.conic;
      d["aspheric"] = std::vector<double>(s.aspheric.begin(), s.aspheric.end());
      out.append(d);
      z += s.thickness;
    }
    return out;
  }

  py::object trace(py::handle originsIn, py::handle directionsIn, py::handle wavelengthIn, py::handle fstop,
                   py::handle coatings) const {
    const auto origins = toFiniteMatrix(originsIn, "origins", 3);
    const auto directions = toFiniteMatrix(directionsIn, "directions", 3, origins.shape(0));
    const double wavelength = toDouble(wavelengthIn, "wavelength_nm");
    if (wavelength < 300.0 || wavelength > 1000.0)
      throw py::value_error(fmt::format("wavelength_nm: expected 300 to 1000 nm, got {:g}", wavelength));
    WarningList warnings;
    const std::optional<double> f = toOptionalDouble(fstop, "fstop");
    checkFNumber(f);
    const LensSystem lens = withLensErrors(lens_, [&] {
      return LensSystem(f ? stopDown(lens_.prescription, *f, warnings.sink()) : lens_.prescription,
                        toCoating(coatings));
    });
    warnings.emit();
    const py::ssize_t n = origins.shape(0);
    const double* o = origins.data();
    const double* d = directions.data();
    for (py::ssize_t i = 0; i < n; ++i)
      if (!(d[3 * i + 2] < 0.0))
        throw py::value_error(fmt::format(
            "directions: row {} does not point toward the lens's front (rays leave the film with z < 0)", i));
    py::array_t<double> points({n, py::ssize_t(3)}), exits({n, py::ssize_t(3)});
    py::array_t<double> weights(n);
    py::array_t<bool> passed(n);
    double* p = points.mutable_data();
    double* e = exits.mutable_data();
    double* w = weights.mutable_data();
    bool* ok = passed.mutable_data();
    {
      const py::gil_scoped_release release;
      // Chunks of the batched trace, bit for bit traceFromFilm on each ray.
      constexpr py::ssize_t kChunk = 4096;
      tbb::parallel_for(py::ssize_t(0), (n + kChunk - 1) / kChunk, [&](py::ssize_t chunk) {
        const py::ssize_t first = chunk * kChunk, count = std::min(kChunk, n - first);
        std::vector<LensRay> rays(count);
        std::vector<std::optional<LensRay>> out(count);
        for (py::ssize_t i = 0; i < count; ++i) {
          const double* oi = o + 3 * (first + i);
          const double* di = d + 3 * (first + i);
          rays[i].origin = {oi[0], oi[1], oi[2]};
          rays[i].direction = {di[0], di[1], di[2]};
        }
        if (wavelength == kWavelengthDNm) {
          lens.traceFromFilm(rays, out);
        } else {
          const std::vector<double> wavelengths(count, wavelength);
          lens.traceFromFilm(rays, wavelengths, out);
        }
        for (py::ssize_t i = 0; i < count; ++i) {
          const py::ssize_t k = first + i;
          const std::optional<LensRay>& r = out[i];
          ok[k] = r.has_value();
          const LensRay hit = r.value_or(LensRay{{0, 0, 0}, {0, 0, 0}, 0.0});
          p[3 * k] = hit.origin.x, p[3 * k + 1] = hit.origin.y, p[3 * k + 2] = hit.origin.z;
          e[3 * k] = hit.direction.x, e[3 * k + 1] = hit.direction.y, e[3 * k + 2] = hit.direction.z;
          w[k] = r ? hit.transmittance : 0.0;
        }
      });
    }
    const py::object traceResult = py::module_::import("lensrt").attr("TraceResult");
    return traceResult(points, exits, weights, passed);
  }

  double focus(py::handle distance) const {
    const double mm = parseFocusDistanceMm(toDistanceText(distance, "distance_m"));
    requireRealImage(lens_);
    return withLensErrors(lens_, [&] { return focusFilmDistance(LensSystem(lens_.prescription), mm); });
  }

  py::array_t<double> spot(py::handle field, py::handle fstop, py::handle focus, py::handle rays,
                           py::handle wavelengthIn, py::handle coatings) const {
    const double angle = toDouble(field, "field_deg");
    if (!(std::abs(angle) < 90.0))
      throw py::value_error("field_deg: expected an angle from the axis under 90 deg");
    const int grid = int(toInteger(rays, "rays", 2, 4096));
    const double wavelength = toDouble(wavelengthIn, "wavelength_nm");
    WarningList warnings;
    const LensView v = view(fstop, focus, py::str("36x24"), coatings, warnings);
    warnings.emit();
    const SpotDiagram s = withLensErrors(lens_, [&] {
      return spotDiagram(v.lens, {angle, v.focusMm}, v.filmDistanceMm, grid, wavelength);
    });
    py::array_t<double> out({py::ssize_t(s.points.size()), py::ssize_t(2)});
    double* o = out.mutable_data();
    for (std::size_t i = 0; i < s.points.size(); ++i) o[2 * i] = s.points[i].x, o[2 * i + 1] = s.points[i].y;
    return out;
  }

  py::tuple relativeIllumination(py::handle fstop, py::handle focus, py::handle sensor,
                                 py::handle points) const {
    const int count = int(toInteger(points, "points", 2, 10000));
    WarningList warnings;
    const LensView v = view(fstop, focus, sensor, py::none(), warnings);
    warnings.emit();
    std::vector<RelativeIlluminationPoint> curve;
    {
      const py::gil_scoped_release release;
      curve = withLensErrors(lens_, [&] {
        return relativeIlluminationCurve(v.lens, v.filmDistanceMm, v.halfDiagonalMm(), count);
      });
    }
    py::array_t<double> radius(py::ssize_t(curve.size())), relative(py::ssize_t(curve.size()));
    for (std::size_t i = 0; i < curve.size(); ++i) {
      radius.mutable_data()[i] = curve[i].filmRadiusMm;
      relative.mutable_data()[i] = curve[i].relative;
    }
    return py::make_tuple(radius, relative);
  }

  py::tuple distortion(py::handle fstop, py::handle focus, py::handle sensor, py::handle points) const {
    const int count = int(toInteger(points, "points", 2, 10000));
    WarningList warnings;
    const LensView v = view(fstop, focus, sensor, py::none(), warnings);
    warnings.emit();
    const std::vector<DistortionPoint> curve = withLensErrors(lens_, [&] {
      return distortionCurve(v.lens, v.focusMm, v.filmDistanceMm, v.halfDiagonalMm(), count);
    });
    py::array_t<double> angle(py::ssize_t(curve.size())), percent(py::ssize_t(curve.size()));
    for (std::size_t i = 0; i < curve.size(); ++i) {
      angle.mutable_data()[i] = curve[i].fieldAngleDeg;
      percent.mutable_data()[i] = curve[i].percent;
    }
    return py::make_tuple(angle, percent);
  }

  // Lens.psf() and Lens.mtf(): the keywords of `lens psf` / `lens mtf`.
  struct WaveArguments {
    py::handle field, fstop, focus, wavelengths, weights, pupilSamples, padding, blades, bladeRotation, mask,
        coatings;
  };
  LensWave wave(const WaveArguments& a, WarningList& warnings) const {
    LensViewOptions o;
    o.fNumber = toOptionalDouble(a.fstop, "fstop");
    o.focus = toDistanceText(a.focus, "focus");
    const std::optional<Coating> coating = toCoating(a.coatings);
    o.coatings = coating ? coatingName(*coating) : "";
    LensWaveOptions w;
    w.fieldDeg = toDouble(a.field, "field_deg");
    if (!isNone(a.wavelengths)) w.wavelengthsNm = toDoubles(a.wavelengths, "wavelengths_nm");
    if (!isNone(a.weights)) w.weights = toDoubles(a.weights, "weights");
    w.pupilSamples = int(toInteger(a.pupilSamples, "pupil_samples", 0, 2049));
    w.padding = int(toInteger(a.padding, "padding", 2, 32));
    w.blades = int(toInteger(a.blades, "blades", 0, 64));
    w.bladeRotationDeg = toDouble(a.bladeRotation, "blade_rotation_deg");
    if (!isNone(a.mask)) w.apertureMask = toPathText(a.mask, "aperture_mask");
    return prepareLensWave(lens_, o, w, warnings.sink());
  }

  static std::vector<double> toDoubles(py::handle value, const char* name) {
    std::vector<double> out;
    if (py::isinstance<py::str>(value)) badArgument(name, "a sequence of numbers", value);
    for (const py::handle item : py::iter(value)) out.push_back(toDouble(item, name));
    return out;
  }

  static py::array_t<double> toArray(const std::vector<double>& values) {
    py::array_t<double> out(py::ssize_t(values.size()));
    std::copy(values.begin(), values.end(), out.mutable_data());
    return out;
  }

  py::dict psf(const WaveArguments& a) const {
    WarningList warnings;
    const LensWave w = wave(a, warnings);
    warnings.emit();
    Psf psf;
    {
      const py::gil_scoped_release release;
      psf = withLensErrors(lens_, [&] { return w.model->psf(); });
    }
    const auto grid = [&](const std::vector<double>& v) {
      py::array_t<double> out({py::ssize_t(psf.size), py::ssize_t(psf.size)});
      std::copy(v.begin(), v.end(), out.mutable_data());
      return out;
    };
    py::dict d;
    d["psf"] = grid(psf.intensity);
    d["limit"] = grid(psf.limit);
    d["pixel_um"] = psf.pixelMm * 1000.0;
    d["summary"] = toPython(psfSummaryJson(w, psf));
    return d;
  }

  py::dict mtf(const WaveArguments& a, py::handle maxFrequency, py::handle points, py::handle focusFrequency,
               py::handle focusRange) const {
    const int count = int(toInteger(points, "points", 2, 100000));
    const std::optional<double> maxF = toOptionalDouble(maxFrequency, "max_frequency");
    const std::optional<double> focusF = toOptionalDouble(focusFrequency, "focus_frequency");
    const std::optional<double> range = toOptionalDouble(focusRange, "focus_range_mm");
    for (const auto& [v, name] : {std::pair{maxF, "max_frequency"}, std::pair{focusF, "focus_frequency"},
                                  std::pair{range, "focus_range_mm"}})
      if (v && !(*v > 0.0)) throw py::value_error(std::string(name) + ": must be positive");
    WarningList warnings;
    const LensWave w = wave(a, warnings);
    warnings.emit();
    Psf psf;
    MtfCurves curves;
    ThroughFocusMtf focus;
    {
      const py::gil_scoped_release release;
      withLensErrors(lens_, [&] {
        psf = w.model->psf();
        const double cutoff = std::max(psf.cutoffPerMm.x, psf.cutoffPerMm.y);
        curves = mtfCurves(psf, maxF.value_or(cutoff), count);
        const double primary = w.model->settings().wavelengthsNm.front() * 1e-6;
        const double reach = range.value_or(4.0 * primary * w.fNumber * w.fNumber);
        std::vector<double> shifts;
        for (int k = 0; k <= 20; ++k) shifts.push_back(reach * (k / 10.0 - 1.0));
        focus = throughFocusMtf(*w.model, focusF.value_or(cutoff / 4.0), shifts);
        return 0;
      });
    }
    py::dict d;
    d["frequency_per_mm"] = toArray(curves.frequencyPerMm);
    d["tangential"] = toArray(curves.tangential);
    d["sagittal"] = toArray(curves.sagittal);
    d["limit_tangential"] = toArray(curves.limitTangential);
    d["limit_sagittal"] = toArray(curves.limitSagittal);
    py::dict tf;
    tf["frequency_per_mm"] = focus.frequencyPerMm;
    tf["film_shift_mm"] = toArray(focus.filmShiftMm);
    tf["tangential"] = toArray(focus.tangential);
    tf["sagittal"] = toArray(focus.sagittal);
    tf["limit"] = toArray(focus.limit);
    d["through_focus"] = tf;
    d["summary"] = toPython(psfSummaryJson(w, psf));
    return d;
  }

 private:
  UserLens lens_;
};

}  // namespace

void bindLens(py::module_& m) {
  using py::arg;
  py::class_<PyLens>(
      m, "Lens", R"doc(A lens: a library name (e.g. "dgauss-50mm") or a lens file (.lens, .json, .dat, .zmx).

Lens space: millimetres, the optical axis along z, the front vertex at z = 0
and the film behind the rear vertex at z > 0. Raises FileNotFoundError when
no such file or library lens exists, ValueError when the file is invalid.)doc")
      .def(py::init<py::handle>(), arg("lens"))
      .def_property_readonly(
          "name", [](const PyLens& l) { return l.user().prescription.name; }, "The lens's name (str).")
      .def_property_readonly(
          "file", [](const PyLens& l) { return l.user().prescription.file; },
          "The file it was read from (str).")
      .def("__repr__", [](const PyLens& l) { return "lensrt.Lens('" + l.user().label + "')"; })
      .def("info", &PyLens::info, arg("fstop") = py::none(), arg("focus") = "inf", arg("sensor") = "36x24",
           arg("coc") = py::none(), arg("coatings") = "none",
           R"doc(First-order data, the dict `lensrt lens info --json` prints.

fstop: f-number to stop down to (None: wide open).
focus: object distance in metres from the entrance pupil, or "inf".
sensor: "WxH" in mm or a (width, height) pair in mm.
coc: circle of confusion in mm (None: the sensor diagonal / 1500).
coatings: "none", "single" or "multi", for the axial transmittance.
Distances are in mm unless the key ends in _m (metres); None at infinity.)doc")
      .def("ghosts", &PyLens::ghosts, arg("coatings") = "none",
           R"doc(The two-reflection ghosts, strongest first: the dict `lensrt lens ghosts --json`
prints (lens, coatings, ghosts: surfaces [I, J] numbered from the front,
strength R_I R_J, passing, relative_flux, focus_from_film_mm or None,
size_on_film_mm). coatings: "none", "single" or "multi".)doc")
      .def_property_readonly("surfaces", &PyLens::surfaces,
                             R"doc(The surfaces front to back, as dicts: radius_mm (0: flat), thickness_mm
(to the next vertex), aperture_diameter_mm, z_mm (vertex), stop (bool), n_d, v_d
and glass of the medium behind the surface ("air" for air), conic, aspheric
(A4, A6, ... A16).)doc")
      .def("trace", &PyLens::trace, arg("origins"), arg("directions"), arg("wavelength_nm") = kWavelengthDNm,
           arg("fstop") = py::none(), arg("coatings") = py::none(),
           R"doc(Traces rays from the film side through the lens toward the scene, exactly.

origins, directions: N x 3 arrays in lens space (mm), directions with z < 0.
wavelength_nm: the wavelength in nm (default the helium d line, 587.5618).
fstop: stop down first (None: wide open). coatings: None (lossless glass),
"none" (bare glass), "single" or "multi": the weights carry Fresnel losses.
Returns TraceResult(points, directions, weights, passed): where the rays leave
the front surface (N x 3, mm) and their unit directions (N x 3), the
transmitted fraction (N), and which rays passed (N, bool; rows of blocked
rays are 0). The GIL is released; the rays are traced in parallel.)doc")
      .def("focus", &PyLens::focus, arg("distance_m"),
           R"doc(The film distance in mm (rear vertex to film) that focuses an object
distance_m metres in front of the entrance pupil (or "inf"/math.inf).)doc")
      .def("spot", &PyLens::spot, arg("field_deg") = 0.0, arg("fstop") = py::none(), arg("focus") = "inf",
           arg("rays") = 41, arg("wavelength_nm") = kWavelengthDNm, arg("coatings") = py::none(),
           R"doc(Spot diagram: film (x, y) in mm, an M x 2 array, of a grid of `rays` rays across the
passing beam of a point at field_deg degrees from the axis (toward +x), with the
film focused at `focus` metres (or "inf").)doc")
      .def("relative_illumination", &PyLens::relativeIllumination, arg("fstop") = py::none(),
           arg("focus") = "inf", arg("sensor") = "36x24", arg("points") = 33,
           R"doc(Relative illumination E(r)/E(0) of a uniform scene across the film, from exact rays
(cos^4 falloff, vignetting, pupil aberration). Returns (radius_mm, relative),
two arrays of `points` film radii from 0 to the sensor's half diagonal.)doc")
      .def("distortion", &PyLens::distortion, arg("fstop") = py::none(), arg("focus") = "inf",
           arg("sensor") = "36x24", arg("points") = 41,
           R"doc(Distortion of the real chief ray against the paraxial image height, in percent
(negative: barrel). Returns (field_deg, percent), two arrays up to the field
that reaches the sensor's half diagonal.)doc")
      .def("project", &PyLens::project, arg("world_points"), arg("camera_to_world"), py::kw_only(),
           arg("res"), arg("focus"), arg("sensor") = "full-frame", arg("fstop") = py::none(),
           arg("wavelength_nm") = kWavelengthDNm, arg("camera") = "lens",
           R"doc(Where world points image on the film, in pixels: the projection a render with the
same keywords has (Scene.render's camera, lens, res, sensor, focus, fstop).

world_points: N x 3, metres. camera_to_world: the camera's 4 x 4 pose (glTF's
convention: it looks down -Z with +Y up; the origin at the entrance pupil),
or None for points already in camera space. focus: metres or "inf" (not
"auto"). camera: "lens" (the full lens), "thick", "thin" or "pinhole".
A point maps to where its chief ray (through the stop's centre) meets the
film, traced at wavelength_nm (the full lens with dispersion data, and the
thick lens, image colours apart).
Returns Projection(pixels, visible, status): raster positions (N x 2;
(0, 0) the top-left corner of the top-left pixel, x right, y down), which are
inside the frame, and why not: 0 visible, 1 outside the frame, 2 blocked by
the lens (pixels: where the chief ray would land with the rims opened, NaN
when none exists), 3 behind the camera (NaN). The GIL is released.)doc")
      .def("unproject", &PyLens::unproject, arg("pixels"), arg("camera_to_world") = py::none(), py::kw_only(),
           arg("res"), arg("focus"), arg("sensor") = "full-frame", arg("fstop") = py::none(),
           arg("wavelength_nm") = kWavelengthDNm, arg("camera") = "lens",
           R"doc(The chief ray each raster position sees: project's inverse (every point on the
ray projects to that position). pixels: N x 2 raster positions; the other
arguments as project's. Returns Unprojection(origins, directions, visible,
status): world-space origins (N x 3, metres: where the ray leaves the front
glass for the full lens, the camera origin for the others), unit directions
toward the scene, and status as project's (2: the lens blocks it).)doc")
      .def("calibrate", &PyLens::calibrate, py::kw_only(), arg("res"), arg("focus"),
           arg("sensor") = "full-frame", arg("fstop") = py::none(), arg("model") = "opencv",
           arg("wavelength_nm") = kWavelengthDNm, arg("camera") = "lens", arg("max_residual") = 1.0,
           R"doc(OpenCV's camera model fitted to this lens's projection over the whole frame: the
dict `lensrt lens calibrate --json` prints (fx, fy, cx, cy in OpenCV's pixels,
whose top-left pixel's centre is (0, 0); the coefficients by name;
camera_matrix, dist_coeffs; residual_px {rms, max, points, blocked}; colmap,
the COLMAP cameras.txt line, whose cx, cy are OpenCV's + 0.5).
model: "opencv" (k1 k2 p1 p2 k3), "opencv4" (k1 k2 p1 p2), "full-opencv"
(k1..k6, p1, p2) or "fisheye" (cv2.fisheye's k1..k4). The points lie on the
focus plane (directions at infinity). Raises ValueError when the largest
residual exceeds max_residual pixels.)doc")
      .def(
          "psf",
          [](const PyLens& l, py::handle field, py::handle fstop, py::handle focus, py::handle wavelengths,
             py::handle weights, py::handle pupilSamples, py::handle padding, py::handle blades,
             py::handle bladeRotation, py::handle mask, py::handle coatings) {
            return l.psf({field, fstop, focus, wavelengths, weights, pupilSamples, padding, blades,
                          bladeRotation, mask, coatings});
          },
          arg("field_deg") = 0.0, arg("fstop") = py::none(), arg("focus") = "inf",
          arg("wavelengths_nm") = py::none(), arg("weights") = py::none(), arg("pupil_samples") = 0,
          arg("padding") = 4, arg("blades") = 0, arg("blade_rotation_deg") = 0.0,
          arg("aperture_mask") = py::none(), arg("coatings") = py::none(),
          R"doc(The PSF of a field point by FFT of its pupil function (as `lensrt lens psf`):
a dict with "psf" and "limit" (the same pupil without its OPD), size x size
arrays on the film (rows along y, the chief ray's image at [size/2, size/2],
values the fraction of the light per sample), "pixel_um", and "summary" (the
sampling, Strehl ratio, RMS OPD per wavelength). wavelengths_nm defaults to
the d, F and C lines, the first the primary; weights to equal.)doc")
      .def(
          "mtf",
          [](const PyLens& l, py::handle field, py::handle fstop, py::handle focus, py::handle wavelengths,
             py::handle weights, py::handle pupilSamples, py::handle padding, py::handle blades,
             py::handle bladeRotation, py::handle mask, py::handle coatings, py::handle maxFrequency,
             py::handle points, py::handle focusFrequency, py::handle focusRange) {
            return l.mtf({field, fstop, focus, wavelengths, weights, pupilSamples, padding, blades,
                          bladeRotation, mask, coatings},
                         maxFrequency, points, focusFrequency, focusRange);
          },
          arg("field_deg") = 0.0, arg("fstop") = py::none(), arg("focus") = "inf",
          arg("wavelengths_nm") = py::none(), arg("weights") = py::none(), arg("pupil_samples") = 0,
          arg("padding") = 4, arg("blades") = 0, arg("blade_rotation_deg") = 0.0,
          arg("aperture_mask") = py::none(), arg("coatings") = py::none(), arg("max_frequency") = py::none(),
          arg("points") = 101, arg("focus_frequency") = py::none(), arg("focus_range_mm") = py::none(),
          R"doc(The MTF of a field point (as `lensrt lens mtf`): a dict of arrays
"frequency_per_mm", "tangential", "sagittal", "limit_tangential",
"limit_sagittal" (`points` frequencies up to max_frequency, default the
cutoff), "through_focus" (the MTF at focus_frequency, default a quarter of
the cutoff, for 21 film shifts over +-focus_range_mm) and "summary".)doc");
}

}  // namespace lensrt::python
