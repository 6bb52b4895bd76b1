// Helpers for the camera tests: rays in camera space, where a scene point
// images on the film, and a reference lens that needs no files.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "camera/camera.h"
#include "core/vec.h"
#include "optics/prescription.h"

namespace lensrt::test {

// The seed lecture's double Gauss (EFL about 100.7 mm), scaled by `scale`.
LensPrescription lectureDoubleGauss(double scale = 1.0);

// A film of 56.25 um square pixels on a 36 x 20.25 mm sensor.
FilmGeometry testFilm();

// A raster of w x h pixels (the sensor left at its default).
FilmGeometry rasterFilm(int w, int h);

// The world-space ray for a raster position and lens sample (wavelength: the d line).
std::optional<Ray> cameraRay(const Camera& camera, Vec2d raster, Vec2d lens, float wavelengthNm = 587.56f);

// Where a ray crosses the plane Z = z (camera space, metres).
Vec3d pointAtZ(const Ray& ray, double z);

// The raster position whose ray, for lens sample `lens`, passes through the
// camera-space point `p` (the camera's transform is undone) (Newton's method from `guess`); nullopt when the
// rays are blocked or it does not converge.
std::optional<Vec2d> imageOf(const Camera& camera, const Vec3d& p, Vec2d lens, Vec2d guess);
// The same for any source of camera-space rays by raster position.
using RaySource = std::function<std::optional<Ray>(Vec2d raster)>;
std::optional<Vec2d> imageOf(const RaySource& rayAt, const Vec3d& p, Vec2d guess);

// Largest distance between any two of the points.
double spread(const std::vector<Vec2d>& points);

}  // namespace lensrt::test
