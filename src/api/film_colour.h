// How a render's film records colour, from the camera options: spectral
// transport through a film response (render/film_response.h), or RGB
// transport (--spectral off).
#pragma once

#include <memory>
#include <string>

#include "api/camera_options.h"
#include "render/film_response.h"

namespace lensrt {

// None for --spectral off. Throws UsageError for bad options.
std::shared_ptr<const FilmResponse> filmResponse(const CameraOptions& options);

// "rgb", or "spectral:" and the response's name: part of a render's identity
// (a checkpoint resumes, and tiles merge, only with the same transport).
std::string transportDescription(const FilmResponse* response);

}  // namespace lensrt
