#include "camera_test_util.h"

#include <cmath>

#include "optics/lens_readers.h"

namespace lensrt::test {

LensPrescription lectureDoubleGauss(double scale) {
  static constexpr const char* kTable = R"(radius    thick   n_d    V     ap
 58.950   7.520  1.670  47.1  50.4
169.660   0.240                50.4
 38.550   8.050  1.670  47.1  46.0
 81.540   6.550  1.699  30.1  46.0
 25.500  11.410                36.0
 stop     9.000                34.2
-28.990   2.360  1.603  38.0  34.0
 81.540  12.130  1.658  57.3  40.0
-40.770   0.380                40.0
874.130   6.440  1.717  48.0  40.0
-79.460  72.228                40.0
)";
  LensPrescription lens = parseTableLens(kTable, "lecture-dgauss.lens");
  return scale == 1.0 ? lens : lens.scaled(scale);
}

FilmGeometry testFilm() {
  return {640, 360, 36.0, 20.25};
}

FilmGeometry rasterFilm(int w, int h) {
  FilmGeometry f;
  f.width = w;
  f.height = h;
  return f;
}

std::optional<Ray> cameraRay(const Camera& camera, Vec2d raster, Vec2d lens, float wavelengthNm) {
  CameraSample s;
  s.film = {float(raster.x), float(raster.y)};
  s.lens = {float(lens.x), float(lens.y)};
  s.wavelengthNm = wavelengthNm;
  const auto r = camera.generateRay(s);
  if (!r) return std::nullopt;
  return r->ray;
}

Vec3d pointAtZ(const Ray& ray, double z) {
  const Vec3d o(ray.origin), d(ray.direction);
  return o + d * ((z - o.z) / d.z);
}

std::optional<Vec2d> imageOf(const Camera& camera, const Vec3d& p, Vec2d lens, Vec2d guess) {
  const Transform cameraFromWorld = camera.worldFromCamera().inverse();
  return imageOf(
      [&](Vec2d raster) -> std::optional<Ray> {
        const auto r = cameraRay(camera, raster, lens);
        if (!r) return std::nullopt;
        return cameraFromWorld(*r);
      },
      p, guess);
}

std::optional<Vec2d> imageOf(const RaySource& rayAt, const Vec3d& p, Vec2d guess) {
  // The miss at the point's depth is close to affine in the raster position.
  const auto miss = [&](Vec2d raster) -> std::optional<Vec2d> {
    const auto r = rayAt(raster);
    if (!r) return std::nullopt;
    const Vec3d q = pointAtZ(*r, p.z);
    return Vec2d{q.x - p.x, q.y - p.y};
  };
  Vec2d x = guess;
  for (int it = 0; it < 20; ++it) {
    const auto m = miss(x);
    if (!m) return std::nullopt;
    const double h = 0.5;
    const auto mx = miss({x.x + h, x.y}), my = miss({x.x, x.y + h});
    if (!mx || !my) return std::nullopt;
    const double a = (mx->x - m->x) / h, b = (my->x - m->x) / h;
    const double c = (mx->y - m->y) / h, d = (my->y - m->y) / h;
    const double det = a * d - b * c;
    if (det == 0.0) return std::nullopt;
    const Vec2d step{(d * m->x - b * m->y) / det, (-c * m->x + a * m->y) / det};
    x = x - step;
    if (std::hypot(step.x, step.y) < 1e-3) return x;
  }
  return std::nullopt;
}

double spread(const std::vector<Vec2d>& points) {
  double best = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = i + 1; j < points.size(); ++j)
      best = std::max(best, std::hypot(points[i].x - points[j].x, points[i].y - points[j].y));
  return best;
}

}  // namespace lensrt::test
