#include "image/statistics.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace lensrt {
namespace {

// Continued fraction for the incomplete beta function, evaluated with the
// modified Lentz method (converges fast for x < (a+1)/(a+b+2)).
double betaContinuedFraction(double a, double b, double x) {
  constexpr double kTiny = 1e-300;
  constexpr double kEps = 1e-15;
  const double qab = a + b, qap = a + 1, qam = a - 1;
  double c = 1.0;
  double d = 1.0 - qab * x / qap;
  if (std::fabs(d) < kTiny) d = kTiny;
  d = 1.0 / d;
  double h = d;
  for (int m = 1; m <= 1000; ++m) {
    const int m2 = 2 * m;
    double aa = m * (b - m) * x / ((qam + m2) * (a + m2));
    d = 1.0 + aa * d;
    if (std::fabs(d) < kTiny) d = kTiny;
    c = 1.0 + aa / c;
    if (std::fabs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    h *= d * c;
    aa = -(a + m) * (qab + m) * x / ((a + m2) * (qap + m2));
    d = 1.0 + aa * d;
    if (std::fabs(d) < kTiny) d = kTiny;
    c = 1.0 + aa / c;
    if (std::fabs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::fabs(delta - 1.0) < kEps) break;
  }
  return h;
}

}  // namespace

double normalUpperTail(double z) {
  return 0.5 * std::erfc(z / std::sqrt(2.0));
}

double incompleteBeta(double a, double b, double x) {
  if (x <= 0) return 0.0;
  if (x >= 1) return 1.0;
  const double logFront =
      std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log1p(-x);
  const double front = std::exp(logFront);
  // Use the symmetry I_x(a,b) = 1 - I_{1-x}(b,a) where the fraction converges.
  if (x < (a + 1) / (a + b + 2)) return front * betaContinuedFraction(a, b, x) / a;
  return 1.0 - front * betaContinuedFraction(b, a, 1.0 - x) / b;
}

double studentTUpperTail(double t, double nu) {
  if (!(nu > 0)) throw std::invalid_argument("studentTUpperTail: nu must be positive");
  const double half = 0.5 * incompleteBeta(0.5 * nu, 0.5, nu / (nu + t * t));
  return t >= 0 ? half : 1.0 - half;
}

double twoSidedCriticalValue(double alpha, double nu) {
  if (!(alpha > 0 && alpha < 1)) throw std::invalid_argument("twoSidedCriticalValue: alpha must be in (0,1)");
  const bool normal = nu == 0 || std::isinf(nu);
  const auto twoSidedTail = [&](double c) {
    return 2.0 * (normal ? normalUpperTail(c) : studentTUpperTail(c, nu));
  };
  // The tail falls monotonically in c: bisect on a bracket grown until it holds.
  double lo = 0.0, hi = 1.0;
  while (twoSidedTail(hi) > alpha) hi *= 2.0;
  for (int i = 0; i < 200 && hi - lo > 1e-12 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (twoSidedTail(mid) > alpha ? lo : hi) = mid;
  }
  return hi;
}

long long binomialCriticalCount(long long n, double p, double beta) {
  if (n <= 0 || p <= 0) return 0;
  if (p >= 1) return n;
  const double logP = std::log(p), logQ = std::log1p(-p);
  const double logNFactorial = std::lgamma(double(n) + 1);
  double cdf = 0.0;
  for (long long k = 0; k < n; ++k) {
    cdf += std::exp(logNFactorial - std::lgamma(double(k) + 1) - std::lgamma(double(n - k) + 1) +
                    double(k) * logP + double(n - k) * logQ);
    if (1.0 - cdf <= beta) return k;
  }
  return n;
}

}  // namespace lensrt
