// libFuzzer target for response files (`lensrt sensor plot FILE.csv`, the
// renderer's response CSV): the bytes through the reader. Only InputError
// may escape; an accepted response keeps the reader's promises (at least 3
// rows, strictly increasing wavelengths in 300-1100 nm, values in [0, 1e9],
// each channel positive somewhere), and at() is finite, non-negative, the
// sample itself at each wavelength, between its neighbours in between, and 0
// outside.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/error.h"
#include "fuzz/fuzz_check.h"
#include "sensor/response_csv.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace lensrt;
  try {
    const SensorResponse r =
        parseResponseCsv(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.csv");
    const std::size_t n = r.wavelengthsNm.size();
    LENSRT_FUZZ_CHECK(n >= 3 && r.rgb.size() == n);
    Vec3d largest;
    for (std::size_t i = 0; i < n; ++i) {
      const double nm = r.wavelengthsNm[i];
      LENSRT_FUZZ_CHECK(nm >= 300.0 && nm <= 1100.0);
      LENSRT_FUZZ_CHECK(i == 0 || nm > r.wavelengthsNm[i - 1]);
      LENSRT_FUZZ_CHECK(r.at(nm) == r.rgb[i]);
      for (int c = 0; c < 3; ++c) {
        LENSRT_FUZZ_CHECK(r.rgb[i][c] >= 0.0 && r.rgb[i][c] <= 1e9);
        largest[c] = std::max(largest[c], r.rgb[i][c]);
      }
      if (i + 1 < n) {
        const Vec3d mid = r.at(0.5 * (nm + r.wavelengthsNm[i + 1]));
        for (int c = 0; c < 3; ++c) {
          const double lo = std::min(r.rgb[i][c], r.rgb[i + 1][c]),
                       hi = std::max(r.rgb[i][c], r.rgb[i + 1][c]);
          LENSRT_FUZZ_CHECK(std::isfinite(mid[c]) && mid[c] >= lo * (1 - 1e-12) &&
                            mid[c] <= hi * (1 + 1e-12));
        }
      }
    }
    for (int c = 0; c < 3; ++c) LENSRT_FUZZ_CHECK(largest[c] > 0.0);
    LENSRT_FUZZ_CHECK(r.at(r.wavelengthsNm.front() - 1.0) == Vec3d());
    LENSRT_FUZZ_CHECK(r.at(r.wavelengthsNm.back() + 1.0) == Vec3d());
    const Vec3d peak = r.peakWavelengthsNm();
    for (int c = 0; c < 3; ++c)
      LENSRT_FUZZ_CHECK(peak[c] >= r.wavelengthsNm.front() && peak[c] <= r.wavelengthsNm.back());
  } catch (const InputError&) {
  }
  return 0;
}
