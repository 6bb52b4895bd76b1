// `lensrt render SCENE -o OUT`: path-trace a glTF scene to an image.
#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "api/camera_options.h"
#include "api/render_options.h"
#include "app/camera_flags.h"
#include "app/command.h"
#include "app/frame_sequence.h"
#include "app/option_checks.h"
#include "app/render_flags.h"
#include "cluster/cluster.h"
#include "cluster/render_sequence.h"
#include "cluster/render_to_file.h"
#include "core/error.h"

namespace lensrt {
namespace {

struct RenderArgs {
  SceneArgs frame;  // the scene file and its frame
  std::string output;
  int spp = 16;
  AdaptiveArgs adaptive;
  int threads = 0;
  std::uint64_t seed = 0;
  std::vector<std::string> aovs;
  int tileSize = 16;
  std::string crop;
  std::string tile;
  RawOutputOptions raw;
  std::string ocioDisplay, ocioView;  // empty: the sRGB curve (both empty) or the config's default
  double checkpointSeconds = 0;       // 0: no checkpoints
  std::string resume;
  bool quiet = false;
  CameraOptions camera;
  std::string frames;  // --frames A:B[:STEP]; empty: one frame
};

std::string checkCrop(const std::string& text) {
  int v[4];
  char end = 0;
  if (std::sscanf(text.c_str(), "%d,%d,%d,%d%c", &v[0], &v[1], &v[2], &v[3], &end) != 4)
    return "expected X0,X1,Y0,Y1 in pixels, e.g. --crop 0,320,0,180";
  if (v[0] < 0 || v[2] < 0 || v[1] <= v[0] || v[3] <= v[2])
    return "expected 0 <= X0 < X1 and 0 <= Y0 < Y1 (X1, Y1 exclusive), got " + text;
  return "";
}

std::string checkTile(const std::string& text) {
  int index = 0, count = 0;
  char end = 0;
  if (std::sscanf(text.c_str(), "%d/%d%c", &index, &count, &end) != 2)
    return "expected I/N (tile I of N, I from 0), e.g. --tile 0/8";
  if (count < 1 || index < 0 || index >= count) return "expected 0 <= I < N, got " + text;
  return "";
}

int runRender(const RenderArgs& args, const CommandContext& context) {
  FileRender job;
  job.scene = sceneOptions(args.frame, args.quiet);
  job.camera = args.camera;
  // A moving scene is posed over the time the frame records it.
  job.scene.time.spanSeconds = recordedSpanSeconds(job.camera);
  RenderSettings& settings = job.settings;
  settings.samplesPerPixel = args.spp;
  settings.seed = args.seed;
  settings.threads = args.threads;
  settings.tileSize = args.tileSize;
  settings.aovs = parseAovs(args.aovs);
  settings.adaptive = adaptiveSampling(args.adaptive, args.spp);
  settings.aovs.spp = settings.adaptive.has_value();
  job.output = args.output;
  job.raw = args.raw;
  if (!args.ocioDisplay.empty() || !args.ocioView.empty())
    job.display = DisplayTransform{args.ocioDisplay, args.ocioView};
  // The syntax is checked by the flags' validators.
  if (!args.tile.empty()) {
    FileRender::Strip strip;
    std::sscanf(args.tile.c_str(), "%d/%d", &strip.index, &strip.count);
    job.tile = strip;
  }
  if (!args.crop.empty()) {
    PixelRegion crop;
    std::sscanf(args.crop.c_str(), "%d,%d,%d,%d", &crop.x0, &crop.x1, &crop.y0, &crop.y1);
    job.crop = crop;
  }
  job.checkpointSeconds = args.checkpointSeconds;
  job.resume = args.resume;
  job.quiet = args.quiet;
  job.commandLine = context.commandLine;
  if (args.frames.empty()) return renderToFile(job, *context.cluster);
  // A sequence: each frame is the render `--frame N` gives, to its own file.
  const FrameRange range = parseFrames(args.frames);
  if (args.frame.time || args.frame.frame)
    throw UsageError("--frames", "give --frames A:B, or --time / --frame for one frame, not both");
  if (!args.resume.empty())
    throw UsageError("--frames", "--resume continues one frame's checkpoint: resume it alone with --frame N");
  std::vector<SequenceFrame> frames;  // the output's pattern checked before any work
  for (int f = range.first; f <= range.last; f += range.step)
    frames.push_back({double(f) / args.frame.fps, frameFileName(args.output, f)});
  return renderSequence(job, frames, *context.cluster);
}

}  // namespace

CommandAction addRenderCommand(CLI::App& app, const CommandContext& context) {
  CLI::App* cmd = app.add_subcommand("render",
                                     "Path-trace a glTF 2.0 scene (.gltf/.glb) to an image.\n"
                                     "Example: lensrt render scenes/dof_row.gltf --spp 64 --res 640x360 "
                                     "--aov depth,variance -o out/dof_row.exr");
  auto args = std::make_shared<RenderArgs>();
  cmd->add_option("scene", args->frame.scene, "glTF scene file (.gltf or .glb), e.g. scenes/dof_row.gltf")
      ->required();
  cmd->add_option("-o,--output", args->output,
                  "output image: .exr (linear float, all channels and metadata), .png/.jpg (8-bit sRGB "
                  "preview), .tif/.jp2 (16-bit sRGB), .webp (8-bit sRGB) or .dpx (10-bit Cineon log); "
                  "e.g. -o out/a.exr")
      ->required();
  cmd->add_option(
      "--ocio-display", args->ocioDisplay,
      "a preview's OpenColorIO display (the $OCIO config's, through OpenImageIO) instead of the sRGB "
      "curve, e.g. --ocio-display sRGB (default with --ocio-view: the config's default display)");
  cmd->add_option("--ocio-view", args->ocioView,
                  "that display's view, e.g. --ocio-view Film (default: the display's default view)");
  cmd->add_option("--spp", args->spp,
                  "samples per pixel (>= 1; with --noise-threshold, the most a pixel takes), e.g. --spp 64")
      ->check(integerIn(1, 1 << 24, "samples per pixel"))
      ->capture_default_str();
  addAdaptiveOptions(*cmd, args->adaptive);
  cmd->add_option(
         "--res", args->frame.resolution,
         "image size in pixels WIDTHxHEIGHT, e.g. --res 640x360; a WIDTH alone takes the height from the "
         "glTF camera's aspect ratio (default 640 wide, height from the camera's aspect ratio or 360)")
      ->check([](const std::string& s) { return checkResolution(s); });
  cmd->add_option(
         "--max-depth", args->frame.maxDepth,
         "maximum scattering events per path (0: emitters only, 1: direct light), e.g. --max-depth 8")
      ->check(integerIn(0, 1024, "scattering events per path"))
      ->capture_default_str();
  cmd->add_option("--threads", args->threads, "worker threads (0: all cores), e.g. --threads 4")
      ->check(integerIn(0, 4096, "worker threads, 0 for all cores"))
      ->capture_default_str();
  cmd->add_option("--seed", args->seed, "random seed; same seed, same image on any machine, e.g. --seed 7")
      ->check(integerIn<std::uint64_t>(0, std::numeric_limits<std::uint64_t>::max()))
      ->capture_default_str();
  cmd->add_option(
      "--camera-node", args->frame.cameraNode,
      "camera to render: a glTF node name or index, e.g. --camera-node 3 (default: the scene's first "
      "camera, else a view framing the scene)");
  cmd->add_option(
         "--scene-index", args->frame.sceneIndex,
         "which glTF scene to render (0-based; default: the file's default scene), e.g. --scene-index 1")
      ->check(integerIn(0, 1 << 20, "0-based"));
  addLightSamplerOption(*cmd, args->frame);
  addEnvironmentOptions(*cmd, args->frame.environment);
  addSceneAccessOptions(*cmd, args->frame.access);
  addAnimationOptions(*cmd, args->frame);
  cmd->add_option(
         "--aov", args->aovs,
         "extra EXR channels, comma separated: depth (depth.Z, metres), normal (normal.X/Y/Z, world), "
         "albedo (albedo.R/G/B), variance (variance.R/G/B of the pixel mean), e.g. --aov depth,variance")
      ->delimiter(',')
      ->check(CLI::IsMember({"depth", "normal", "albedo", "variance"}));
  cmd->add_option("--tile-size", args->tileSize,
                  "tile size in pixels for scheduling threads (does not change the image)")
      ->check(integerIn(1, 4096, "pixels"))
      ->capture_default_str();
  auto* crop =
      cmd->add_option("--crop", args->crop,
                      "render only pixels X0 <= x < X1, Y0 <= y < Y1 of the frame into an EXR whose data "
                      "window places them (join parts with lensrt merge), e.g. --crop 0,320,0,180")
          ->check([](const std::string& s) { return checkCrop(s); });
  cmd->add_option(
         "--tile", args->tile,
         "render only tile I (from 0) of N: horizontal strips top to bottom, heights differing by at "
         "most a row (for job arrays; join with lensrt merge), e.g. --tile 0/8")
      ->check([](const std::string& s) { return checkTile(s); })
      ->excludes(crop);
  cmd->add_option(
      "--raw", args->raw.file,
      "also write the raw file a camera would: the colour filter mosaic (--cfa) as a 16-bit linear "
      "DNG that raw developers read (with --noise on the sensor's DN; else an image value of 1.0 "
      "at the white level 65535), e.g. --raw out/a.dng");
  cmd->add_option("--cfa", args->raw.cfa, "the raw file's colour filter pattern: RGGB, BGGR, GRBG or GBRG")
      ->check(CLI::IsMember({"RGGB", "BGGR", "GRBG", "GBRG"}))
      ->capture_default_str();
  cmd->add_option(
         "--checkpoint", args->checkpointSeconds,
         "every SECONDS, write the image so far to -o (atomically) with its running sums in OUT.sums, "
         "so that --resume can continue it exactly, e.g. --checkpoint 600")
      ->check(CLI::Range(0.0, 1e9));
  cmd->add_option("--frames", args->frames,
                  "render frames A to B (every STEP-th) of the animation at --fps, each as --frame N would, "
                  "to the output's name with its # marks or %04d replaced by the frame number, e.g. --frames "
                  "0:47 -o out/f.####.exr")
      ->check(checkWith(parseFrames, "A:B[:STEP]"));
  cmd->add_option("--resume", args->resume,
                  "continue the checkpoint CHECKPOINT.exr (same scene, camera and settings) to --spp, e.g. "
                  "--resume out/a.exr");
  addCameraOptions(*cmd, args->camera);
  cmd->add_flag("-q,--quiet", args->quiet, "no progress, warnings or summary on stderr (errors still print)");
  return [args, context]() { return runRender(*args, context); };
}

}  // namespace lensrt
