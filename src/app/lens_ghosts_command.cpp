// `lensrt lens ghosts LENS [--coatings none|single|multi] [--json]`: where a
// lens's flare comes from, its two-reflection ghosts strongest first.
#include <fmt/core.h>

#include <iostream>
#include <memory>

#include "api/lens_ghosts.h"
#include "api/lens_loading.h"
#include "app/lens_subcommands.h"
#include "optics/ghosts.h"

namespace lensrt {

namespace {

struct GhostsOptions {
  std::string lens;
  std::string coatings = "none";
  bool json = false;
};

int printGhosts(const GhostsOptions& o, const LensPrescription& lens) {
  const Coating coating = *parseCoating(o.coatings);
  const std::vector<GhostPath> ghosts = strongestGhosts(lens, coating);
  if (o.json) {
    std::cout << lensGhostsJson(lens, coating, ghosts).dump(2) << "\n";
    return 0;
  }
  fmt::print("{}: {} two-reflection ghosts, strongest first (coatings {}; surfaces from the front)\n",
             lens.name.empty() ? lens.file : lens.name, ghosts.size(), coatingName(coating));
  fmt::print("  surfaces   strength   passing   rel. flux   focus from film   size on film\n");
  for (const GhostPath& g : ghosts)
    fmt::print("  {:>3},{:<3}   {:>9.2e}   {:>7.3f}   {:>9.2e}   {:>15}   {:>9.2f} mm\n", g.first + 1,
               g.second + 1, g.strength, g.passing, g.strength * g.passing,
               g.focusFromFilmMm ? fmt::format("{:+.2f} mm", *g.focusFromFilmMm) : std::string("infinity"),
               g.sizeOnFilmMm);
  fmt::print(
      "(paraxial, on axis, a point at infinity: strength R_i R_j at normal incidence and 550 nm; passing: "
      "the "
      "part of the ghost's bundle the apertures let through, over the direct image's; focus from the film at "
      "the "
      "rear focal point, + behind it)\n");
  return 0;
}

}  // namespace

CommandAction addLensGhostsCommand(CLI::App& lensApp, const CommandContext&) {
  auto options = std::make_shared<GhostsOptions>();
  CLI::App* ghosts = lensApp.add_subcommand(
      "ghosts",
      "List a lens's two-reflection ghosts (lens flare): focus, size and strength, strongest first");
  ghosts
      ->add_option("lens", options->lens,
                   "Lens file (.lens, .json, .dat, .zmx) or library name, e.g. dgauss-50mm")
      ->required();
  addLensCoatingsOption(*ghosts, options->coatings, "for the ghosts' strengths");
  ghosts->add_flag("--json", options->json, "Print JSON (distances in mm, a focus at infinity as null)");
  return [options] {
    const UserLens user = loadUserLens(options->lens, LENSRT_LENS_DIR);
    requireRealImage(user);
    return withLensErrors(user, [&] { return printGhosts(*options, user.prescription); });
  };
}

}  // namespace lensrt
