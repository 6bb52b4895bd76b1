#include "render/distribution.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace lensrt {
namespace {

// Distribution1D::sample searches a guide table's bracket instead of the whole
// cdf; it must pick the very bin (and remapped value) that the plain search of
// its definition picks: the first bin whose upper cdf exceeds u, stepping back
// over zero-weight bins.
TEST(Distribution1D, GuidedSearchPicksTheBinOfThePlainSearch) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> uniform(0, 1);
  for (const std::size_t n :
       {std::size_t{8}, std::size_t{9}, std::size_t{100}, std::size_t{1000}, std::size_t{70000}}) {
    for (const double zeros : {0.0, 0.5, 0.95}) {
      std::vector<float> w(n);
      for (float& x : w)
        x = uniform(rng) < zeros ? 0.0f : std::pow(uniform(rng), 6.0f);  // spread over decades
      w[n / 2] = 1;
      const Distribution1D d(w);
      std::vector<double> cdf(n + 1, 0.0);
      for (std::size_t i = 0; i < n; ++i) cdf[i + 1] = cdf[i] + double(w[i]);
      for (double& c : cdf) c /= cdf.back();
      std::vector<float> us = {0.0f, std::nextafter(1.0f, 0.0f), 0.5f, 0.25f};
      for (int k = 0; k < 20000; ++k) us.push_back(uniform(rng));
      for (std::size_t i = 1; i < n; i += std::max<std::size_t>(1, n / 50))
        us.push_back(float(cdf[i]));  // on the steps
      for (const float u : us) {
        const auto it = std::upper_bound(cdf.begin() + 1, cdf.end(), double(u));
        std::size_t want = std::min<std::size_t>(std::size_t(it - cdf.begin()) - 1, n - 1);
        while (w[want] == 0 && want > 0) --want;
        float remapped = -1;
        ASSERT_EQ(d.sample(u, &remapped), want) << "n " << n << " u " << u;
        const double width = cdf[want + 1] - cdf[want];
        const double r = width > 0 ? (double(u) - cdf[want]) / width : 0.0;
        ASSERT_EQ(remapped, float(std::clamp(r, 0.0, double(std::nextafter(1.0f, 0.0f)))))
            << "n " << n << " u " << u;
      }
    }
  }
}

}  // namespace
}  // namespace lensrt
