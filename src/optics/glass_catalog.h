// The built-in glass catalogue: Schott glasses by name, with n_d, V_d and,
// for most, the Sellmeier coefficients of Schott's public catalogue.
//
// Old (lead-containing) glasses that Schott replaced by an "N-" glass of the
// same optical position carry their own historical n_d and V_d with the
// replacement's Sellmeier curve (shifted to the old n_d by Dispersion; the
// tests check each pairing within 1e-4 in n_d and 0.5% in V_d). A few old glasses
// with no close successor carry n_d and V_d only (Cauchy dispersion).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "optics/glass.h"

namespace lensrt {

struct CatalogGlass {
  std::string_view name;  // as Schott spells it, e.g. "N-SK16"
  double nd = 1.0;
  double vd = 0.0;
  std::optional<Sellmeier> sellmeier;
  std::string_view curveOf;  // the glass whose Sellmeier curve an old glass borrows; empty if its own
};

// Every entry, in catalogue order.
std::span<const CatalogGlass> glassCatalog();

// The medium of a catalogue glass, by name, ignoring case ("sk16", "N-BK7");
// nullopt when the catalogue does not know it.
std::optional<Medium> findCatalogGlass(std::string_view name);

}  // namespace lensrt
