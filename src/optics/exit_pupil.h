// Exit pupil bounds: where on the rear-vertex plane (z = lens.rearZ()) rays
// from a film point can aim and still pass the whole lens.
//
// The lens is rotationally symmetric, so bounds are precomputed for film
// radii 0..maxFilmRadius in `intervals` steps: for each interval a convex
// polygon (in the frame where the film point lies on +x) containing every
// passing point for any film radius in that interval, conservatively dilated.
// Sampling a film point rotates its interval's polygon to the point's azimuth.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "core/vec.h"
#include "optics/lens_system.h"

namespace lensrt {

// A camera turns a sample into a ray from film point f toward `point`; its
// pdf per solid angle is pdf * |point - f|^2 / cos(theta), theta the angle to
// the axis (the plane is perpendicular to it).
struct PupilSample {
  Vec3d point;       // on the plane z = planeZ(), lens space, mm
  double pdf = 0.0;  // per unit area (1/mm^2) on that plane
};

// Film points off the plane z = filmZ (a tilted film): their z lies in
// [filmZ + min, filmZ + max] (mm).
struct FilmDepthRange {
  double min = 0.0, max = 0.0;
};

class ExitPupilBounds {
 public:
  // filmZ: the film plane (lens.rearZ() + film distance). maxFilmRadius: the
  // largest film radius to support, e.g. half the sensor diagonal. With a
  // depth range, each interval's polygon holds the nodes' boundaries at
  // depths across it too (every 1 mm or closer, ends included): bounds for
  // any film point in that slab, as the radius nodes cover the radii between
  // them. Sampling, pdf and polygon() then take only the point's x and y.
  ExitPupilBounds(const LensSystem& lens, double filmZ, double maxFilmRadius, int intervals = 64,
                  FilmDepthRange depth = {});

  double planeZ() const { return planeZ_; }
  double filmZ() const { return filmZ_; }
  double maxFilmRadius() const { return maxFilmRadius_; }

  // A point on the pupil plane for film point (x, y) (lens space) from a
  // uniform sample u in [0,1)^2, with its pdf per unit area. nullopt when no
  // ray from that film point can pass (outside the image circle) or the film
  // point is beyond maxFilmRadius.
  std::optional<PupilSample> sample(Vec2d filmPoint, Vec2d u) const;
  // sample() for many film points, bit for bit; a pdf of 0 where it gives
  // nullopt. With AVX2, the square roots and divisions four at a time.
  void sample(std::span<const Vec2d> filmPoints, std::span<const Vec2d> u, std::span<PupilSample> out) const;
  // The pdf `sample` would give for that pupil-plane point (0 outside bounds).
  double pdf(Vec2d filmPoint, Vec2d pupilPoint) const;
  // The bounding polygon for a film point, rotated to its azimuth (lens-space
  // x, y on the pupil plane; counter-clockwise; empty when nothing passes).
  std::vector<Vec2d> polygon(Vec2d filmPoint) const;
  // Area of the bounds (mm^2) for a film radius; 0 when nothing passes.
  double area(double filmRadius) const;

 private:
  // A fan triangle (vertices[0], b, c) as sample() takes it: its start in
  // the cdf and its area as the division sees it, so a sample reads one
  // small record instead of three arrays.
  struct Triangle {
    double lo = 0.0;    // cdf before it
    double span = 0.0;  // std::max(cdf after - lo, 1e-300)
    Vec2d b, c;
  };
  struct Polygon {
    std::vector<Vec2d> vertices;  // counter-clockwise, convex
    std::vector<double> cdf;      // fan triangles from vertices[0], cumulative area
    double area = 0.0;
    double invArea = 0.0;  // 1.0 / area: the pdf
    std::vector<Triangle> triangles;
    // The fan triangle upper_bound would pick, for targets (u.x * area) in
    // equal steps: a first guess that sample() corrects by exact comparisons
    // (usually none), instead of a binary search's unpredictable branches.
    std::vector<std::uint16_t> firstTriangle;
    double bucketScale = 0.0;  // buckets per unit of target
  };
  int intervalOf(double filmRadius) const;
  // intervalOf for a radius whose interval coordinate filmRadius /
  // maxFilmRadius * intervals is already computed (the batched sample()).
  int intervalAt(double filmRadius, double coordinate) const;
  // The fan triangle (index into triangles) that u.x * area selects.
  static std::size_t triangleOf(const Polygon& poly, double target);

  double planeZ_ = 0.0;
  double filmZ_ = 0.0;
  double maxFilmRadius_ = 0.0;
  std::vector<Polygon> polygons_;  // one per interval
};

}  // namespace lensrt

namespace lensrt {

struct PupilEfficiency {
  long sampled = 0;  // film samples that got a pupil sample
  long passed = 0;   // of those, rays that passed the whole lens
  long empty = 0;    // film samples with no bounds (outside the image circle)
  double efficiency() const { return sampled ? static_cast<double>(passed) / sampled : 0.0; }
};
// Fraction of rays sampled from the bounds that pass the lens, for film points
// uniform over a centred sensor (mm). Deterministic for a given seed.
PupilEfficiency measurePupilEfficiency(const LensSystem& lens, const ExitPupilBounds& bounds,
                                       double sensorWidthMm, double sensorHeightMm, long samples,
                                       unsigned long long seed = 1);

}  // namespace lensrt
