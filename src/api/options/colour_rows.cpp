// Colour (api/colour_spec.h). Rows of the option table (api/option_table.h).
#include <cstdlib>
#include <optional>

#include "api/options/rows.h"
#include "color/color_space.h"

namespace lensrt {

void addColourRows(std::vector<Option>& table) {
  const auto add = [&table](Option o) -> Option& { return addRow(table, "colour", std::move(o)); };
  add(choice(
      row("--spectral", "spectral", "on|off|auto",
          "auto (default): spectral where the image depends on wavelengths (a camera response, "
          "--white-balance or --output-space, dispersive scene glass, a lens traced with "
          "dispersion or coatings under flare, --diffraction on), RGB elsewhere, which reaches "
          "the same error sooner; the EXR's lensrt:transport says which and why. on: light "
          "travels at four wavelengths per sample (a hero and three rotated copies), glTF colours "
          "upsampled to smooth spectra, the film the CIE 1931 observer in linear sRGB; scene glass "
          "with KHR_materials_dispersion and the lens disperse in the same transport. off: RGB "
          "transport",
          "on", PyValue::Switch),
      [](auto& s) -> auto& { return s.colour.transport; },
      std::vector<std::pair<std::string, Transport>>{
          {"on", Transport::Spectral}, {"off", Transport::Rgb}, {"auto", Transport::Auto}}));
  add(text(
      row("--sensor-response", "sensor_response", "NAME|FILE.csv",
          "the sensor's spectral response with --spectral on or auto: cie1931 (default; the CIE 1931 "
          "observer, "
          "colorimetric), a camera from `lensrt sensor list`, or a CSV file of wavelength_nm,r,g,b",
          "nikon-d850", PyValue::Path),
      [](auto& s) -> auto& { return s.colour.sensorResponse; }));
  {
    Option o =
        row("--white-balance", "white_balance", "auto|none|KELVIN",
            "none (the default for cie1931: RGB (1,1,1) light is D65 and records white), auto (balance "
            "to the scene's most powerful light; the default for cameras) or a colour temperature in "
            "K, e.g. 3200 (a black body below 4000 K, CIE daylight above): a grey card under that "
            "light records grey (Bradford adaptation)",
            "3200", PyValue::NumberOrText);
    o.set = [](RenderSpec& s, const std::string& text) {
      constexpr double kMin = 1500, kMax = 25000;
      WhiteBalance wb;
      if (text == "none") {
        wb.kind = WhiteBalance::Kind::None;
      } else if (text == "auto") {
        wb.kind = WhiteBalance::Kind::Auto;
      } else {
        std::string n = text;
        if (!n.empty() && (n.back() == 'K' || n.back() == 'k')) n.pop_back();
        char* end = nullptr;
        const double k = std::strtod(n.c_str(), &end);
        if (n.empty() || *end != '\0' || !(k >= kMin && k <= kMax))
          throw UsageError(
              "--white-balance",
              fmt::format("expected auto, none or a colour temperature from {:g} to {:g} K (e.g. "
                          "5500), got '{}'",
                          kMin, kMax, text));
        wb = {WhiteBalance::Kind::Kelvin, k};
      }
      s.colour.whiteBalance = wb;
    };
    o.show = [](const RenderSpec& s) {
      if (!s.colour.whiteBalance) return std::string("default");
      switch (s.colour.whiteBalance->kind) {
        case WhiteBalance::Kind::None:
          return std::string("none");
        case WhiteBalance::Kind::Auto:
          return std::string("auto");
        case WhiteBalance::Kind::Kelvin:
          break;
      }
      return numberText(s.colour.whiteBalance->kelvin) + "K";
    };
    add(std::move(o));
  }
  {
    Option o = row("--output-space", "output_space", "SPACE",
                   "the RGB of the image: srgb (linear Rec. 709 primaries, D65), rec2020, acescg (AP1, ACES "
                   "white), xyz (CIE XYZ), or camera (the camera response's own RGB); the EXR's "
                   "chromaticities say which. PNG and JPEG previews need srgb",
                   "acescg", PyValue::Text);
    o.set = [](RenderSpec& s, const std::string& text) {
      if (text == "camera") {
        s.colour.outputSpace.reset();
        return;
      }
      const std::optional<ColorSpaceId> id = parseColorSpace(text);
      if (!id)
        throw UsageError("--output-space",
                         "expected srgb, rec2020, acescg, xyz or camera, got '" + text + "'");
      s.colour.outputSpace = *id;
    };
    o.show = [](const RenderSpec& s) {
      return s.colour.outputSpace ? std::string(colorSpace(*s.colour.outputSpace).name)
                                  : std::string("camera");
    };
    add(std::move(o));
  }
}

}  // namespace lensrt
