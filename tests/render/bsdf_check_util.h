// Checks shared by the BSDF tests: numerical integration over the sphere and
// a chi-square test of a sampling routine against its density.
#pragma once

#include <functional>
#include <optional>
#include <random>

#include "core/vec.h"

namespace lensrt::test {

Vec3f sphericalDir(double theta, double phi);
// A direction uniform on the sphere for u1, u2 uniform in [0, 1): z = 2 u1 - 1,
// azimuth 2 pi u2 (float arithmetic).
Vec3f uniformSphereDir(float u1, float u2);
// uniformSphereDir of two uniform draws from rng, u1 first.
inline Vec3f randomSphereDir(std::mt19937& rng) {
  std::uniform_real_distribution<float> u(0, 1);
  const float u1 = u(rng);
  return uniformSphereDir(u1, u(rng));
}

// Composite Simpson over a (theta, phi) region of g(w) sin(theta), n even.
double integrateSphere(const std::function<double(const Vec3f&)>& g, double theta0, double theta1,
                       double phi0, double phi1, int n);

// Wilson-Hilferty: upper tail of chi-square with k degrees of freedom.
double chiSquarePValue(double x, int k);

struct ChiSquareResult {
  double pValue = 0;
  double chi2 = 0;
  int dof = 0;
  double pdfMass = 0;     // integral of the pdf over the sphere
  double unexpected = 0;  // samples in pooled bins where the pdf expects fewer than 5 in all
};

// Bins `samples` directions drawn by `sample` (nullopt: rejected) on the whole
// sphere (theta from +z over [0, pi]) and compares them with the mass the pdf
// gives each bin (rejections against the pdf's missing mass). Each bin's mass
// is integrated on a 24x24 Simpson grid: refraction densities jump where the
// generalised half vector reaches the horizon, and a coarser grid's error
// there fails the test.
ChiSquareResult sphereChiSquare(const std::function<std::optional<Vec3f>(std::mt19937&)>& sample,
                                const std::function<double(const Vec3f&)>& pdf, int samples,
                                int thetaBins = 20, int phiBins = 32);

}  // namespace lensrt::test
