// The few distribution functions the noise-aware image comparison needs.
#pragma once

namespace lensrt {

// P(Z > z) for a standard normal Z.
double normalUpperTail(double z);

// P(T > t) for Student's t with nu > 0 degrees of freedom.
double studentTUpperTail(double t, double nu);

// Regularised incomplete beta function I_x(a, b), a, b > 0, x in [0,1].
double incompleteBeta(double a, double b, double x);

// The c with P(|T| > c) = alpha for Student's t with nu degrees of freedom,
// or for the standard normal when nu is 0 or infinite. alpha in (0,1).
double twoSidedCriticalValue(double alpha, double nu);

// The smallest k with P(X > k) <= beta for X ~ Binomial(n, p): the most
// failures n independent tests with false-alarm rate p may show before the
// whole is judged failed at false-alarm rate beta.
long long binomialCriticalCount(long long n, double p, double beta);

}  // namespace lensrt
