// The render pipeline shared by `lensrt render` and `lensrt compare`: the
// scene, materials, lights and integrator are built once, then any number of
// cameras render through them with the same settings.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "api/camera_factory.h"
#include "api/render_options.h"
#include "api/scene.h"
#include "camera/camera.h"
#include "camera/lens_camera.h"
#include "core/transform.h"
#include "core/warnings.h"
#include "image/image.h"
#include "render/environment.h"
#include "render/integrator.h"
#include "render/lights.h"
#include "render/material_eval.h"
#include "render/renderer.h"
#include "scene/camera_selection.h"
#include "scene/render_scene.h"

namespace lensrt {

// What a render sets up around a loaded scene.
struct FrameOptions {
  std::string cameraNode;                    // empty: the first camera, else a view framing the scene
  std::optional<Transform> worldFromCamera;  // replaces the chosen camera's pose (looks down -Z, +Y up)
  std::optional<Resolution> resolution;      // none: 640 wide, height from the camera's aspect
  EnvironmentSpec environment;
  int maxDepth = 8;
  LightSampling lightSampling = LightSampling::Tree;  // --light-sampler
  bool quiet = false;                                 // no "no lights" warning
  // A scene without a camera is framed for the chosen camera's field at an
  // aspect ratio (width / height): see FramingField. None: 40 degrees.
  std::function<FramingField(float aspect)> framingField;
};

// A scene file and its frame, as `lensrt render` and `lensrt compare` take them.
struct SceneOptions : FrameOptions {
  std::string scene;  // .gltf / .glb
  int sceneIndex = -1;
  SceneReadLimits limits;  // what the scene may make lensrt read and hold
  AnimationTime time;      // --time/--frame and --animation
};

struct RenderJobResult {
  RenderOutput output;
  double seconds = 0.0;
};

class RenderJob {
 public:
  // Loads the scene and builds everything but the camera. Throws InputError.
  RenderJob(const SceneOptions& options, Warnings& warnings);
  // The same around a scene already loaded (which the job shares).
  RenderJob(std::shared_ptr<const Scene> scene, const FrameOptions& frame, Warnings& warnings);
  ~RenderJob();
  RenderJob(const RenderJob&) = delete;
  RenderJob& operator=(const RenderJob&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  const Integrator& integrator() const { return *integrator_; }

  // One of the models for this request, framed by the glTF camera (its
  // keyframed settings read at the scene's time); --focus auto asks the
  // scene what the focus pixel sees. `flareLens`: the full lens when it
  // makes stray light, else null.
  struct MadeCamera {
    std::unique_ptr<Camera> camera;
    const LensCamera* flareLens = nullptr;
  };
  MadeCamera makeCamera(const CameraSpec& camera, const ShutterSpec& shutter, const FlareSpec& flare,
                        Warnings& warnings) const;
  // The same with keyframed settings read at another time (a neighbouring frame's).
  MadeCamera makeCamera(const CameraSpec& camera, const ShutterSpec& shutter, const FlareSpec& flare,
                        double timeSeconds, Warnings& warnings) const;
  // When the samples are taken (RenderSettings::timing): for a scene that
  // moves during the span it was loaded for, from the shutter; none when
  // nothing moves (a notice then when a rolling shutter or a shutter curve
  // was asked for).
  std::optional<ShutterTiming> shutterTiming(const ShutterSpec& shutter, Warnings& warnings) const;
  // --aov flow's moments (render/motion_flow.h) for a camera made by this
  // job: the scene posed `frameSeconds` before and after its time (read
  // again from the file) when frameSeconds > 0, else the shutter's opening
  // and closing under `timing`. UsageError("--aov") when nothing moves over
  // the shutter (api/flow_moments.cpp). A keyframed focus moves the film
  // between frames: the neighbours then get their own camera from `spec`.
  std::shared_ptr<const MotionFlow> motionFlow(const Camera& camera, const CameraSpec& spec,
                                               const ShutterSpec& shutter,
                                               const std::optional<ShutterTiming>& timing,
                                               double frameSeconds) const;
  // Whether the scene has glass whose index depends on the wavelength
  // (KHR_materials_dispersion), which --spectral auto renders spectrally.
  bool sceneDisperses() const;
  // The colour of the scene's most powerful light (--white-balance auto).
  std::optional<Rgb> dominantLightColour() const { return lights_->dominantColour(); }

  // Renders with a progress bar on stderr unless `quiet`.
  RenderJobResult render(const Camera& camera, const RenderSettings& settings, bool quiet) const;

  // The full lens's stray light: the light pass (render/flare_light_pass.h)
  // of the scene's punctual lights, still emitters and environment sun (and,
  // with a maximum depth of 1 or more, the lamps' lit surfaces) for these
  // settings. spp x pixels / 10 paths (at least 65 536) for
  // each light, the emitters together and the sun (an eighth of that for a
  // lamp's lit surfaces), from the render's seed. Camera paths of
  // a flare camera skip these sources after a lens reflection, so every
  // render of one adds this image.
  std::shared_ptr<const FlareImage> flareLight(const LensCamera& camera,
                                               const RenderSettings& settings) const;

  // Continues `state` to settings.samplesPerPixel in passes steered by
  // `control` (see renderPasses); `finished` says whether it got there.
  RenderJobResult renderPasses(const Camera& camera, const RenderSettings& settings, FilmState& state,
                               const PassControl& control, bool quiet, bool& finished) const;

  // The metadata that identifies this render (render/render_identity.h):
  // scene digest, camera, settings, seed. Every option that changes the
  // image must show in it, so that parts and checkpoints of other renders
  // are refused.
  ImageMetadata identity(const Camera& camera, const RenderSettings& settings) const;

  // The EXR header of a render: its identity, region, timing, efficiency.
  // "constant 1,1,1", "latlong 512x256 rotated 90deg", ... prefixed with
  // "default " when the scene had no light and no --env (lensrt:environment).
  std::string environmentDescription() const;

  // The EXR header of a render: camera (with its exposure), settings,
  // timing, efficiency; `identity` is the render's (identity(), and what
  // the plan adds to it).
  ImageMetadata metadata(const Camera& camera, const Exposure& exposure, const RenderSettings& settings,
                         const RenderJobResult& result, const std::string& commandLine,
                         const ImageMetadata& identity) const;

 private:
  std::shared_ptr<const Scene> scene_;
  FrameOptions frame_;
  int width_ = 0, height_ = 0;
  CameraDesc gltfCamera_;
  std::unique_ptr<Environment> environment_;
  bool defaultEnvironment_ = false;
  std::unique_ptr<LightSet> lights_;
  std::unique_ptr<Integrator> integrator_;
};

// The radiance of the default environment, W/(sr m^2) in every direction: a
// scene with no light source (no punctual light, no emissive surface) and no
// --env is lit by it, times --env-intensity.
inline constexpr float kDefaultSkyRadiance = 1.0f;

// The environment a spec describes (black when it names none); reads the map
// file. Throws InputError.
Environment makeEnvironment(const EnvironmentSpec& spec);

}  // namespace lensrt
