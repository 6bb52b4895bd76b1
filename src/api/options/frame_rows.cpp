// The frame: raster, camera node, environment. Rows of the option table (api/option_table.h).
#include "api/options/rows.h"

namespace lensrt {

void addFrameRows(std::vector<Option>& table) {
  const auto add = [&table](Option o) -> Option& { return addRow(table, "frame", std::move(o)); };
  {
    Option o =
        row("--res", "res", "WxH",
            "image size in pixels WIDTHxHEIGHT, e.g. --res 640x360; a WIDTH alone takes the height from "
            "the glTF camera's aspect ratio (default 640 wide, height from the camera's aspect ratio or "
            "360)",
            "32x18", PyValue::Pair);
    o.separator = 'x';
    o.set = [](RenderSpec& s, const std::string& text) { s.resolution = parseResolution(text); };
    o.show = [](const RenderSpec& s) {
      return s.resolution ? fmt::format("{}x{}", s.resolution->width, s.resolution->height)
                          : std::string("default");
    };
    add(std::move(o));
  }
  add(text(
      row("--camera-node", "camera_node", "NAME|INDEX",
          "camera to render: a glTF node name or index, e.g. --camera-node 3 (default: the scene's first "
          "camera, else a view framing the scene)",
          "0", PyValue::NumberOrText),
      [](auto& s) -> auto& { return s.cameraNode; }));
  {
    Option o =
        row("--env", "env", "SPEC",
            "environment light: constant:V or constant:R,G,B radiance in W/(sr m^2), a lat-long image "
            "(centre = -Z, +Y up: .exr/.hdr as linear light, .png/.jpg/.tif/.webp/... decoded from "
            "sRGB, log .dpx from Cineon), or none (the scene's own light alone), e.g. --env constant:1 "
            "(default: none when the scene's lights and emissive surfaces light it, else a uniform sky "
            "of radiance 1, with a notice saying why)",
            "constant:0.5", PyValue::NumberOrText);
    o.numberPrefix = "constant:";
    o.set = [](RenderSpec& s, const std::string& text) {
      const EnvironmentSpec e = parseEnvironment(text);
      s.environment.none = e.none;
      s.environment.constant = e.constant;
      s.environment.file = e.file;
    };
    o.show = [](const RenderSpec& s) {
      const EnvironmentSpec& e = s.environment;
      if (e.none) return std::string("none");
      if (e.constant)
        return fmt::format("constant:{},{},{}", numberText(e.constant->x), numberText(e.constant->y),
                           numberText(e.constant->z));
      return e.file.empty() ? std::string("default") : e.file;
    };
    add(std::move(o));
  }
  add(number(
      row("--env-rotate", "env_rotate", "DEG",
          "turn the environment about +Y by DEG degrees, counterclockwise seen from above (right-hand "
          "rule): at 90 the map's centre moves from -Z to -X; e.g. --env-rotate 90 (default 0)",
          "90", PyValue::Number),
      [](auto& s) -> auto& { return s.environment.rotationDegrees; }, -360.0, 360.0, "degrees"));
  add(number(
      row("--env-intensity", "env_intensity", "K",
          "multiply the environment's radiance by K (constant, map or the default sky), e.g. "
          "--env-intensity 0.5 (default 1)",
          "0.5", PyValue::Number),
      [](auto& s) -> auto& { return s.environment.intensity; }, 0.0, 1e9, "a radiance scale"));
}

}  // namespace lensrt
