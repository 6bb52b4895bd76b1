// libFuzzer target for --aperture-mask: the image bytes through the decoder
// (the glTF textures' stb_image) into an ApertureMask, then lookups over the
// stop. Only InputError may escape; a mask must transmit within [0, 1] and
// pass some light.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "api/aperture_mask_file.h"
#include "core/error.h"
#include "fuzz/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace lensrt;
  try {
    const ApertureMask mask =
        decodeApertureMask(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.png");
    const double mean = mask.meanOverDisk();
    LENSRT_FUZZ_CHECK(mean > 0.0 && mean <= 1.0);
    for (int i = 0; i < 64; ++i) {
      const double t =
          mask.transmittance({std::cos(i * 0.7) * (i % 9) / 8.0, std::sin(i * 0.7) * (i % 9) / 8.0}, 1.0);
      LENSRT_FUZZ_CHECK(t >= 0.0 && t <= 1.0);
    }
  } catch (const InputError&) {
  }
  return 0;
}
