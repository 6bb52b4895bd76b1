// Fresnel losses at the refracting surfaces of a lens, bare or coated.
//
//  none    uncoated glass: the unpolarised Fresnel transmittance
//          1 - (R_s + R_p) / 2 at every refracting surface.
//  single  a quarter-wave layer of MgF2 (n = 1.38, physical thickness
//          550 nm / (4 * 1.38)) on every glass-air surface: the exact
//          single-layer thin-film reflectance for s and p at the ray's angle
//          and wavelength (at normal incidence and 550 nm it is
//          ((n0 ns - n1^2) / (n0 ns + n1^2))^2).
//  multi   an ideal broadband multilayer: 0.5% reflectance at every glass-air
//          surface, whatever the angle and wavelength.
// Cemented (glass-glass) interfaces are never coated: bare Fresnel there.
// Absorption in the glass is not modelled.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace lensrt {

enum class Coating { None, Single, Multi };

inline constexpr double kMgF2Index = 1.38;
inline constexpr double kSingleLayerDesignNm = 550.0;
inline constexpr double kMultiLayerReflectance = 0.005;

// "none", "single", "multi"; nullopt for anything else.
std::optional<Coating> parseCoating(std::string_view name);
std::string coatingName(Coating coating);

// Unpolarised transmittance of one surface between media of indices n1 and n2
// (either order), for a ray at cos1 to the normal in n1 and cos2 in n2 (both
// in [0, 1], related by Snell's law).
double surfaceTransmittance(Coating coating, double n1, double n2, double cos1, double cos2,
                            double wavelengthNm);

}  // namespace lensrt
