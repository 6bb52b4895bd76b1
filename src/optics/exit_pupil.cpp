#include "optics/exit_pupil.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <thread>

#include "core/constants.h"
#include "optics/avx_doubles.h"
#include "optics/trace_lanes.h"

namespace lensrt {
namespace {

double cross2(const Vec2d& o, const Vec2d& a, const Vec2d& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// The fan triangle whose cumulative area first exceeds `target`, else the
// last: the search the bucket table stands in for.
std::size_t searchFanTriangle(const std::vector<double>& cdf, double target) {
  return static_cast<std::size_t>(std::upper_bound(cdf.begin() + 1, cdf.end() - 1, target) - cdf.begin() - 1);
}

// Andrew's monotone chain; counter-clockwise, no collinear points.
std::vector<Vec2d> convexHull(std::vector<Vec2d> pts) {
  std::sort(pts.begin(), pts.end(),
            [](const Vec2d& a, const Vec2d& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  if (pts.size() < 3) return pts;
  std::vector<Vec2d> hull(2 * pts.size());
  std::size_t k = 0;
  for (const Vec2d& p : pts) {
    while (k >= 2 && cross2(hull[k - 2], hull[k - 1], p) <= 0) --k;
    hull[k++] = p;
  }
  for (std::size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross2(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  hull.resize(k - 1);
  return hull;
}

// For a convex region, the boundary arc between consecutive boundary samples
// B and C lies inside the triangle of the chord BC and the extensions of the
// neighbouring chords AB and DC: adding each triangle's apex makes the hull
// of the samples contain the whole region, corners included.
std::vector<Vec2d> withApexes(const std::vector<Vec2d>& ring) {
  const std::size_t n = ring.size();
  std::vector<Vec2d> out = ring;
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2d& a = ring[(k + n - 1) % n];
    const Vec2d& b = ring[k];
    const Vec2d& c = ring[(k + 1) % n];
    const Vec2d& d = ring[(k + 2) % n];
    const Vec2d u = b - a, v = c - d, w = c - b;
    const double chord = std::hypot(w.x, w.y);
    // Solve b + u s = c + v t.
    const double den = u.x * v.y - u.y * v.x;
    double s = den != 0.0 ? (w.x * v.y - w.y * v.x) / den : -1.0;
    const double uLen = std::hypot(u.x, u.y);
    // Nearly parallel neighbours (a straight edge) put the apex far away or
    // behind: cap it at one chord length, which no smooth boundary reaches.
    if (!(s >= 0.0) || s * uLen > chord) s = uLen > 0 ? chord / uLen : 0.0;
    out.push_back(b + u * s);
  }
  return out;
}

// Traces for one film radius: the boundary of the passing region on the
// pupil plane, as points just OUTSIDE it along rays from an interior point.
class NodeSolver {
 public:
  NodeSolver(const LensSystem& lens, double planeZ, double filmZ)
      : lens_(lens), planeZ_(planeZ), filmZ_(filmZ) {}

  std::vector<Vec2d> boundary(double filmRadius) const {
    // Half-size of a square on the plane that holds every passing point: the
    // line from the film point through the rear aperture rim, extended.
    const Surface& rear = lens_.prescription().surfaces.back();
    const double a = rear.apertureDiameter / 2.0;
    const double sagRim = rear.maxAbsSag();
    const double D = filmZ_ - planeZ_;
    const double dRim = std::max(D - sagRim, 1e-3 * D);
    const double extent = 1.05 * (filmRadius + (a + filmRadius) * D / dRim) + 1e-3;

    constexpr int kGrid = 16;
    std::vector<Vec2d> inside;
    for (int j = 0; j < kGrid; ++j)
      for (int i = 0; i < kGrid; ++i) {
        const Vec2d q{-extent + 2 * extent * (i + 0.5) / kGrid, -extent + 2 * extent * (j + 0.5) / kGrid};
        if (passes(filmRadius, q)) inside.push_back(q);
      }
    // A finer grid around the paraxial chief ray (aimed at the exit pupil's
    // centre) finds small regions the coarse grid steps over: a stopped-down
    // lens, or the edge of the image circle.
    const ParaxialData& p = lens_.paraxial();
    const double toPupil = filmZ_ - p.exitPupilZ;
    if (toPupil > 1e-6 * D) {
      const double scale = D / toPupil;
      const Vec2d chief{filmRadius - filmRadius * scale, 0.0};
      const double half = std::min(extent, 0.6 * p.exitPupilDiameter * scale);
      constexpr int kFine = 12;
      for (int j = 0; j < kFine; ++j)
        for (int i = 0; i < kFine; ++i) {
          const Vec2d q{chief.x - half + 2 * half * (i + 0.5) / kFine,
                        chief.y - half + 2 * half * (j + 0.5) / kFine};
          if (passes(filmRadius, q)) inside.push_back(q);
        }
    }
    if (inside.empty()) return {};
    Vec2d c{0, 0};
    for (const Vec2d& q : inside) c = c + q;
    c = c / static_cast<double>(inside.size());
    if (!passes(filmRadius, c)) {
      const auto nearest =
          std::min_element(inside.begin(), inside.end(), [&](const Vec2d& u, const Vec2d& v) {
            return std::hypot(u.x - c.x, u.y - c.y) < std::hypot(v.x - c.x, v.y - c.y);
          });
      c = *nearest;
    }
    // March out from c in each direction, keeping the LAST passing step (so a
    // gap in a non-convex region is not taken for its edge), then bisect.
    constexpr int kDirections = 48;
    const double step = extent / 8.0;
    std::vector<Vec2d> edge;
    edge.reserve(kDirections);
    for (int k = 0; k < kDirections; ++k) {
      const double theta = 2.0 * kPi * k / kDirections;
      const Vec2d dir{std::cos(theta), std::sin(theta)};
      // Every passing point lies in the square: march only to its edge.
      const double tx = dir.x != 0 ? ((dir.x > 0 ? extent : -extent) - c.x) / dir.x : kInfinity;
      const double ty = dir.y != 0 ? ((dir.y > 0 ? extent : -extent) - c.y) / dir.y : kInfinity;
      const double tMax = std::min(tx, ty);
      double lastIn = 0.0;
      for (double t = step; t <= tMax; t += step)
        if (passes(filmRadius, c + dir * t)) lastIn = t;
      double lo = lastIn, hi = lastIn + step;
      for (int it = 0; it < 12; ++it) {
        const double mid = 0.5 * (lo + hi);
        (passes(filmRadius, c + dir * mid) ? lo : hi) = mid;
      }
      edge.push_back(c + dir * hi);
    }
    return withApexes(edge);
  }

 private:
  bool passes(double filmRadius, const Vec2d& q) const {
    const LensRay ray{{filmRadius, 0.0, filmZ_}, {q.x - filmRadius, q.y, planeZ_ - filmZ_}};
    return lens_.traceFromFilm(ray).has_value();
  }
  const LensSystem& lens_;
  double planeZ_, filmZ_;
};

}  // namespace

ExitPupilBounds::ExitPupilBounds(const LensSystem& lens, double filmZ, double maxFilmRadius, int intervals,
                                 FilmDepthRange depth)
    : planeZ_(lens.rearZ()), filmZ_(filmZ), maxFilmRadius_(maxFilmRadius) {
  if (!(depth.min <= depth.max) || !std::isfinite(depth.min) || !std::isfinite(depth.max))
    throw std::invalid_argument("ExitPupilBounds: bad film depth range");
  if (!(filmZ + depth.min > planeZ_))
    throw std::invalid_argument("ExitPupilBounds: the film must lie behind the rear vertex");
  if (!(maxFilmRadius > 0.0) || intervals < 1)
    throw std::invalid_argument("ExitPupilBounds: bad film extent");
  // Nodes at every interval end and middle; each interval's polygon is the
  // hull of its three nodes' boundaries, so it also covers radii in between.
  // A film slab adds depth nodes, at most 1 mm apart (ends included), whose
  // boundaries join the hull the same way: the passing region moves little
  // and smoothly with the film point's depth, and a hull of convex regions
  // holds every blend of them.
  const int nodes = 2 * intervals + 1;
  const double slab = depth.max - depth.min;
  const int depths = slab > 0.0 ? std::max(3, 1 + static_cast<int>(std::ceil(slab / 1.0))) : 1;
  std::vector<NodeSolver> solvers;
  for (int j = 0; j < depths; ++j)
    solvers.emplace_back(lens, planeZ_, depths == 1 ? filmZ_ : filmZ_ + depth.min + slab * j / (depths - 1));
  std::vector<std::vector<Vec2d>> boundaries(std::size_t(nodes) * depths);
  const unsigned threads = std::max(1u, std::min(8u, std::thread::hardware_concurrency()));
  {
    const int jobs = nodes * depths;
    std::vector<std::jthread> pool;
    for (unsigned t = 0; t < threads; ++t)
      pool.emplace_back([&, t] {
        for (int k = static_cast<int>(t); k < jobs; k += static_cast<int>(threads))
          boundaries[k] = solvers[k % depths].boundary(maxFilmRadius * (k / depths) / (nodes - 1));
      });
  }
  polygons_.resize(intervals);
  for (int i = 0; i < intervals; ++i) {
    std::vector<Vec2d> pts;
    for (int k = 2 * i * depths; k < (2 * i + 3) * depths; ++k)
      pts.insert(pts.end(), boundaries[k].begin(), boundaries[k].end());
    std::vector<Vec2d> hull = convexHull(pts);
    if (hull.size() < 3) continue;
    // Dilate about the vertex mean by 0.5% plus a micrometre, for the
    // variation between nodes and the bisection's tolerance.
    Vec2d g{0, 0};
    for (const Vec2d& v : hull) g = g + v;
    g = g / static_cast<double>(hull.size());
    for (Vec2d& v : hull) {
      const Vec2d r = v - g;
      const double len = std::hypot(r.x, r.y);
      if (len > 0) v = g + r * (1.005 + 1e-3 / len);
    }
    Polygon& poly = polygons_[i];
    poly.vertices = std::move(hull);
    poly.cdf.push_back(0.0);
    const auto& v = poly.vertices;
    for (std::size_t k = 1; k + 1 < v.size(); ++k)
      poly.cdf.push_back(poly.cdf.back() + 0.5 * cross2(v[0], v[k], v[k + 1]));
    poly.area = poly.cdf.back();
    poly.invArea = 1.0 / poly.area;
    for (std::size_t k = 1; k + 1 < v.size(); ++k)
      poly.triangles.push_back(
          {poly.cdf[k - 1], std::max(poly.cdf[k] - poly.cdf[k - 1], 1e-300), v[k], v[k + 1]});
    // Eight buckets per triangle: a target rarely shares its bucket with a
    // triangle boundary, so the correction in sample() rarely runs. Only
    // for an increasing cdf (a convex hull's fan, always in practice), where
    // that correction finds what upper_bound would.
    if (!std::is_sorted(poly.cdf.begin(), poly.cdf.end()) || poly.triangles.size() > 65535) continue;
    const std::size_t buckets = 8 * poly.triangles.size();
    poly.bucketScale = static_cast<double>(buckets) / poly.area;
    for (std::size_t b = 0; b < buckets; ++b) {
      const double target = static_cast<double>(b) / poly.bucketScale;
      poly.firstTriangle.push_back(static_cast<std::uint16_t>(searchFanTriangle(poly.cdf, target)));
    }
  }
}

namespace {
// Film radii are millimetres: no overflow to guard against, so no std::hypot
// (several times slower, and this runs once per camera sample).
double filmRadius(Vec2d filmPoint) {
  return std::sqrt(filmPoint.x * filmPoint.x + filmPoint.y * filmPoint.y);
}
}  // namespace

int ExitPupilBounds::intervalOf(double filmRadius) const {
  return intervalAt(filmRadius, filmRadius / maxFilmRadius_ * static_cast<int>(polygons_.size()));
}

int ExitPupilBounds::intervalAt(double filmRadius, double coordinate) const {
  if (!(filmRadius <= maxFilmRadius_ * (1.0 + 1e-9))) return -1;
  return std::clamp(static_cast<int>(coordinate), 0, static_cast<int>(polygons_.size()) - 1);
}

double ExitPupilBounds::area(double filmRadius) const {
  const int i = intervalOf(filmRadius);
  return i < 0 ? 0.0 : polygons_[i].area;
}

std::size_t ExitPupilBounds::triangleOf(const Polygon& poly, double target) {
  if (poly.firstTriangle.empty()) [[unlikely]]
    return searchFanTriangle(poly.cdf, target);
  const double bucket = target * poly.bucketScale;
  const std::size_t lastBucket = poly.firstTriangle.size() - 1;
  std::size_t k =
      poly.firstTriangle[bucket >= 0.0 ? std::min(static_cast<std::size_t>(std::min(bucket, 1e9)), lastBucket)
                                       : 0];
  const std::size_t last = poly.triangles.size() - 1;
  while (k < last && !(target < poly.triangles[k + 1].lo)) ++k;
  while (k > 0 && target < poly.triangles[k].lo) --k;
  return k;
}

std::optional<PupilSample> ExitPupilBounds::sample(Vec2d filmPoint, Vec2d u) const {
  const double r = filmRadius(filmPoint);
  const int i = intervalOf(r);
  if (i < 0 || polygons_[i].area <= 0.0) return std::nullopt;
  const Polygon& poly = polygons_[i];
  // Pick a fan triangle by area, reuse u.x within it, then uniform in the
  // triangle. The triangle is the one std::upper_bound over the inner cdf
  // values would give: the first whose end exceeds the target, else the
  // last. The bucket's guess moves by those comparisons until it is that one
  // (the cdf increases: every fan triangle of a convex hull has an area).
  const double target = u.x * poly.area;
  const Triangle& tri = poly.triangles[triangleOf(poly, target)];
  const double ux = std::clamp((target - tri.lo) / tri.span, 0.0, 1.0);
  const double s = std::sqrt(ux);
  const double b0 = 1.0 - s, b1 = u.y * s;
  const Vec2d& A = poly.vertices[0];
  const Vec2d q = A * b0 + tri.b * b1 + tri.c * (1.0 - b0 - b1);
  const double cosPhi = r > 0 ? filmPoint.x / r : 1.0, sinPhi = r > 0 ? filmPoint.y / r : 0.0;
  return PupilSample{{q.x * cosPhi - q.y * sinPhi, q.x * sinPhi + q.y * cosPhi, planeZ_}, poly.invArea};
}

namespace {

// Four samples of the batched sample() in flight, lane by lane.
struct FourSamples {
  alignas(32) double x[4], y[4];                  // film point
  alignas(32) double r[4], f[4], cos[4], sin[4];  // its radius, interval coordinate, azimuth
  alignas(32) double target[4], lo[4], span[4], uy[4], ax[4], ay[4], bx[4], by[4], cx[4], cy[4];
  alignas(32) double px[4], py[4];  // the pupil point
};

#if LENSRT_AVX_DOUBLES
// The square roots and divisions of sample() in AVX registers (the same
// operations in the same order, no FMA); trace_lanes::available() decides.
using namespace avx;
// filmRadius(), the interval coordinate filmRadius / maxFilmRadius * n and
// the azimuth's cosine and sine.
LENSRT_AVX void polarFour(FourSamples& s, double maxFilmRadius, double intervals) {
  const V x = load(s.x), y = load(s.y);
  const V r = avx::sqrt(x * x + y * y);
  const M positive = r > splat(0.0);
  store(s.r, r);
  store(s.f, r / splat(maxFilmRadius) * splat(intervals));
  store(s.cos, select(positive, x / r, splat(1.0)));
  store(s.sin, select(positive, y / r, splat(0.0)));
}
// The point in the picked triangle, rotated to the film point's azimuth.
LENSRT_AVX void pointFour(FourSamples& s) {
  const V zero = splat(0.0), one = splat(1.0);
  const V t = (load(s.target) - load(s.lo)) / load(s.span);
  const V ux = select(t < zero, zero, select(one < t, one, t));  // std::clamp(t, 0.0, 1.0)
  const V root = avx::sqrt(ux);
  const V b0 = one - root, b1 = load(s.uy) * root, b2 = one - b0 - b1;
  const V qx = load(s.ax) * b0 + load(s.bx) * b1 + load(s.cx) * b2;
  const V qy = load(s.ay) * b0 + load(s.by) * b1 + load(s.cy) * b2;
  const V c = load(s.cos), sn = load(s.sin);
  store(s.px, qx * c - qy * sn);
  store(s.py, qx * sn + qy * c);
}
#else
void polarFour(FourSamples&, double, double) {}
void pointFour(FourSamples&) {}
#endif

}  // namespace

void ExitPupilBounds::sample(std::span<const Vec2d> filmPoints, std::span<const Vec2d> u,
                             std::span<PupilSample> out) const {
  if (u.size() != filmPoints.size() || out.size() != filmPoints.size())
    throw std::invalid_argument("ExitPupilBounds::sample: as many samples and outputs as film points");
  std::size_t first = 0;
  if (trace_lanes::available()) {
    const int n = static_cast<int>(polygons_.size());
    FourSamples s;
    for (; first + 4 <= filmPoints.size(); first += 4) {
      for (std::size_t l = 0; l < 4; ++l) s.x[l] = filmPoints[first + l].x, s.y[l] = filmPoints[first + l].y;
      polarFour(s, maxFilmRadius_, n);
      // The polygon and fan triangle one lane at a time; a lane without
      // one computes on zeros and gets a pdf of 0.
      std::array<const Polygon*, 4> poly{};
      for (std::size_t l = 0; l < 4; ++l) {
        if (const int i = intervalAt(s.r[l], s.f[l]); i >= 0 && !(polygons_[i].area <= 0.0))
          poly[l] = &polygons_[i];  // sample()'s test, NaN included
        s.uy[l] = u[first + l].y;
        if (!poly[l]) {
          s.target[l] = s.lo[l] = s.ax[l] = s.ay[l] = s.bx[l] = s.by[l] = s.cx[l] = s.cy[l] = 0.0;
          s.span[l] = 1.0;
          continue;
        }
        s.target[l] = u[first + l].x * poly[l]->area;
        const Triangle& tri = poly[l]->triangles[triangleOf(*poly[l], s.target[l])];
        s.lo[l] = tri.lo, s.span[l] = tri.span;
        s.ax[l] = poly[l]->vertices[0].x, s.ay[l] = poly[l]->vertices[0].y;
        s.bx[l] = tri.b.x, s.by[l] = tri.b.y, s.cx[l] = tri.c.x, s.cy[l] = tri.c.y;
      }
      pointFour(s);
      for (std::size_t l = 0; l < 4; ++l)
        out[first + l] = poly[l] ? PupilSample{{s.px[l], s.py[l], planeZ_}, poly[l]->invArea} : PupilSample{};
    }
  }
  for (; first < filmPoints.size(); ++first)
    out[first] = sample(filmPoints[first], u[first]).value_or(PupilSample{});
}

std::vector<Vec2d> ExitPupilBounds::polygon(Vec2d filmPoint) const {
  const double r = filmRadius(filmPoint);
  const int i = intervalOf(r);
  if (i < 0) return {};
  const double cosPhi = r > 0 ? filmPoint.x / r : 1.0, sinPhi = r > 0 ? filmPoint.y / r : 0.0;
  std::vector<Vec2d> out;
  for (const Vec2d& q : polygons_[i].vertices)
    out.push_back({q.x * cosPhi - q.y * sinPhi, q.x * sinPhi + q.y * cosPhi});
  return out;
}

double ExitPupilBounds::pdf(Vec2d filmPoint, Vec2d pupilPoint) const {
  const double r = filmRadius(filmPoint);
  const int i = intervalOf(r);
  if (i < 0 || polygons_[i].area <= 0.0) return 0.0;
  const double cosPhi = r > 0 ? filmPoint.x / r : 1.0, sinPhi = r > 0 ? filmPoint.y / r : 0.0;
  const Vec2d q{pupilPoint.x * cosPhi + pupilPoint.y * sinPhi,
                -pupilPoint.x * sinPhi + pupilPoint.y * cosPhi};
  const auto& v = polygons_[i].vertices;
  // Each edge (v[k - 1], v[k]), the closing one first: no modulo per vertex
  // (a division; the lanes of spectral transport ask this three times a ray).
  for (std::size_t k = 0, prev = v.size() - 1; k < v.size(); prev = k++)
    if (cross2(v[prev], v[k], q) < 0.0) return 0.0;
  return polygons_[i].invArea;
}

}  // namespace lensrt

#include "optics/sample_sequence.h"

namespace lensrt {

PupilEfficiency measurePupilEfficiency(const LensSystem& lens, const ExitPupilBounds& bounds,
                                       double sensorWidthMm, double sensorHeightMm, long samples,
                                       unsigned long long seed) {
  SplitMix64 rng(seed);
  PupilEfficiency result;
  for (long i = 0; i < samples; ++i) {
    const Vec2d film{(rng.uniform() - 0.5) * sensorWidthMm, (rng.uniform() - 0.5) * sensorHeightMm};
    const Vec2d u{rng.uniform(), rng.uniform()};
    const auto s = bounds.sample(film, u);
    if (!s) {
      ++result.empty;
      continue;
    }
    ++result.sampled;
    const Vec3d origin{film.x, film.y, bounds.filmZ()};
    if (lens.traceFromFilm({origin, s->point - origin})) ++result.passed;
  }
  return result;
}

}  // namespace lensrt
