// `lensrt merge PARTS... -o OUT.exr`: joins the parts of one render (--tile
// or --crop outputs, from a job array) into the whole frame, bit for bit.
#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "api/output_file.h"
#include "app/command.h"
#include "core/error.h"
#include "image/image_io.h"
#include "image/image_merge.h"
#include "image/spp_channel.h"
#include "render/render_identity.h"

namespace lensrt {
namespace {

struct MergeArgs {
  std::vector<std::string> parts;
  std::string output;
  bool quiet = false;
};

std::uint64_t count(const ImageMetadata& m, const std::string& key) {
  const auto it = m.find(key);
  if (it == m.end()) return 0;
  try {
    return std::stoull(it->second);
  } catch (const std::exception&) {
    return 0;
  }
}

int runMerge(const MergeArgs& args) {
  noteCreatedFolder(checkOutputFile(args.output), args.quiet);
  if (std::filesystem::path(args.output).extension() != ".exr")
    throw CLI::ValidationError("-o",
                               "the merged image must be an .exr (it keeps every channel and the metadata)");
  std::vector<Image> parts;
  std::vector<ImageMetadata> metas;
  for (const std::string& file : args.parts) {
    ImageMetadata meta;
    parts.push_back(readImage(file, &meta));
    if (!meta.count("lensrt:spp")) throw InputError(file, "is not a lensrt render (no lensrt:spp)");
    metas.push_back(std::move(meta));
  }
  // Same render: identity and samples per pixel (a checkpoint of a part is
  // not a finished part).
  // Adaptive parts differ in their pixels' samples: their passes must agree.
  const auto sppDone = [&](std::size_t i) -> const std::string& {
    return isAdaptiveSpp(metas[i]["lensrt:spp"]) ? metas[i]["lensrt:samples_done"] : metas[i]["lensrt:spp"];
  };
  for (std::size_t i = 1; i < parts.size(); ++i) {
    if (const std::string diff = renderIdentityDifference(metas[i], metas[0]); !diff.empty())
      throw InputError(args.parts[i], "is not a part of the render " + args.parts[0] + " is from: " + diff);
    if (sppDone(i) != sppDone(0))
      throw InputError(args.parts[i],
                       fmt::format("has {} spp, {} has {}", sppDone(i), args.parts[0], sppDone(0)));
  }
  for (std::size_t i = 0; i < parts.size(); ++i)
    if (const auto r = metas[i].find("lensrt:spp_requested"); r != metas[i].end() && r->second != sppDone(i))
      throw InputError(args.parts[i],
                       fmt::format("is an unfinished render ({} of {} spp)", sppDone(i), r->second));
  Image merged;
  try {
    merged = mergeImageParts(parts, args.parts);
  } catch (const std::invalid_argument& e) {
    throw InputError(args.output, std::string("cannot merge: ") + e.what());
  }

  // The whole render's metadata: the first part's, with the counts summed.
  // Only lensrt's own keys and the Cryptomatte layers' (the same in every
  // part: the manifest lists the whole scene); the file format's (data
  // window, compression...) are the writer's business.
  ImageMetadata meta;
  for (const auto& [key, value] : metas[0])
    if (key.rfind("lensrt:", 0) == 0 || key.rfind("cryptomatte/", 0) == 0) meta[key] = value;
  meta.erase("lensrt:region");
  meta.erase("lensrt:sums_sha256");
  std::uint64_t nan = 0, samples = 0, blocked = 0;
  double seconds = 0;
  for (const ImageMetadata& m : metas) {
    nan += count(m, "lensrt:nan_samples");
    samples += count(m, "lensrt:camera_samples");
    blocked += count(m, "lensrt:blocked_camera_rays");
    if (const auto it = m.find("lensrt:render_seconds"); it != m.end())
      seconds += std::atof(it->second.c_str());
  }
  meta["lensrt:nan_samples"] = std::to_string(nan);
  meta["lensrt:camera_samples"] = std::to_string(samples);
  meta["lensrt:blocked_camera_rays"] = std::to_string(blocked);
  if (samples > 0)
    meta["lensrt:camera_ray_efficiency"] = fmt::format("{:.4f}", 1.0 - double(blocked) / double(samples));
  meta["lensrt:render_seconds"] = fmt::format("{:.3f}", seconds);
  meta["lensrt:merged_parts"] = std::to_string(parts.size());
  if (const std::optional<std::string> spp = adaptiveSppSummary(merged)) meta["lensrt:spp"] = *spp;
  writeOutputImage(args.output, merged, meta);
  if (!args.quiet)
    fmt::print(stderr, "lensrt: wrote {} ({}x{}, {} parts)\n", args.output, merged.width, merged.height,
               parts.size());
  return 0;
}

}  // namespace

CommandAction addMergeCommand(CLI::App& app, const CommandContext&) {
  CLI::App* cmd =
      app.add_subcommand("merge",
                         "Join the parts of one render (--tile or --crop outputs) into the whole image\n"
                         "Joins lensrt render --tile I/N or --crop outputs after checking that they come "
                         "from the same render and cover the frame exactly once.\n"
                         "Example: lensrt merge out/part-*.exr -o out/whole.exr");
  auto args = std::make_shared<MergeArgs>();
  cmd->add_option("parts", args->parts, "the parts: EXR files written by lensrt render --tile/--crop")
      ->required();
  cmd->add_option("-o,--output", args->output, "the whole image (.exr), e.g. -o out/whole.exr")->required();
  cmd->add_flag("-q,--quiet", args->quiet, "no summary on stderr (errors still print)");
  return [args]() { return runMerge(*args); };
}

}  // namespace lensrt
