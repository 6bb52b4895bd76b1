// Exact (real) ray tracing through a lens prescription.
//
// Lens space, used by every optics API: millimetres, right-handed, the optical
// axis is z, +z points from the scene toward the film (the way light travels).
// The first (front) vertex is at z = 0, surface i at surfaceZ(i), the last
// (rear) vertex at rearZ(); the film is the plane z = rearZ() + filmDistance.
// The scene is at negative z. x and y are arbitrary but shared by film and
// scene: the real image on the film is inverted (a camera flips it).
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "core/vec.h"
#include "optics/coating.h"
#include "optics/glass.h"
#include "optics/paraxial.h"
#include "optics/prescription.h"
#include "optics/trace_lanes.h"

namespace lensrt {

struct LensRay {
  Vec3d origin;
  Vec3d direction;  // unit length on output; any non-zero length on input
  // The fraction of the light the surfaces transmit (Fresnel losses): the
  // input's value times every refracting surface's, when the system models
  // coatings; unchanged otherwise.
  double transmittance = 1.0;
};

class LensSystem {
 public:
  // The prescription is validated (throws InputError). With a coating the
  // traces multiply each ray's transmittance by every refracting surface's
  // Fresnel transmittance (optics/coating.h); without one, glass is lossless.
  explicit LensSystem(LensPrescription prescription, std::optional<Coating> coating = std::nullopt);

  const LensPrescription& prescription() const { return prescription_; }
  const ParaxialData& paraxial() const { return paraxial_; }
  std::optional<Coating> coating() const { return coating_; }
  int surfaceCount() const { return static_cast<int>(surfaces_.size()); }
  double surfaceZ(int i) const { return surfaces_[i].z; }
  double rearZ() const { return surfaces_.back().z; }
  double rearApertureRadius() const { return surfaces_.back().apertureRadius; }
  double frontApertureRadius() const { return surfaces_.front().apertureRadius; }
  // The same lens with every clear aperture opened as far as its surface
  // goes (a sphere to its hemisphere, a flat surface and the stop without
  // limit; an asphere keeps its own, where its sag is defined): no ray is
  // blocked but by missing a surface or total internal reflection. For
  // solving for a ray the rims may block (the chief ray of a vignetted
  // field, optics/chief_ray.h), then testing it in the real lens.
  LensSystem withOpenRims() const;

  // A ray leaving a film point toward the scene (direction.z < 0). Returns the
  // ray leaving the front surface into the scene, or nullopt when an aperture,
  // the stop, a missed surface or total internal reflection blocks it. Never
  // returns non-finite values. `path`, when given, receives every surface hit.
  std::optional<LensRay> traceFromFilm(const LensRay& ray, double wavelengthNm = kWavelengthDNm,
                                       std::vector<Vec3d>* path = nullptr) const;
  // Many rays from the film at the d line: the same as traceFromFilm on each,
  // bit for bit, but several at a time (kTraceLanes), whose independent
  // square-root chains the CPU overlaps: about twice the throughput.
  void traceFromFilm(std::span<const LensRay> rays, std::span<std::optional<LensRay>> out) const;
  // The same with each ray at its own wavelength (dispersion): bit for bit
  // traceFromFilm(rays[i], wavelengthsNm[i]).
  void traceFromFilm(std::span<const LensRay> rays, std::span<const double> wavelengthsNm,
                     std::span<std::optional<LensRay>> out) const;
  static constexpr std::size_t kTraceLanes = trace_lanes::kLanes;

  // A ray from the scene toward the lens (direction.z > 0); returns the ray
  // leaving the rear surface toward the film.
  std::optional<LensRay> traceFromScene(const LensRay& ray, double wavelengthNm = kWavelengthDNm,
                                        std::vector<Vec3d>* path = nullptr) const;

  // A trace from the scene paused after surface `surface`: traceFromScene's
  // arithmetic up to there (its path's entries, the same bits), to resume
  // later. Coatings are left out: they change the transmittance alone.
  struct PausedTrace {
    Vec3d origin, direction;  // at the last surface crossed, and on from it
    int crossed = 0;          // surfaces crossed
  };
  std::optional<PausedTrace> traceFromSceneTo(const LensRay& ray, int surface,
                                              double wavelengthNm = kWavelengthDNm,
                                              std::vector<Vec3d>* path = nullptr) const;
  // The rest of the trace, by this lens (which may differ from the paused
  // trace's in its rims alone, as withOpenRims does): with the rims held
  // (rimsHold), traceFromScene's ray, bit for bit; transmittance 1.
  std::optional<LensRay> resumeFromScene(const PausedTrace& paused,
                                         double wavelengthNm = kWavelengthDNm) const;
  // Whether this lens's rims hold the hits, on its first hits.size()
  // surfaces from the scene, of a trace by the same lens with other rims.
  bool rimsHold(std::span<const Vec3d> hits) const;
  // Where a ray from the film meets surface `surface`: traceFromFilm's
  // arithmetic up to there (its path's entry, the same bits); nullopt when
  // the ray is blocked on the way or at that surface.
  std::optional<Vec3d> hitFromFilm(const LensRay& ray, int surface,
                                   double wavelengthNm = kWavelengthDNm) const;

  // A ghost (optics/ghosts.h): a ray from the scene that reflects at surface
  // `first`, back toward the scene, then at `second` (second < first), and
  // leaves the rear surface toward the film; every other surface refracts
  // it, and apertures block it as in the other traces. Its transmittance is
  // the input's times the Fresnel reflectance of both reflections (with the
  // lens's coating, bare glass without one) and, when the lens models
  // coatings, the refractions' transmittance. nullopt when blocked or when
  // the surfaces are out of range or not second < first.
  std::optional<LensRay> traceGhostFromScene(const LensRay& ray, int first, int second,
                                             double wavelengthNm = kWavelengthDNm,
                                             std::vector<Vec3d>* path = nullptr) const;

  // Stray light (lens flare). At every surface where the index changes the
  // ray reflects with the Fresnel reflectance R (the lens's coating, bare
  // glass without one) and refracts otherwise, chosen by `random` (uniform in
  // [0, 1)) so that the weight stays exact: up to `maxReflections`
  // reflections, after which it refracts with weight 1 - R (the R dropped
  // is `truncated`). The stop (times `stop`, when set: blades or a mask) and
  // the rims block as in every trace; a rim (not the stop) scatters the ray
  // diffusely back with probability `barrelReflectance` (the barrel: see
  // flareTrace), which counts as a reflection.
  struct FlareOptions {
    int maxReflections = 2;
    double barrelReflectance = 0.0;  // in [0, 1)
    // The stop's transmittance at a point (x, y) of its plane (lens space,
    // mm), in [0, 1], at every crossing; empty: the round stop alone.
    std::function<double(double, double)> stop;
    // More than 1: a glass surface reflects with probability q = min(0.5,
    // reflectionBoost x R) (R itself where that is less), the weight times
    // R / q when it does and (1 - R) / (1 - q) when it refracts, so that
    // more paths make ghosts for the same expected weights (the light pass's
    // paths, most of which would otherwise refract straight through: their
    // weights no longer add up path by path, only on average).
    double reflectionBoost = 1.0;
    // A ghost to make rather than a choice at every surface: the path
    // reflects at surface ghost->first (0-based) on its way toward the film
    // and at ghost->second (< first) on its way back, and refracts at every
    // other glass surface, its weight times R at those two and 1 - R
    // elsewhere: the expected weight of the paths that take that ghost.
    // Monte Carlo over the ghosts (the light pass picks one per path), for
    // traces from the scene without the barrel; maxReflections and
    // reflectionBoost do not apply.
    std::optional<std::pair<int, int>> ghost = std::nullopt;
  };
  struct FlareTrace {
    // Where the ray ends: leaving the front surface toward the scene, leaving
    // the rear surface toward the film (the film absorbs it), or absorbed.
    enum class End { Scene, Film, Blocked };
    End end = End::Blocked;
    // Scene or Film: the ray leaving the lens, its transmittance the weight.
    // Blocked: where it was absorbed.
    LensRay ray;
    int reflections = 0;  // glass reflections and barrel scatters
    struct Bounce {
      int surface = -1;
      bool barrel = false;  // a scatter at the surface's rim
    };
    static constexpr int kRecorded = 4;
    std::array<Bounce, kRecorded> bounces{};  // the first kRecorded, in order
    // The weight lost on the way, so that the input's weight equals the
    // output's plus these (light is moved, never created): absorbed by the
    // stop, a mask or the barrel, and dropped by the reflection limit.
    double absorbed = 0.0;
    double truncated = 0.0;
  };
  // From the film (direction.z < 0): End::Scene after even reflections,
  // End::Film after odd ones.
  template <class Random>
  FlareTrace traceFromFilmWithFlare(const LensRay& ray, const FlareOptions& options, Random&& random,
                                    double wavelengthNm = kWavelengthDNm,
                                    std::vector<Vec3d>* path = nullptr) const {
    return flareTrace(
        ray, true, options, [&random] { return double(random()); }, wavelengthNm, path);
  }
  template <class Random>
  FlareTrace traceFromFilmWithFlare(const LensRay& ray, int maxReflections, Random&& random,
                                    double wavelengthNm = kWavelengthDNm,
                                    std::vector<Vec3d>* path = nullptr) const {
    return traceFromFilmWithFlare(ray, FlareOptions{maxReflections, 0.0, {}}, random, wavelengthNm, path);
  }
  // From the scene (direction.z > 0), the light's way (particle tracing):
  // End::Film after even reflections, End::Scene (back out of the front)
  // after odd ones.
  template <class Random>
  FlareTrace traceFromSceneWithFlare(const LensRay& ray, const FlareOptions& options, Random&& random,
                                     double wavelengthNm = kWavelengthDNm,
                                     std::vector<Vec3d>* path = nullptr) const {
    return flareTrace(
        ray, false, options, [&random] { return double(random()); }, wavelengthNm, path);
  }

 private:
  // The one stochastic loop behind both flare traces; fromFilm: the ray
  // starts at the rear surface going toward the scene, else at the front.
  FlareTrace flareTrace(const LensRay& ray, bool fromFilm, const FlareOptions& options,
                        const std::function<double()>& random, double wavelengthNm,
                        std::vector<Vec3d>* path) const;
  // Everything about a surface that does not depend on the ray, laid out for
  // the trace loop.
  struct TraceSurface {
    double z = 0.0;
    double radius = 0.0;  // 0 = flat
    double invRadius = 0.0;
    double absInvRadius = 0.0;
    double invRadius2 = 0.0;
    double apertureRadius = 0.0;
    double apertureRadius2 = 0.0;
    // n_d before (scene side) / after (film side), and the ratios refract()
    // takes going each way: precomputed so the d line (no dispersion) costs
    // no division. `refracts` is false for the stop and between equal media.
    double etaFromFilm = 1.0;   // ndAfter / ndBefore
    double etaFromScene = 1.0;  // ndBefore / ndAfter
    bool refracts = false;
    bool isStop = false;
    // Aspheric surfaces only (asphereStep, optics/asphere.h); shared and
    // immutable, so spherical surfaces stay small in the trace loop's cache.
    std::shared_ptr<const AsphereProfile> asphere;
    double ndAfter = 1.0;  // index after the surface (toward the film) at the d line
    Dispersion after;
    double rimZ = 0.0;  // the plane of the rim around the clear aperture (the barrel, flareTrace)
  };
  // The unit normal of surface `s` at `hit` (lens space), facing against `d`.
  static Vec3d facingNormal(const TraceSurface& s, const Vec3d& hit, const Vec3d& d);
  template <bool kFromFilm>
  static bool asphereStep(const TraceSurface& s, double eta, Vec3d& o, Vec3d& d, std::vector<Vec3d>* path);
  template <bool kFromFilm>
  static bool step(const TraceSurface& s, double eta, Vec3d& o, Vec3d& d, std::vector<Vec3d>* path);
  // The batched trace on CPUs with vector units (optics/trace_lanes.h).
  // Empty wavelengthsNm: every ray at the d line.
  void traceFromFilmVectorized(std::span<const LensRay> rays, std::span<const double> wavelengthsNm,
                               std::span<std::optional<LensRay>> out) const;
  template <bool kFromFilm, bool kCoated>
  bool cross(Vec3d& o, Vec3d& d, double& transmittance, int first, int last, double wavelengthNm,
             std::vector<Vec3d>* path) const;
  template <bool kFromFilm, bool kCoated>
  std::optional<LensRay> trace(const LensRay& ray, double wavelengthNm, std::vector<Vec3d>* path) const;

  LensPrescription prescription_;
  ParaxialData paraxial_;
  std::vector<TraceSurface> surfaces_;
  // The same surfaces as the batched trace takes them, built once here
  // rather than on every batch of rays.
  std::vector<trace_lanes::Sphere> spheres_;
  bool hasAspheres_ = false;
  std::optional<Coating> coating_;
};

// Refract unit direction d at a surface with unit normal n facing against d
// (dot(n, d) < 0), from index n1 into n2. False on total internal reflection.
bool refract(const Vec3d& d, const Vec3d& n, double n1, double n2, Vec3d& out);

}  // namespace lensrt
