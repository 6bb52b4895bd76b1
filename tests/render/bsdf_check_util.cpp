#include "bsdf_check_util.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/constants.h"

namespace lensrt::test {

Vec3f sphericalDir(double theta, double phi) {
  return {float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)),
          float(std::cos(theta))};
}

Vec3f uniformSphereDir(float u1, float u2) {
  const float z = 2 * u1 - 1, phi = 2 * float(kPi) * u2, r = std::sqrt(std::max(0.0f, 1 - z * z));
  return {r * std::cos(phi), r * std::sin(phi), z};
}

double integrateSphere(const std::function<double(const Vec3f&)>& g, double theta0, double theta1,
                       double phi0, double phi1, int n) {
  const double ht = (theta1 - theta0) / n, hp = (phi1 - phi0) / n;
  double sum = 0;
  for (int i = 0; i <= n; ++i) {
    const double wt = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
    const double theta = theta0 + i * ht;
    for (int j = 0; j <= n; ++j) {
      const double wp = (j == 0 || j == n) ? 1 : (j % 2 ? 4 : 2);
      sum += wt * wp * g(sphericalDir(theta, phi0 + j * hp)) * std::sin(theta);
    }
  }
  return sum * ht * hp / 9;
}

double chiSquarePValue(double x, int k) {
  const double z = (std::cbrt(x / k) - (1 - 2.0 / (9 * k))) / std::sqrt(2.0 / (9 * k));
  return 0.5 * std::erfc(z / std::sqrt(2.0));
}

ChiSquareResult sphereChiSquare(const std::function<std::optional<Vec3f>(std::mt19937&)>& sample,
                                const std::function<double(const Vec3f&)>& pdf, int samples, int thetaBins,
                                int phiBins) {
  const int bins = thetaBins * phiBins;
  std::vector<double> observed(bins + 1, 0), expected(bins + 1, 0);
  std::mt19937 rng(7);
  int valid = 0;
  for (int k = 0; k < samples; ++k) {
    const std::optional<Vec3f> w = sample(rng);
    if (!w) continue;
    ++valid;
    const double theta = std::acos(std::clamp(double(w->z), -1.0, 1.0));
    double phi = std::atan2(w->y, w->x);
    if (phi < 0) phi += 2 * kPi;
    const int ti = std::min(thetaBins - 1, int(theta / kPi * thetaBins));
    const int pi = std::min(phiBins - 1, int(phi / (2 * kPi) * phiBins));
    observed[ti * phiBins + pi] += 1;
  }
  observed.back() = samples - valid;
  ChiSquareResult r;
  for (int ti = 0; ti < thetaBins; ++ti)
    for (int pi = 0; pi < phiBins; ++pi) {
      // Simpson's end nodes stay off the horizon, where a BSDF's density
      // jumps from its reflection lobe to its transmission lobe.
      constexpr double kInset = 1e-6;
      const double mass =
          integrateSphere(pdf, ti * kPi / thetaBins + kInset, (ti + 1) * kPi / thetaBins - kInset,
                          pi * 2 * kPi / phiBins, (pi + 1) * 2 * kPi / phiBins, 24);
      expected[ti * phiBins + pi] = mass * samples;
      r.pdfMass += mass;
    }
  expected.back() = std::max(0.0, 1.0 - r.pdfMass) * samples;
  // Pool bins too small for the chi-square approximation.
  double pooledObs = 0, pooledExp = 0;
  for (std::size_t i = 0; i < observed.size(); ++i) {
    if (expected[i] < 5) {
      pooledObs += observed[i];
      pooledExp += expected[i];
      continue;
    }
    r.chi2 += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
    ++r.dof;
  }
  if (pooledExp >= 5) {
    r.chi2 += (pooledObs - pooledExp) * (pooledObs - pooledExp) / pooledExp;
    ++r.dof;
  } else {
    r.unexpected = pooledObs;
  }
  r.dof -= 1;
  r.pValue = chiSquarePValue(r.chi2, r.dof);
  return r;
}

}  // namespace lensrt::test
