#include "api/lens_info.h"

#include <algorithm>
#include <cmath>

#include "core/constants.h"
#include "optics/axial_transmittance.h"
#include "optics/exit_pupil.h"
#include "optics/focus.h"
#include "optics/lens_readers.h"

namespace lensrt {
namespace {

// JSON has no infinity: distances at infinity are null.
nlohmann::json finiteOrNull(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

}  // namespace

double LensInfo::halfDiagonalMm() const {
  return std::hypot(settings.sensorWidthMm, settings.sensorHeightMm) / 2.0;
}

LensInfo lensInfo(const LensPrescription& design, const LensInfoSettings& s, Warnings& warnings) {
  LensInfo info(LensSystem(s.fNumber ? stopDown(design, *s.fNumber, warnings) : design));
  info.widestFNumber = computeParaxial(design).fNumber;
  info.settings = s;
  const LensSystem& lens = info.lens;
  const ParaxialData& p = lens.paraxial();

  const double focusMm = s.focusMetres * 1000.0;
  info.filmDistanceMm = focusFilmDistance(lens, focusMm);
  info.conjugate = paraxialConjugate(p, focusMm);
  const double halfDiagonal = info.halfDiagonalMm();
  info.fov = fieldOfView(info.conjugate.imageDistance, s.sensorWidthMm, s.sensorHeightMm);
  info.closestFocusMm = closestFocusDistanceMm(lens);
  // Circle of confusion: the common diagonal / 1500 rule (0.029 mm on full frame).
  info.circleOfConfusionMm = s.circleOfConfusionMm.value_or(2.0 * halfDiagonal / 1500.0);
  const double coc = info.circleOfConfusionMm;
  // DoF formulas measure from the front principal plane; report from the entrance pupil.
  const double hToPupil = p.entrancePupilZ - p.frontPrincipalZ;
  info.hyperfocalMm = hyperfocalDistance(p.efl, p.fNumber, coc) + hToPupil;
  const DepthOfField dof = std::isinf(focusMm)
                               ? DepthOfField{info.hyperfocalMm, kInfinity}
                               : depthOfField(p.efl, p.fNumber, coc, info.conjugate.objectDistanceFromH);
  // Focused at infinity the near limit is f^2 / (N c) (the seed's D_N as s -> infinity).
  info.nearMm = std::isinf(focusMm) ? p.efl * p.efl / (p.fNumber * coc) + hToPupil : dof.nearLimit + hToPupil;
  info.farMm = dof.farLimit + hToPupil;

  const ExitPupilBounds bounds(lens, lens.rearZ() + info.filmDistanceMm, halfDiagonal);
  info.exitPupilEfficiency =
      measurePupilEfficiency(lens, bounds, s.sensorWidthMm, s.sensorHeightMm, 20000).efficiency();
  // Chromatic aberration (0 without Abbe numbers): lateral at the half diagonal.
  info.axialColorMm = axialColorMm(lens.prescription());
  info.lateralColor = lateralColor(lens, halfDiagonal);
  info.axialTransmittance = axialTransmittance(LensSystem(lens.prescription(), s.coating));
  return info;
}

nlohmann::json lensInfoJson(const LensInfo& info, const std::vector<std::string>& warnings) {
  const LensPrescription& rx = info.lens.prescription();
  const ParaxialData& p = info.lens.paraxial();
  const LensInfoSettings& s = info.settings;
  nlohmann::json j;
  j["name"] = rx.name;
  j["description"] = rx.description;
  j["source"] = rx.source;
  j["file"] = rx.file;
  j["nominal_focal_length_mm"] =
      finiteOrNull(rx.nominalFocalLengthMm > 0 ? rx.nominalFocalLengthMm : kInfinity);
  j["surfaces"] = rx.surfaces.size();
  j["aspheric_surfaces"] = std::count_if(rx.surfaces.begin(), rx.surfaces.end(),
                                         [](const Surface& surface) { return surface.isAspheric(); });
  j["length_mm"] = p.lastVertexZ;
  j["efl_mm"] = p.efl;
  j["bfl_mm"] = p.bfl;
  j["ffl_mm"] = p.ffl;
  j["front_focal_point_mm"] = p.frontFocalZ;
  j["rear_focal_point_mm"] = p.rearFocalZ;
  j["front_principal_plane_mm"] = p.frontPrincipalZ;
  j["rear_principal_plane_mm"] = p.rearPrincipalZ;
  j["front_nodal_point_mm"] = p.frontPrincipalZ;
  j["rear_nodal_point_mm"] = p.rearPrincipalZ;
  j["aperture_stop"] = {
      {"surface", p.stopIndex + 1}, {"position_mm", p.stopZ}, {"diameter_mm", p.stopDiameter}};
  j["entrance_pupil_pos_mm"] = p.entrancePupilZ;
  j["entrance_pupil_diameter_mm"] = p.entrancePupilDiameter;
  j["exit_pupil_pos_mm"] = p.exitPupilZ;
  j["exit_pupil_diameter_mm"] = p.exitPupilDiameter;
  j["f_number"] = p.fNumber;
  j["widest_f_number"] = info.widestFNumber;
  j["sensor_mm"] = {{"width", s.sensorWidthMm}, {"height", s.sensorHeightMm}};
  j["fov_deg"] = {{"diagonal", info.fov.diagonalDeg},
                  {"horizontal", info.fov.horizontalDeg},
                  {"vertical", info.fov.verticalDeg}};
  j["focus_distance_m"] = finiteOrNull(s.focusMetres);
  j["film_distance_mm"] = info.filmDistanceMm;
  j["paraxial_film_distance_mm"] = info.conjugate.filmDistance;
  j["image_distance_mm"] = info.conjugate.imageDistance;
  j["magnification"] = info.conjugate.magnification;
  j["closest_focus_m"] = info.closestFocusMm / 1000.0;
  j["circle_of_confusion_mm"] = info.circleOfConfusionMm;
  j["hyperfocal_distance_m"] = info.hyperfocalMm / 1000.0;
  j["depth_of_field_m"] = {{"near", finiteOrNull(info.nearMm / 1000.0)},
                           {"far", finiteOrNull(info.farMm / 1000.0)}};
  j["exit_pupil_efficiency"] = info.exitPupilEfficiency;
  j["dispersion_data"] = hasDispersion(rx);
  j["axial_color_mm"] = info.axialColorMm;
  j["lateral_color_um"] =
      info.lateralColor ? nlohmann::json(info.lateralColor->um()) : nlohmann::json(nullptr);
  j["coatings"] = coatingName(s.coating);
  j["axial_transmittance"] = info.axialTransmittance;
  j["warnings"] = warnings;
  return j;
}

}  // namespace lensrt
