#include "api/lens_wave.h"

#include <fmt/core.h>

#include <cmath>

#include "api/aperture_mask_file.h"
#include "camera/aperture.h"
#include "core/error.h"
#include "optics/focus.h"

namespace lensrt {

std::vector<double> parseNumberList(const std::string& text, const std::string& option) {
  std::vector<double> values;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, comma - start);
    try {
      std::size_t used = 0;
      const double v = std::stod(item, &used);
      if (used != item.size() || !std::isfinite(v)) throw std::invalid_argument(item);
      values.push_back(v);
    } catch (const std::exception&) {
      throw UsageError(option, "expected comma-separated numbers, got '" + text + "'");
    }
    start = comma + 1;
  }
  return values;
}

namespace {

void checkWaveOptions(const LensWaveOptions& w) {
  if (!(std::abs(w.fieldDeg) < 89.5)) throw UsageError("--field", "must be within +-89.5 degrees");
  for (const double wl : w.wavelengthsNm)
    if (!(wl >= 200.0 && wl <= 2000.0)) throw UsageError("--wavelengths", "each must be within 200-2000 nm");
  if (!w.weights.empty() && w.weights.size() != (w.wavelengthsNm.empty() ? 3 : w.wavelengthsNm.size()))
    throw UsageError("--weights", "needs one weight per wavelength");
  double sum = 0.0;
  for (const double v : w.weights) {
    if (!(v >= 0.0)) throw UsageError("--weights", "must be >= 0");
    sum += v;
  }
  if (!w.weights.empty() && !(sum > 0.0)) throw UsageError("--weights", "must not all be 0");
  if (w.pupilSamples != 0 && (w.pupilSamples < 9 || w.pupilSamples > 2049 || w.pupilSamples % 2 == 0))
    throw UsageError("--pupil-samples", "must be odd, 9-2049 (or 0: automatic)");
  if (w.padding < 2 || w.padding > 32) throw UsageError("--padding", "must be 2-32");
  if (w.blades < 0 || w.blades == 1 || w.blades == 2 || w.blades > 64)
    throw UsageError("--blades", "must be 0 (round) or 3-64");
  if (!std::isfinite(w.bladeRotationDeg)) throw UsageError("--blade-rotation", "must be finite");
  if (w.blades && !w.apertureMask.empty())
    throw UsageError("--aperture-mask", "give blades or a mask, not both");
}

}  // namespace

LensWave prepareLensWave(const LensViewOptions& view, const LensWaveOptions& wave, Warnings& warnings) {
  if (!view.output.empty()) checkSvgOutput(view.output);
  parseSensorSize(view.sensor);
  parseFocusDistanceMm(view.focus);
  checkFNumber(view.fNumber);
  checkWaveOptions(wave);
  return prepareLensWave(loadUserLens(view.lens, LENSRT_LENS_DIR), view, wave, warnings);
}

LensWave prepareLensWave(const UserLens& user, const LensViewOptions& viewOptions,
                         const LensWaveOptions& wave, Warnings& warnings) {
  checkWaveOptions(wave);
  std::shared_ptr<const ApertureMask> mask;
  if (!wave.apertureMask.empty()) mask = std::make_shared<ApertureMask>(readApertureMask(wave.apertureMask));
  requireRealImage(user);
  // Blades: as the full-lens camera, a polygon of the f-number's area whose
  // corners touch the round stop, opened by the polygon's factor.
  const double widen = polygonCircumradiusFactor(wave.blades);
  LensViewOptions o = viewOptions;
  const double requested = o.fNumber.value_or(computeParaxial(user.prescription).fNumber);
  if (wave.blades) o.fNumber = requested / widen;
  LensWave w{prepareLensView(user, o, warnings), nullptr, 0.0, "round"};
  return withLensErrors(user, [&] {
    const LensSystem& lens = w.view.lens;
    const ParaxialData& p = lens.paraxial();
    const double stopRadius = lens.prescription().surfaces[std::size_t(p.stopIndex)].apertureDiameter / 2.0;
    w.fNumber = p.fNumber * widen;
    PsfSettings s;
    s.field = {wave.fieldDeg, w.view.focusMm};
    s.filmDistanceMm = w.view.filmDistanceMm;
    if (!wave.wavelengthsNm.empty()) {
      s.wavelengthsNm = wave.wavelengthsNm;
      s.weights.assign(wave.wavelengthsNm.size(), 1.0);
    }
    if (!wave.weights.empty()) s.weights = wave.weights;
    s.pupilSamples = wave.pupilSamples;
    s.padding = wave.padding;
    if (wave.blades) {
      const ApertureShape shape{wave.blades, wave.bladeRotationDeg};
      const Aperture polygon(stopRadius / widen, shape);
      s.stop = [polygon](double x, double y) { return polygon.contains({x, y}) ? 1.0 : 0.0; };
      w.stopText = fmt::format("{} blades at {:g} deg", wave.blades, wave.bladeRotationDeg);
    } else if (mask) {
      s.stop = [mask, stopRadius](double x, double y) { return mask->transmittance({x, y}, stopRadius); };
      w.stopText = "mask " + mask->describe();
    }
    // A field whose chief ray does not pass is a bad --field for this lens.
    if (!chiefRayAim(lens, s.field, s.wavelengthsNm.front()))
      throw UsageError("--field",
                       fmt::format("{}: {:g} deg is beyond the lens's coverage (its chief ray does not "
                                   "pass the lens)",
                                   user.label, wave.fieldDeg));
    w.model = std::make_unique<PsfModel>(lens, std::move(s));
    return std::move(w);
  });
}

std::string LensWave::summary() const {
  const ParaxialData& p = view.lens.paraxial();
  return fmt::format("EFL {:.2f} mm, f/{:.3g}, focus {}, field {:g} deg, stop {}", p.efl, fNumber,
                     view.focusText(), model->settings().field.angleDeg, stopText);
}

std::string samplingText(const Psf& psf) {
  return fmt::format(
      "pupil {} samples across, FFT {} x {} (padding {}), PSF sampled every {:.3g} um; largest OPD step "
      "{:.3f} "
      "waves per sample: {}",
      psf.pupilSamples, psf.size, psf.size, psf.padding, psf.pixelMm * 1000.0, psf.maxStepWaves,
      psf.aliased() ? "ALIASED (the PSF wraps around: raise --pupil-samples)" : "not aliased (below 0.5)");
}

nlohmann::json psfSummaryJson(const LensWave& wave, const Psf& psf) {
  const PsfSettings& s = wave.model->settings();
  nlohmann::json j;
  j["lens"] = wave.view.lens.prescription().name;
  j["f_number"] = wave.fNumber;
  j["focus_mm"] =
      std::isinf(wave.view.focusMm) ? nlohmann::json("infinity") : nlohmann::json(wave.view.focusMm);
  j["film_distance_mm"] = wave.view.filmDistanceMm;
  j["field_deg"] = s.field.angleDeg;
  j["stop"] = wave.stopText;
  j["image_point_mm"] = {psf.originMm.x, psf.originMm.y};
  j["sampling"] = {{"pupil_samples", psf.pupilSamples},
                   {"fft_size", psf.size},
                   {"padding", psf.padding},
                   {"psf_sample_um", psf.pixelMm * 1000.0},
                   {"psf_window_um", psf.size * psf.pixelMm * 1000.0},
                   {"max_opd_step_waves", psf.maxStepWaves},
                   {"aliased", psf.aliased()},
                   {"light_in_window", psf.windowLight}};
  j["strehl"] = psf.strehl;
  j["rms_radius_um"] = psf.rmsRadiusMm() * 1000.0;
  j["centroid_um"] = {psf.centroidMm().x * 1000.0, psf.centroidMm().y * 1000.0};
  j["cutoff_per_mm"] = {psf.cutoffPerMm.x, psf.cutoffPerMm.y};
  nlohmann::json list = nlohmann::json::array();
  for (const PsfWavelength& w : psf.wavelengths)
    list.push_back({{"wavelength_nm", w.wavelengthNm},
                    {"weight", w.weight},
                    {"pupil_samples", w.pupilSamples},
                    {"rms_opd_waves", w.rmsWaves},
                    {"peak_to_valley_opd_waves", w.peakToValleyWaves},
                    {"max_opd_step_waves", w.maxStepWaves},
                    {"strehl", w.strehl}});
  j["wavelengths"] = list;
  return j;
}

}  // namespace lensrt
