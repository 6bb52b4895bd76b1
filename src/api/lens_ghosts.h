// `lensrt lens ghosts`: a lens's two-reflection ghosts (optics/ghosts.h),
// strongest first, as JSON (the command prints it as text or JSON).
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "optics/coating.h"
#include "optics/ghosts.h"
#include "optics/prescription.h"

namespace lensrt {

// Surfaces are numbered from 1 at the front, as lens files and diagrams
// number them; distances in mm, a focus at infinity as null.
nlohmann::json lensGhostsJson(const LensPrescription& lens, Coating coating,
                              const std::vector<GhostPath>& ghosts);

}  // namespace lensrt
