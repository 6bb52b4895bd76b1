#include "api/film_colour.h"

namespace lensrt {

std::shared_ptr<const FilmResponse> filmResponse(const CameraOptions& options) {
  if (options.spectral == "off") return nullptr;
  // The built-in response lives as long as the program: a non-owning pointer.
  return std::shared_ptr<const FilmResponse>(std::shared_ptr<const void>(), &FilmResponse::cie1931Srgb());
}

std::string transportDescription(const FilmResponse* response) {
  if (!response) return "rgb";
  std::string s = "spectral:";
  s += response->describe();
  return s;
}

}  // namespace lensrt
