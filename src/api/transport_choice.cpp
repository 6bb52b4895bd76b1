#include "api/transport_choice.h"

#include <array>
#include <utility>

namespace lensrt {

TransportChoice chooseTransport(Transport asked, const WavelengthNeeds& n) {
  switch (asked) {
    case Transport::Spectral:
      return {true, "spectral (--spectral on)"};
    case Transport::Rgb:
      return {false, "rgb (--spectral off)"};
    case Transport::Auto:
      break;
  }
  const std::array<std::pair<bool, const char*>, 6> rules{{
      {n.cameraResponse, "a camera response"},
      {n.colourSettings, "--white-balance or --output-space"},
      {n.sceneDispersion, "dispersive glass in the scene"},
      {n.lensDispersion, "the lens disperses"},
      {n.flareCoatings, "coatings under flare"},
      {n.diffraction, "diffraction"},
  }};
  for (const auto& [holds, why] : rules)
    if (holds) return {true, std::string("spectral (auto: ") + why + ")"};
  return {false, "rgb (auto: nothing needs wavelengths)"};
}

}  // namespace lensrt
