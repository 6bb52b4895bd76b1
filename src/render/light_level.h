// How strongly a scene's own emitters light what the camera sees: the test
// that decides whether a scene whose lights are token ones (glowing labels, a
// car body whose emissive texture is black but for its lamps) is lit by the
// default sky as well, as glTF viewers light such scenes.
#pragma once

#include <optional>
#include <span>

#include "core/bounds.h"
#include "core/ray.h"
#include "render/material_eval.h"
#include "scene/render_scene.h"

namespace lensrt {

// The median, over the probe rays that see a surface, of the irradiance (W/m^2
// of luminance) that the scene's punctual lights and emissive triangles give
// there, facing the ray, ignoring shadows (a lamp inside its shade still
// counts). A probe goes on through transmitting surfaces, as camera paths
// do: a lamp behind a window is seen. The window's transmittance is not
// applied: what the camera sees through it is dimmed alike under the scene's
// light and under the sky, so the comparison below does not depend on it.
// A surface that glows itself adds pi times its radiance, the irradiance
// that would make a white diffuse surface as bright. An emissive triangle
// counts as a point source at its centroid with the radiance of its factor
// times its emissive texture (four sample points), and gives at most pi L,
// what a surface touching it would get.
// nullopt when no ray sees a surface.
std::optional<double> medianEmitterIrradiance(const RenderScene& scene, const MaterialTable& materials,
                                              std::span<const Ray> probes);

// Below this fraction of the default sky's irradiance (pi L_sky on any
// surface) at what the camera sees, a scene's own light counts as too weak to
// light it: 1% when it has punctual lights (glTF's way of lighting a scene),
// 5% when it has emissive surfaces only. glTF viewers let emissive surfaces
// glow but light nothing, so such files (labels, a car's lamps) are made to
// be seen under the viewer's environment; a path tracer's lamp is many times
// brighter than the sky (measured, README: labels 2.3%, the Cornell box 9%).
inline constexpr double kWeakLightFraction = 0.01;
inline constexpr double kWeakGlowFraction = 0.05;

}  // namespace lensrt
