// Everything a render needs, from its spec (api/render_spec.h), made in one
// place: the scene posed over the shutter's span, the frame (raster, lights,
// environment, integrator), the camera, the integrator's settings with the
// shutter timing, the film colour and the flare light, the sensor readout,
// the identity and the metadata. `lensrt render` (run/render_to_file.h),
// `lensrt compare`, the tile and rank runners and Python's Scene.render all
// start here.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "api/film_colour.h"
#include "api/option_table.h"
#include "api/render_job.h"
#include "api/render_spec.h"
#include "api/sensor_readout.h"
#include "api/transport_choice.h"
#include "core/warnings.h"
#include "render/renderer.h"

namespace lensrt {

// The scene posed again over another span (Python's loaded scene); none:
// the file is read again.
using ScenePoser = std::function<std::shared_ptr<const Scene>(double spanSeconds)>;

struct PlanOptions {
  std::shared_ptr<const Scene> scene;  // already loaded and posed at the spec's time; none: load it
  ScenePoser repose;
  bool quiet = false;                 // no "no lights" or default-sky notice
  bool lightPass = true;              // run the flare light pass (an MPI worker rank needs none)
  unsigned command = kRenderCommand;  // whose checks apply (api/option_table.h)
};

// One camera of a plan, with what depends on it.
struct PlannedShot {
  std::unique_ptr<Camera> camera;
  RenderSettings settings;  // the plan's, with this camera's flare light
  ImageMetadata identity;   // render/render_identity.h's keys
};

// The scene file and frame of a spec as RenderJob loads them, posed over
// the shutter's span.
SceneOptions sceneOptions(const RenderSpec& spec, bool quiet);

class RenderPlan {
 public:
  // Checks the spec, loads (or poses) the scene and makes the camera.
  // Throws UsageError and InputError before any rendering.
  RenderPlan(const RenderSpec& spec, Warnings& warnings, const PlanOptions& options = {});
  ~RenderPlan();
  RenderPlan(const RenderPlan&) = delete;
  RenderPlan& operator=(const RenderPlan&) = delete;

  const RenderSpec& spec() const { return spec_; }
  const RenderJob& job() const { return *job_; }
  const PlannedShot& shot() const { return shot_; }
  const Camera& camera() const { return *shot_.camera; }
  const RenderSettings& settings() const { return shot_.settings; }
  const ImageMetadata& identity() const { return shot_.identity; }
  const FilmColour& colour() const { return colour_; }
  // The transport used (--spectral auto resolved) and why.
  const TransportChoice& transport() const { return transport_; }
  const std::optional<SensorReadout>& readout() const { return readout_; }
  const Exposure& exposure() const { return exposure_; }

  // The same render through another camera spec (`compare`'s models).
  PlannedShot shotOf(const CameraSpec& camera, Warnings& warnings) const;

  // A rendered image's metadata; with a sensor readout the image is read
  // out first (R, G, B then hold its reading).
  ImageMetadata finish(RenderJobResult& result, const PlannedShot& shot, const std::string& commandLine,
                       Warnings& warnings) const;
  // Writes the raw file when the spec asks for one.
  void writeRaw(const Image& image) const;

 private:
  // The shot of a camera made for `camera`: its settings and identity.
  PlannedShot finishShot(RenderJob::MadeCamera made, const CameraSpec& camera) const;

  RenderSpec spec_;
  PlanOptions options_;
  std::unique_ptr<RenderJob> job_;
  TransportChoice transport_;
  FilmColour colour_;
  Exposure exposure_;
  RenderSettings base_;  // what every shot shares
  std::optional<SensorReadout> readout_;
  PlannedShot shot_;
};

}  // namespace lensrt
