// The built-in glass catalogue against its own published figures: each
// glass's Sellmeier curve must reproduce the n_d and V_d Schott prints for it.
#include "optics/glass_catalog.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

namespace lensrt {
namespace {

// The raw Schott formula, written out here (l in micrometres).
double sellmeierIndex(const Sellmeier& s, double wavelengthNm) {
  const double l2 = (wavelengthNm * 1e-3) * (wavelengthNm * 1e-3);
  double n2 = 1.0;
  for (int i = 0; i < 3; ++i) n2 += s.b[i] * l2 / (l2 - s.c[i]);
  return std::sqrt(n2);
}

TEST(GlassCatalog, SellmeierGivesEachGlassItsNdAndVd) {
  int withCurve = 0;
  for (const CatalogGlass& g : glassCatalog()) {
    SCOPED_TRACE(std::string(g.name));
    if (!g.sellmeier) continue;
    ++withCurve;
    const double nd = sellmeierIndex(*g.sellmeier, kWavelengthDNm);
    const double nF = sellmeierIndex(*g.sellmeier, kWavelengthFNm);
    const double nC = sellmeierIndex(*g.sellmeier, kWavelengthCNm);
    EXPECT_NEAR(nd, g.nd, 1e-4);
    // V_d from the catalogue n_d (the one the renderer traces with).
    const double vd = (g.nd - 1.0) / (nF - nC);
    EXPECT_NEAR(vd / g.vd, 1.0, 0.005);
  }
  EXPECT_GE(withCurve, 30);
}

TEST(GlassCatalog, KnowsTheClassicNamesIgnoringCase) {
  for (const char* name : {"BK7", "N-BK7", "F2", "N-F2", "SF1", "SF2", "SF5", "SF10", "SK4", "SK16", "N-SK16",
                           "LAF2", "PSK3", "BAF4", "KF9", "N-LAK9", "sk16", "n-bk7"}) {
    SCOPED_TRACE(name);
    const std::optional<Medium> m = findCatalogGlass(name);
    ASSERT_TRUE(m.has_value());
    EXPECT_GT(m->nd, 1.4);
    EXPECT_GT(m->vd, 20.0);
  }
  // N-BK7 from Schott's data sheet.
  const Medium bk7 = *findCatalogGlass("n-bk7");
  EXPECT_DOUBLE_EQ(bk7.nd, 1.5168);
  EXPECT_NEAR(Dispersion::of(bk7).index(kWavelengthFNm), 1.52238, 2e-5);
  EXPECT_FALSE(findCatalogGlass("UNOBTAINIUM").has_value());
  EXPECT_FALSE(findCatalogGlass("").has_value());
}

TEST(GlassCatalog, NamesAreUnique) {
  std::set<std::string> names;
  for (const CatalogGlass& g : glassCatalog()) EXPECT_TRUE(names.insert(std::string(g.name)).second) << g.name;
}

}  // namespace
}  // namespace lensrt
