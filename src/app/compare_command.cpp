// `lensrt compare SCENE --lens FILE -o DIR`: the four camera models with
// matched settings (the simpler ones derived from the lens's paraxial data),
// their renders, a contact sheet, heat maps against the full lens, and the
// figures in report.json and report.html.
#include <fmt/core.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "api/camera_models.h"
#include "api/option_table.h"
#include "api/render_plan.h"
#include "api/text_file.h"
#include "app/command.h"
#include "app/option_flags.h"
#include "core/error.h"
#include "image/contact_sheet.h"
#include "image/heatmap.h"
#include "image/image_diff.h"
#include "image/image_io.h"
#include "optics/lens_readers.h"
#include "optics/paraxial.h"
#include "report/compare_report.h"
#include "run/distributed_render.h"
#include "run/job_on_ranks.h"
#include "run/mpi_job.h"

namespace lensrt {
namespace {

struct CompareArgs {
  RenderSpec spec;  // the option table's flags fill it
  std::string outputDir;
  bool quiet = false;
  std::shared_ptr<OptionFlags> flags;
};

nlohmann::json numberOrNull(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

// DIR and its missing parents are created, as every command's output folder is.
std::filesystem::path prepareOutputDir(const std::string& text, bool quiet) {
  const std::filesystem::path dir(text);
  std::error_code ec;
  if (std::filesystem::exists(dir, ec)) {
    if (!std::filesystem::is_directory(dir, ec)) throw InputError(text, "exists and is not a directory");
  } else {
    if (!std::filesystem::create_directories(dir, ec) && ec)
      throw InputError(text, "cannot create the folder: " + ec.message());
    noteCreatedFolder(dir, quiet);
  }
  if (access(dir.c_str(), W_OK) != 0) throw InputError(text, "the directory is not writable");
  return dir;
}

nlohmann::json lensFigures(const CameraSpec& options) {
  LensPrescription lens = loadLens(findLens(options.lens, options.lensDir));
  if (options.focalLengthMm) lens = lens.scaled(*options.focalLengthMm / computeParaxial(lens).efl);
  const ParaxialData p = computeParaxial(lens);
  return {
      {"name", lens.name},
      {"description", lens.description},
      {"efl_mm", p.efl},
      {"bfl_mm", p.bfl},
      {"ffl_mm", p.ffl},
      {"f_number_wide_open", p.fNumber},
      {"stop_diameter_mm", p.stopDiameter},
      {"entrance_pupil_z_mm", p.entrancePupilZ},
      {"entrance_pupil_diameter_mm", p.entrancePupilDiameter},
      {"exit_pupil_z_mm", p.exitPupilZ},
      {"exit_pupil_diameter_mm", p.exitPupilDiameter},
      {"front_principal_z_mm", p.frontPrincipalZ},
      {"rear_principal_z_mm", p.rearPrincipalZ},
      {"front_focal_z_mm", p.frontFocalZ},
      {"rear_focal_z_mm", p.rearFocalZ},
      {"length_mm", p.lastVertexZ},
  };
}

// One errors scale for all heat maps so they can be compared: the 99.5th
// percentile of the finite errors, so a few fireflies do not wash them out.
double commonHeatmapScale(const std::vector<std::vector<float>>& errors) {
  std::vector<float> all;
  for (const auto& e : errors)
    for (const float v : e)
      if (std::isfinite(v)) all.push_back(v);
  if (all.empty()) return 1.0;
  const std::size_t k = std::min(all.size() - 1, std::size_t(0.995 * double(all.size())));
  std::nth_element(all.begin(), all.begin() + std::ptrdiff_t(k), all.end());
  return all[k] > 0 ? double(all[k]) : 1.0;
}

// A contact sheet cell's samples: the fixed count, or the mean of adaptive sampling's.
std::string sppLabel(const RenderOutput& out) {
  const std::uint64_t pixels = std::uint64_t(out.image.width) * std::uint64_t(out.image.height);
  if (out.image.channelIndex("spp") < 0 || pixels == 0) return std::to_string(out.samplesDone);
  return fmt::format("mean {:.1f}", double(out.cameraSamples) / double(pixels));
}

// The four renders side by side, each labelled with its figures.
void writeContactSheet(const std::filesystem::path& dir, const std::vector<std::string>& modelNames,
                       const std::vector<const PlannedShot*>& shots,
                       const std::vector<RenderJobResult>& results) {
  std::vector<LabelledImage> cells;
  for (std::size_t i = 0; i < modelNames.size(); ++i) {
    const CameraInfo info = shots[i]->camera->info();
    const std::string focus = info.focusMetres <= 0 ? "no focus"
                              : std::isinf(info.focusMetres)
                                  ? "focus inf"
                                  : fmt::format("focus {:.3g} m", info.focusMetres);
    cells.push_back(
        {results[i].output.image,
         {modelNames[i],
          fmt::format("f={:.4g}mm {} {}", info.focalLengthMm,
                      info.fNumber > 0 ? fmt::format("f/{:.3g}", info.fNumber) : "no aperture", focus),
          fmt::format("{} spp, {:.2f} s, rays {:.1f}%", sppLabel(results[i].output), results[i].seconds,
                      100.0 * results[i].output.cameraRayEfficiency())}});
  }
  writeImage(dir / "contact-sheet.png", makeContactSheet(cells, 2), {});
}

// Each model's figures and, against the full lens (the last), its heat map
// (on one scale, which `heatmap` returns).
nlohmann::json modelReports(const std::filesystem::path& dir, const std::vector<std::string>& modelNames,
                            const std::vector<const PlannedShot*>& shots,
                            const std::vector<RenderJobResult>& results, HeatmapOptions& heatmap) {
  const std::size_t lensIndex = modelNames.size() - 1;
  const Image& lensImage = results[lensIndex].output.image;
  std::vector<std::vector<float>> errors;
  for (std::size_t i = 0; i < lensIndex; ++i)
    errors.push_back(perPixelMaxError(results[i].output.image, lensImage));
  heatmap.scaleMax = commonHeatmapScale(errors);

  nlohmann::json models = nlohmann::json::object();
  for (std::size_t i = 0; i < modelNames.size(); ++i) {
    const Image& image = results[i].output.image;
    const CameraInfo info = shots[i]->camera->info();
    nlohmann::json m = {
        {"camera", shots[i]->camera->describe()},
        {"file", std::string(modelNames[i]) + ".exr"},
        {"f_number", info.fNumber > 0 ? nlohmann::json(info.fNumber) : nlohmann::json(nullptr)},
        {"focus_m", info.focusMetres > 0 ? numberOrNull(info.focusMetres) : nlohmann::json(nullptr)},
        {"focus_at_infinity", std::isinf(info.focusMetres)},
        {"focal_length_mm", info.focalLengthMm},
        {"film", info.film},
        {"render_seconds", results[i].seconds},
        {"camera_ray_efficiency", results[i].output.cameraRayEfficiency()},
        {"nan_samples", results[i].output.droppedSamples},
        {"mean_spp",
         double(results[i].output.cameraSamples) /
             double(std::max<std::uint64_t>(1, std::uint64_t(image.width) * std::uint64_t(image.height)))},
        {"mean",
         {{"luminance", numberOrNull(meanLuminance(image))},
          {"R", numberOrNull(channelMean(image, "R"))},
          {"G", numberOrNull(channelMean(image, "G"))},
          {"B", numberOrNull(channelMean(image, "B"))}}},
    };
    nlohmann::json profile = nlohmann::json::array();
    for (const double v : vignettingProfile(image)) profile.push_back(numberOrNull(v));
    m["vignetting_profile"] = profile;
    const DiffReport diff = diffImages(image, lensImage, DiffThresholds{});
    m["mean_abs_diff_vs_lens"] = numberOrNull(diff.overall.meanError);
    m["rmse_vs_lens"] = numberOrNull(diff.overall.rmse);
    if (i < lensIndex) {
      heatmap.title = fmt::format("|{} - lens|", modelNames[i]);
      const std::string name = fmt::format("diff-{}-vs-lens.png", modelNames[i]);
      writeImage(dir / name, makeHeatmap(errors[i], image.width, image.height, heatmap), {});
      m["heatmap"] = name;
    }
    models[modelNames[i]] = m;
  }

  return models;
}

// The settings every model shares, as the report states them.
nlohmann::json settingsReport(const RenderSpec& spec, const RenderPlan& plan,
                              const std::vector<const PlannedShot*>& shots) {
  const CameraInfo lensInfo = shots.back()->camera->info();
  const RenderJob& job = plan.job();
  return {
      {"scene", spec.scene.file},
      {"lens", spec.camera.lens},
      {"f_number", lensInfo.fNumber},
      {"focus", findOption("--focus")->show(spec)},
      {"focus_m", numberOrNull(lensInfo.focusMetres)},
      {"sensor", findOption("--sensor")->show(spec)},
      {"exposure", lensInfo.exposure},
      {"pinhole_film", shots[0]->camera->info().film},
      {"blades", spec.camera.blades},
      {"width", job.width()},
      {"height", job.height()},
      {"spp", spec.sampling.spp},
      {"noise_threshold", plan.settings().adaptive ? nlohmann::json(plan.settings().adaptive->noiseThreshold)
                                                   : nlohmann::json(nullptr)},
      {"min_spp", plan.settings().adaptive ? nlohmann::json(plan.settings().adaptive->minSamples)
                                           : nlohmann::json(nullptr)},
      {"seed", spec.sampling.seed},
      {"max_depth", spec.sampling.maxDepth},
      {"light_sampler", lightSamplingName(spec.sampling.lightSampling)},
      {"environment", job.environmentDescription()}};
}

int runCompare(const CompareArgs& givenArgs, const CommandContext& context) {
  // Under MPI every rank renders each model (rank 0 handing out strips);
  // rank 0 alone speaks and writes the directory.
  const MpiJob& mpi = *context.mpi;
  const bool leader = mpi.isMain();
  CompareArgs args = givenArgs;
  if (!leader) args.quiet = true;
  const RenderSpec& spec = args.spec;
  if (leader) args.flags->warnUnused(spec, args.quiet);
  // 1. Everything that can fail before rendering.
  checkSpec(spec, kCompareCommand);
  const std::string& envFile = spec.environment.file;
  if (!envFile.empty() && !std::filesystem::is_regular_file(envFile))
    throw InputError(envFile, "environment map not found");
  const std::filesystem::path dir =
      leader ? prepareOutputDir(args.outputDir, args.quiet) : std::filesystem::path();

  Warnings warnings([&](const std::string& message) {
    if (!args.quiet) fmt::print(stderr, "lensrt: warning: {}: {}\n", spec.scene.file, message);
  });
  const nlohmann::json lens = lensFigures(spec.camera);
  // An --fstop wider than the lens opens would leave the full lens at its
  // widest and the ideal models wider: all four use the widest instead.
  RenderSpec matched = spec;
  matched.camera.model = CameraModel::Lens;
  matched.camera.film.reset();  // --film is the pinhole's
  const double wideOpen = lens.at("f_number_wide_open").get<double>();
  if (matched.camera.fNumber && *matched.camera.fNumber < wideOpen * (1 - 1e-9))
    matched.camera.fNumber = wideOpen;
  PlanOptions planOptions;
  planOptions.quiet = args.quiet;
  planOptions.command = kCompareCommand;
  const RenderPlan plan(matched, warnings, planOptions);
  if (spec.camera.fNumber && *spec.camera.fNumber < wideOpen * (1 - 1e-9))
    warnings.warn(
        fmt::format("{}: f/{:g} is wider than the lens allows; every model uses its widest aperture f/{:.3g}",
                    spec.camera.lens, *spec.camera.fNumber, wideOpen));
  const RenderJob& job = plan.job();
  // All four cameras first: a bad --focus fails before any render.
  std::vector<PlannedShot> others;
  std::vector<const PlannedShot*> shots;
  others.reserve(cameraModels().size());
  for (const CameraModelInfo& model : cameraModels()) {
    if (model.model == CameraModel::Lens) {
      shots.push_back(&plan.shot());
      continue;
    }
    CameraSpec camera = matched.camera;
    camera.model = model.model;
    // --film chooses the pinhole's film (radiance, the ideal reference, by
    // default); the lens models always record irradiance.
    if (model.model == CameraModel::Pinhole) camera.film = spec.camera.film;
    shots.push_back(&others.emplace_back(plan.shotOf(camera, warnings)));
  }
  std::vector<std::string> modelNames;
  for (const CameraModelInfo& model : cameraModels()) modelNames.push_back(model.name);
  if (mpi.size() > 1) {
    // The full lens's identity covers the scene, the lens and the settings.
    if (const auto failure = setUpTogether(*context.mpi, spec.scene.file, shots.back()->identity)) {
      if (leader)
        fmt::print(stderr, "lensrt: error: rank {} of {}: {}\n", failure->rank, mpi.size(), failure->line);
      return failure->status;
    }
  }

  // 2. Render and write each model's EXR.
  std::vector<RenderJobResult> results;
  for (std::size_t i = 0; i < modelNames.size(); ++i) {
    if (!args.quiet)
      fmt::print(stderr, "lensrt: compare: {} ({}/{})\n", shots[i]->camera->describe(), i + 1,
                 modelNames.size());
    results.push_back(renderOnRanks(job, *shots[i]->camera, shots[i]->settings, args.quiet, mpi));
    if (!leader) continue;
    writeImage(dir / (std::string(modelNames[i]) + ".exr"), results.back().output.image,
               plan.finish(results.back(), *shots[i], context.commandLine, warnings));
    if (results.back().output.droppedSamples > 0)
      warnings.warn(fmt::format("{}: {} samples with NaN or infinite radiance were dropped", modelNames[i],
                                results.back().output.droppedSamples));
  }
  if (!leader) return 0;
  writeContactSheet(dir, modelNames, shots, results);
  HeatmapOptions heatmap;
  const nlohmann::json models = modelReports(dir, modelNames, shots, results, heatmap);
  const nlohmann::json report = {
      {"version", LENSRT_VERSION},
      {"command_line", context.commandLine},
      {"model_order", modelNames},
      {"settings", settingsReport(spec, plan, shots)},
      {"lens", lens},
      {"heatmap_scale", heatmap.scaleMax},
      {"vignetting_bins", kVignettingBins},
      {"models", models},
  };
  writeTextFileAtomically(dir / "report.json", report.dump(2) + "\n");
  writeTextFileAtomically(dir / "report.html", compareReportHtml(report));
  if (!args.quiet) fmt::print(stderr, "lensrt: wrote {}/report.html\n", dir.string());
  return 0;
}

}  // namespace

CommandAction addCompareCommand(CLI::App& app, const CommandContext& context) {
  CLI::App* cmd = app.add_subcommand(
      "compare",
      "Render a scene through the four camera models (pinhole, thin, thick, lens) side by side\n"
      "Pinhole, thin and thick lens derived from --lens's paraxial data, and the full lens. Writes "
      "DIR/{pinhole,thin,thick,lens}.exr, "
      "contact-sheet.png, diff-<model>-vs-lens.png heat maps, report.json and report.html.\n"
      "Example: lensrt compare scenes/dof_row.gltf --lens dgauss-50mm --fstop 2 --focus 2 --spp 64 "
      "--res 640x360 -o out/cmp");
  auto args = std::make_shared<CompareArgs>();
  cmd->add_option("scene", args->spec.scene.file, "glTF scene file (.gltf or .glb), e.g. scenes/dof_row.gltf")
      ->required();
  cmd->add_option("-o,--output", args->outputDir,
                  "output directory, created (with its missing parents) if missing, e.g. -o out/cmp")
      ->required();
  args->flags = std::make_shared<OptionFlags>(*cmd, args->spec, kCompareCommand);
  // compare renders every model; the lens they are derived from is required.
  cmd->get_option("--lens")->required();
  cmd->get_option("--film")->description(
      "the pinhole's film: radiance (the ideal reference, as pbrt, Cycles and Mitsuba record it; default) or "
      "irradiance (all four models on the physical film, cos^4 and bellows factor included, scaled by "
      "--exposure); thin, thick and lens always record irradiance");
  cmd->add_flag("-q,--quiet", args->quiet, "no progress, warnings or summary on stderr (errors still print)");
  return [args, context]() { return runCompare(*args, context); };
}

}  // namespace lensrt
