// `lensrt render SCENE -o OUT`: path-trace a glTF scene to an image.
#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "api/render_spec.h"
#include "app/command.h"
#include "app/frame_sequence.h"
#include "app/option_checks.h"
#include "app/option_flags.h"
#include "core/error.h"
#include "image/output_formats.h"
#include "run/mpi_job.h"
#include "run/render_sequence.h"
#include "run/render_to_file.h"

namespace lensrt {
namespace {

struct RenderArgs {
  FileRender job;                     // the spec (the option table's flags fill it) and the output
  std::string ocioDisplay, ocioView;  // empty: the sRGB curve (both empty) or the config's default
  std::string frames;                 // --frames A:B[:STEP]; empty: one frame
  std::shared_ptr<OptionFlags> flags;
};

int runRender(const RenderArgs& args, const CommandContext& context) {
  FileRender job = args.job;
  if (!args.ocioDisplay.empty() || !args.ocioView.empty())
    job.display = DisplayTransform{args.ocioDisplay, args.ocioView};
  job.commandLine = context.commandLine;
  if (context.mpi->isMain()) args.flags->warnUnused(job.spec, job.quiet);
  if (args.frames.empty()) return renderToFile(job, *context.mpi);
  // A sequence: each frame is the render `--frame N` gives, to its own file.
  const FrameRange range = parseFrames(args.frames);
  if (job.spec.time.seconds || job.spec.time.frame)
    throw UsageError("--frames", "give --frames A:B, or --time / --frame for one frame, not both");
  if (!job.resume.empty())
    throw UsageError("--frames", "--resume continues one frame's checkpoint: resume it alone with --frame N");
  if (job.spec.aovs.flow && job.spec.time.flowStepSeconds == 0)  // --aov flow's neighbours
    job.spec.time.flowStepSeconds = double(range.step) / job.spec.time.fps;
  std::vector<SequenceFrame> frames;  // the output's pattern checked before any work
  for (int f = range.first; f <= range.last; f += range.step)
    frames.push_back({double(f) / job.spec.time.fps, frameFileName(job.output, f)});
  return renderSequence(job, frames, *context.mpi);
}

}  // namespace

CommandAction addRenderCommand(CLI::App& app, const CommandContext& context) {
  CLI::App* cmd = app.add_subcommand("render",
                                     "Path-trace a glTF 2.0 scene (.gltf/.glb) to an image.\n"
                                     "Example: lensrt render scenes/dof_row.gltf --spp 64 --res 640x360 "
                                     "--aov depth,variance -o out/dof_row.exr");
  auto args = std::make_shared<RenderArgs>();
  FileRender& job = args->job;
  cmd->add_option("scene", job.spec.scene.file, "glTF scene file (.gltf or .glb), e.g. scenes/dof_row.gltf")
      ->required();
  cmd->add_option("-o,--output", job.output, "output image: " + outputFormatHelp() + "; e.g. -o out/a.exr")
      ->required();
  cmd->add_option(
      "--ocio-display", args->ocioDisplay,
      "a preview's OpenColorIO display (the $OCIO config's, through OpenImageIO) instead of the sRGB "
      "curve, e.g. --ocio-display sRGB (default with --ocio-view: the config's default display)");
  cmd->add_option("--ocio-view", args->ocioView,
                  "that display's view, e.g. --ocio-view Film (default: the display's default view)");
  args->flags = std::make_shared<OptionFlags>(*cmd, job.spec, kRenderCommand);
  cmd->add_option(
         "--checkpoint", job.checkpointSeconds,
         "every SECONDS, write the image so far to -o (atomically) with its running sums in OUT.sums, "
         "so that --resume can continue it exactly, e.g. --checkpoint 600")
      ->check(CLI::Range(0.0, 1e9));
  cmd->add_option("--flo", job.flo,
                  "on: also write --aov flow as Middlebury/Sintel .flo files beside the output, "
                  "OUT.forward.flo and OUT.backward.flo (OUT: -o without its extension), e.g. --flo on "
                  "(default off)");
  cmd->add_option("--frames", args->frames,
                  "render frames A to B (every STEP-th) of the animation at --fps, each as --frame N would, "
                  "to the output's name with its # marks or %04d replaced by the frame number, e.g. --frames "
                  "0:47 -o out/f.####.exr")
      ->check(checkWith(parseFrames, "A:B[:STEP]"));
  cmd->add_option("--resume", job.resume,
                  "continue the checkpoint CHECKPOINT.exr (same scene, camera and settings) to --spp, e.g. "
                  "--resume out/a.exr");
  cmd->add_flag("-q,--quiet", job.quiet, "no progress, warnings or summary on stderr (errors still print)");
  return [args, context]() { return runRender(*args, context); };
}

}  // namespace lensrt
