// `lensrt lens`: lens tools. `info` prints every first-order quantity of a
// prescription; further sub-subcommands register through lens_subcommands.h.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "api/lens_info.h"
#include "api/lens_loading.h"
#include "api/lens_view.h"
#include "app/lens_subcommands.h"
#include "app/option_checks.h"
#include "core/constants.h"
#include "core/warnings.h"
#include "optics/axial_transmittance.h"
#include "optics/chromatic.h"
#include "optics/exit_pupil.h"
#include "optics/focus.h"
#include "optics/lens_readers.h"
#include "optics/lens_system.h"
#include "optics/paraxial.h"

namespace lensrt {
namespace {

struct InfoOptions {
  std::string lens;
  std::string sensor = "36x24";
  std::optional<double> fNumber;
  std::string focus = "inf";
  std::optional<double> circleOfConfusionMm;
  std::string coatings = "none";
  bool json = false;
};

std::string metresText(double mm) {
  return std::isfinite(mm) ? fmt::format("{:.4g} m", mm / 1000.0) : "infinity";
}

int printInfo(const InfoOptions& o, const LensPrescription& design, const Vec2d& sensor, double focusM,
              Warnings& warnings, const std::vector<std::string>& warningList);

int runInfo(const InfoOptions& o) {
  const Vec2d sensor = parseSensorSize(o.sensor);
  const double focusM = parseFocusMetres(o.focus);
  checkFNumber(o.fNumber);
  if (o.circleOfConfusionMm && !(*o.circleOfConfusionMm > 0))
    throw CLI::ValidationError("--coc", "must be positive");

  std::vector<std::string> warningList;
  Warnings warnings([&](const std::string& w) {
    warningList.push_back(w);
    fmt::print(stderr, "lensrt: warning: {}\n", w);
  });
  const UserLens user = loadUserLens(o.lens, LENSRT_LENS_DIR);
  requireRealImage(user);
  return withLensErrors(
      user, [&] { return printInfo(o, user.prescription, sensor, focusM, warnings, warningList); });
}

int printInfo(const InfoOptions& o, const LensPrescription& design, const Vec2d& sensor, double focusM,
              Warnings& warnings, const std::vector<std::string>& warningList) {
  LensInfoSettings settings;
  settings.sensorWidthMm = sensor.x;
  settings.sensorHeightMm = sensor.y;
  settings.fNumber = o.fNumber;
  settings.focusMetres = focusM;
  settings.circleOfConfusionMm = o.circleOfConfusionMm;
  settings.coating = parseCoating(o.coatings).value_or(Coating::None);
  const LensInfo info = lensInfo(design, settings, warnings);
  if (o.json) {
    std::cout << lensInfoJson(info, warningList).dump(2) << "\n";
    return 0;
  }
  const LensPrescription& rx = info.lens.prescription();
  const ParaxialData& p = info.lens.paraxial();
  const Conjugate& conj = info.conjugate;
  const FieldOfView& fov = info.fov;
  const double focusMm = focusM * 1000.0;
  fmt::print("{}  ({})\n", rx.name, rx.file);
  if (!rx.description.empty()) fmt::print("  {}\n", rx.description);
  if (!rx.source.empty()) fmt::print("  source: {}\n", rx.source);
  fmt::print("Positions are mm along the axis from the first vertex, + toward the film.\n");
  const auto aspheric =
      std::count_if(rx.surfaces.begin(), rx.surfaces.end(), [](const Surface& s) { return s.isAspheric(); });
  fmt::print("  surfaces              {} (stop: surface {}{}), length {:.3f} mm\n", rx.surfaces.size(),
             p.stopIndex + 1, aspheric > 0 ? fmt::format(", {} aspheric", aspheric) : "", p.lastVertexZ);
  fmt::print("  focal length (EFL)    {:.3f} mm{}\n", p.efl,
             rx.nominalFocalLengthMm > 0 ? fmt::format("  (nominal {:g} mm)", rx.nominalFocalLengthMm) : "");
  fmt::print("  back focal length     {:.3f} mm    front focal length {:.3f} mm\n", p.bfl, p.ffl);
  fmt::print("  focal points F, F'    {:.3f}, {:.3f}\n", p.frontFocalZ, p.rearFocalZ);
  fmt::print("  principal planes H,H' {:.3f}, {:.3f}  (nodal points coincide: air both sides)\n",
             p.frontPrincipalZ, p.rearPrincipalZ);
  fmt::print("  aperture stop         at {:.3f}, diameter {:.3f} mm\n", p.stopZ, p.stopDiameter);
  fmt::print("  entrance pupil        at {:.3f}, diameter {:.3f} mm\n", p.entrancePupilZ,
             p.entrancePupilDiameter);
  fmt::print("  exit pupil            at {:.3f}, diameter {:.3f} mm\n", p.exitPupilZ, p.exitPupilDiameter);
  fmt::print("  f-number              f/{:.3g}  (widest f/{:.3g})\n", p.fNumber, info.widestFNumber);
  fmt::print("Sensor {:g} x {:g} mm, focused at {} from the entrance pupil:\n", sensor.x, sensor.y,
             metresText(focusMm));
  fmt::print("  film distance         {:.4f} mm behind the last vertex (paraxial estimate {:.4f})\n",
             info.filmDistanceMm, conj.filmDistance);
  fmt::print("  magnification         {:.5g}   image distance from H' {:.3f} mm\n", conj.magnification,
             conj.imageDistance);
  fmt::print("  field of view         {:.2f} deg diagonal, {:.2f} horizontal, {:.2f} vertical\n",
             fov.diagonalDeg, fov.horizontalDeg, fov.verticalDeg);
  fmt::print("  closest focus         {}\n", metresText(info.closestFocusMm));
  fmt::print("  hyperfocal distance   {}  (circle of confusion {:.4f} mm)\n", metresText(info.hyperfocalMm),
             info.circleOfConfusionMm);
  fmt::print("  depth of field        {} to {}\n", metresText(info.nearMm), metresText(info.farMm));
  fmt::print("  exit pupil efficiency {:.1f}% of rays sampled from the pupil bounds pass\n",
             100.0 * info.exitPupilEfficiency);
  if (hasDispersion(rx))
    fmt::print(
        "  chromatic aberration  axial {:.4f} mm (BFL at C minus F), lateral {} (F minus C at {:.2f} mm)\n",
        info.axialColorMm, info.lateralColor ? fmt::format("{:.2f} um", info.lateralColor->um()) : "n/a",
        info.halfDiagonalMm());
  else
    fmt::print("  chromatic aberration  none (no Abbe numbers or Sellmeier coefficients)\n");
  fmt::print("  axial transmittance   {:.1f}% of an axial bundle at the d line (--coatings {})\n",
             100.0 * info.axialTransmittance, coatingName(settings.coating));
  return 0;
}

}  // namespace

CommandAction addLensInfoCommand(CLI::App& lensApp, const CommandContext&) {
  auto options = std::make_shared<InfoOptions>();
  CLI::App* info =
      lensApp.add_subcommand("info", "Print a lens's focal lengths, cardinal points, pupils, FOV and DoF");
  info->add_option("lens", options->lens,
                   "Lens file (.lens, .json, .dat, .zmx) or library name, e.g. dgauss-50mm")
      ->required();
  info->add_option("--sensor", options->sensor, "Sensor size WIDTHxHEIGHT in mm")->capture_default_str();
  info->add_option("--fstop", options->fNumber, "Stop down to this f-number (default: widest)")
      ->check(aNumber("an f-number"));
  info->add_option("--focus", options->focus, "Focus distance in metres from the entrance pupil, or 'inf'")
      ->capture_default_str();
  info->add_option("--coc", options->circleOfConfusionMm,
                   "Circle of confusion in mm (default: diagonal / 1500)")
      ->check(aNumber("mm"));
  addLensCoatingsOption(*info, options->coatings, "for the axial transmittance");
  info->add_flag("--json", options->json, "Print JSON (distances in mm unless named _m)");
  return [options] { return runInfo(*options); };
}

void addLensCoatingsOption(CLI::App& cmd, std::string& coatings, const std::string& what) {
  cmd.add_option("--coatings", coatings,
                 fmt::format("Surface coatings {}: none (uncoated), single (quarter-wave MgF2 at 550 nm) or "
                             "multi (0.5% per surface)",
                             what))
      ->capture_default_str()
      ->check(CLI::IsMember({"none", "single", "multi"}));
}

CommandAction addLensCommand(CLI::App& app, const CommandContext& context) {
  CLI::App* lensApp =
      app.add_subcommand("lens", "Lens tools: info, diagram, plot, ghosts, calibrate, psf and mtf of a prescription");
  lensApp->require_subcommand(1);
  // One entry per `lens` sub-subcommand (diagram and plot join here).
  std::vector<std::pair<CLI::App*, CommandAction>> subs;
  const auto add = [&](auto registerFn) {
    const std::size_t before = lensApp->get_subcommands({}).size();
    CommandAction action = registerFn(*lensApp, context);
    subs.emplace_back(lensApp->get_subcommands({}).at(before), std::move(action));
  };
  add(addLensInfoCommand);
  add(addLensDiagramCommand);
  add(addLensPlotCommand);
  add(addLensGhostsCommand);
  add(addLensCalibrateCommand);
  add(addLensPsfCommand);
  add(addLensMtfCommand);
  return [subs] {
    for (const auto& [sub, action] : subs)
      if (sub->parsed()) return action();
    return 2;
  };
}

}  // namespace lensrt
