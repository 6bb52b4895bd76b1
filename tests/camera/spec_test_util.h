// Render specs for tests, set through the option table's rows exactly as
// the command line sets them: test::Flags{}("--camera", "thin")("--fstop", "4").
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "api/camera_factory.h"
#include "api/option_table.h"
#include "api/render_spec.h"

namespace lensrt::test {

struct Flags {
  RenderSpec spec;
  Flags() { spec.camera.lensDir = std::filesystem::path(LENSRT_SOURCE_DIR) / "lenses"; }
  Flags& operator()(const std::string& flag, const std::string& value) {
    findOption(flag)->set(spec, value);
    return *this;
  }
  CameraRequest request() const { return CameraRequest{spec.camera, spec.shutter, spec.flare}; }
};

// --shutter's parser.
inline double seconds(const std::string& text) {
  Flags f;
  f("--shutter", text);
  return f.spec.shutter.shutterSeconds();
}

inline std::unique_ptr<Camera> makeCamera(const Flags& f, const CameraDesc& gltf, FilmGeometry raster,
                                          const HitDistance& hit, Warnings& warnings) {
  return lensrt::makeCamera(f.request(), gltf, raster, hit, warnings);
}

}  // namespace lensrt::test
