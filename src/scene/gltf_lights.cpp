// Photometric to radiometric units. KHR_lights_punctual gives point and spot
// intensities in candela (lm/sr) and directional illuminance in lux (lm/m^2).
// lensrt renders radiometric quantities, so by our documented rule
//     radiometric = photometric / 683 lm/W
// i.e. intensity W/sr = candela / 683 (point, spot) and irradiance
// W/m^2 = lux / 683 (directional), each times the light's linear RGB colour.
// (A Blender lamp of P watts is exported as P * 683 / (4 pi) cd and so comes
// back as P / (4 pi) W/sr, which is what Cycles renders.) Emissive materials
// need no conversion: emissiveFactor * emissiveStrength is already the
// radiance in W/(sr m^2).
#include "scene/gltf_lights.h"

#include <algorithm>
#include <cmath>

#include "core/constants.h"

namespace lensrt::gltf {

inline constexpr double kLumensPerWatt = 683.0;

std::optional<PunctualLight> convertLight(const Context& ctx, int index, const Transform& worldFromNode) {
  const auto& lights = ctx.model.lights;
  if (index < 0 || static_cast<std::size_t>(index) >= lights.size())
    ctx.fail("KHR_lights_punctual: light " + std::to_string(index) + " does not exist");
  const tinygltf::Light& gl = lights[static_cast<std::size_t>(index)];
  PunctualLight light;
  light.name = gl.name.empty() ? "light #" + std::to_string(index) : gl.name;
  if (gl.type == "point") {
    light.type = PunctualLight::Type::Point;
  } else if (gl.type == "spot") {
    light.type = PunctualLight::Type::Spot;
  } else if (gl.type == "directional") {
    light.type = PunctualLight::Type::Directional;
  } else {
    ctx.warnings.warn("light '" + light.name + "': unknown type '" + gl.type + "', skipped");
    return std::nullopt;
  }
  if (!std::isfinite(gl.intensity) || gl.intensity < 0) {
    ctx.warnings.warn("light '" + light.name + "': intensity must be finite and >= 0, skipped");
    return std::nullopt;
  }
  Vec3d colour{1, 1, 1};
  if (gl.color.size() == 3) colour = {gl.color[0], gl.color[1], gl.color[2]};
  if (!isFinite(colour) || colour.x < 0 || colour.y < 0 || colour.z < 0) {
    ctx.warnings.warn("light '" + light.name + "': colour must be finite and >= 0, using white");
    colour = {1, 1, 1};
  }
  light.intensity = Rgb(colour * (gl.intensity / kLumensPerWatt));
  light.position = Vec3f(worldFromNode.point(Vec3d(0, 0, 0)));
  const Vec3d dir = worldFromNode.vector(Vec3d(0, 0, -1));  // lights shine down their local -Z
  if (length(dir) > 0) light.direction = Vec3f(normalize(dir));
  if (light.type == PunctualLight::Type::Spot) {
    // glTF limits: 0 <= inner < outer <= pi/2.
    const double outer = std::isfinite(gl.spot.outerConeAngle) ? gl.spot.outerConeAngle : kPi / 4;
    const double inner = std::isfinite(gl.spot.innerConeAngle) ? gl.spot.innerConeAngle : 0.0;
    light.outerConeAngle = static_cast<float>(std::clamp(outer, 1e-6, kPi / 2));
    light.innerConeAngle =
        static_cast<float>(std::clamp(inner, 0.0, static_cast<double>(light.outerConeAngle)));
  }
  light.range = std::isfinite(gl.range) && gl.range > 0 ? static_cast<float>(gl.range) : 0.0f;
  return light;
}

}  // namespace lensrt::gltf
