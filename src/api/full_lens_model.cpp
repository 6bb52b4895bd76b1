// The full lens: every element traced (Kolb et al.), with its stop's shape
// (blades or a mask), coatings and stray light; and the settings only it
// takes (its rows of the option table).
#include "api/aperture_mask_file.h"
#include "api/camera_models.h"
#include "api/options/rows.h"
#include "camera/lens_camera.h"

namespace lensrt {
namespace {

void addFullLensRows(std::vector<Option>& table) {
  const auto add = [&table](Option o) -> Option& { return addRow(table, "camera", std::move(o)); };
  {
    Option o =
        row("--aperture-mask", "aperture_mask", "FILE",
            "grey-scale image (PNG, JPEG, BMP or TGA) over the stop of --camera lens, white transmits: "
            "bokeh takes its shape; instead of --blades",
            "mask.png", PyValue::Path);
    o.set = [](RenderSpec& s, const std::string& text) { s.camera.apertureMask = text; };
    o.show = [](const RenderSpec& s) { return s.camera.apertureMask.string(); };
    add(std::move(o));
  }
  {
    Option o = row("--coatings", "coatings", "none|single|multi",
                   "Fresnel losses in the full lens (--camera lens): none (uncoated glass), single (a "
                   "quarter-wave MgF2 layer at 550 nm) or multi (0.5% reflectance per surface); default: "
                   "lossless glass, as pbrt",
                   "single", PyValue::Text);
    o = choice(
        std::move(o), [](auto& s) -> auto& { return s.camera.coatings; },
        std::vector<std::pair<std::string, std::optional<Coating>>>{
            {"none", Coating::None}, {"single", Coating::Single}, {"multi", Coating::Multi}});
    o.applies = [](const RenderSpec& s) { return s.camera.model == CameraModel::Lens; };
    o.usedBy = "does nothing here: the full lens's surfaces (--camera lens) have coatings";
    add(std::move(o));
  }
}

}  // namespace

CameraModelInfo fullLensModel() {
  return {CameraModel::Lens,
          "lens",
          "traced through every element of the lens",
          true,
          [](const CameraBuild& b) -> std::unique_ptr<Camera> {
            const CameraSpec& o = b.spec;
            LensCameraParams p;
            if (!o.apertureMask.empty()) {
              p.mask = std::make_shared<const ApertureMask>(readApertureMask(o.apertureMask.string()));
            }
            p.fNumber = b.fNumber;
            p.focusMetres = b.focusMetres;
            p.aperture = b.aperture;
            p.dispersion = o.dispersion;
            p.movements = b.movements;
            p.diffraction = o.diffraction;
            p.coatings = o.coatings;
            if (b.flare.on) {
              p.flareReflections = b.flare.bounces;
              p.barrelReflectance = b.flare.barrelReflectance;
              // Stray light needs reflecting surfaces: bare glass unless --coatings says otherwise.
              if (!p.coatings) p.coatings = Coating::None;
            }
            auto camera =
                std::make_unique<LensCamera>(b.worldFromCamera, b.film, *b.lens, p, b.exposure, b.warnings);
            if (b.flareLens && camera->flare()) *b.flareLens = camera.get();
            return camera;
          },
          addFullLensRows};
}

}  // namespace lensrt
