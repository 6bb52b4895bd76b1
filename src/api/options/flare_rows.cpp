// Stray light (api/flare_spec.h). Rows of the option table (api/option_table.h).
#include "api/options/rows.h"

namespace lensrt {

void addFlareRows(std::vector<Option>& table) {
  const auto add = [&table](Option o) -> Option& { return addRow(table, "flare", std::move(o)); };
  add(onOff(
      row("--flare", "flare", "on|off",
          "on: stray light in the full lens (--camera lens): every surface reflects its "
          "Fresnel share (bare glass unless --coatings), so ghosts of bright sources and "
          "veiling glare appear; off (default)",
          "on", PyValue::Switch),
      [](auto& s) -> auto& { return s.flare.on; }));
  {
    Option o = row("--flare-bounces", "flare_bounces", "0|2|4",
                   "with --flare on, the most reflections a path takes in the lens: 0, 2 (default: the "
                   "ghosts) or 4",
                   "4", PyValue::Integer);
    o = choice(
        std::move(o), [](auto& s) -> auto& { return s.flare.bounces; },
        std::vector<std::pair<std::string, int>>{{"0", 0}, {"2", 2}, {"4", 4}});
    o.applies = [](const RenderSpec& s) { return s.flare.on; };
    o.usedBy = "needs --flare on";
    add(std::move(o));
  }
  {
    Option o = row("--barrel-reflectance", "barrel_reflectance", "K",
                   "with --flare on, the diffuse reflectance K in [0, 1) of the barrel: a ray that meets a "
                   "lens's mount (outside a surface's clear aperture, not the stop) scatters back with "
                   "probability K, for veiling glare; default 0 (black)",
                   "0.25", PyValue::Number);
    o.set = [](RenderSpec& s, const std::string& text) {
      double k = -1;
      try {
        k = parseNumberIn("--barrel-reflectance", text, -1e300, 1e300);
      } catch (const UsageError&) {
        throw UsageError("--barrel-reflectance", "expected a reflectance in [0, 1), got '" + text + "'");
      }
      if (!(k >= 0.0 && k < 1.0))
        throw UsageError("--barrel-reflectance",
                         fmt::format("expected a reflectance in [0, 1), got {:g}", k));
      s.flare.barrelReflectance = k;
    };
    o.show = [](const RenderSpec& s) { return numberText(s.flare.barrelReflectance); };
    add(std::move(o));
  }
}

}  // namespace lensrt
