#include "api/lens_ghosts.h"

namespace lensrt {

nlohmann::json lensGhostsJson(const LensPrescription& lens, Coating coating,
                              const std::vector<GhostPath>& ghosts) {
  nlohmann::json list = nlohmann::json::array();
  for (const GhostPath& g : ghosts)
    list.push_back({{"surfaces", {g.first + 1, g.second + 1}},
                    {"strength", g.strength},
                    {"passing", g.passing},
                    {"relative_flux", g.strength * g.passing},
                    {"focus_from_film_mm", g.focusFromFilmMm ? nlohmann::json(*g.focusFromFilmMm) : nullptr},
                    {"size_on_film_mm", g.sizeOnFilmMm}});
  return {{"lens", lens.name.empty() ? lens.file : lens.name},
          {"coatings", coatingName(coating)},
          {"ghosts", list}};
}

}  // namespace lensrt
