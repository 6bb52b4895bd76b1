// The camera (api/camera_spec.h). Rows of the option table (api/option_table.h).
#include <optional>

#include "api/camera_models.h"
#include "api/options/rows.h"
#include "camera/lens_movements.h"

namespace lensrt {

void addCameraRows(std::vector<Option>& table) {
  const auto add = [&table](Option o) -> Option& { return addRow(table, "camera", std::move(o)); };
  {
    std::vector<std::pair<std::string, CameraModel>> models;
    for (const CameraModelInfo& m : cameraModels()) models.emplace_back(m.name, m.model);
    add(choice(
            row("--camera", "camera", "MODEL",
                "camera model: pinhole, thin (ideal thin lens), thick (the lens's paraxial model) or lens "
                "(traced through every element of --lens); default pinhole",
                "thin", PyValue::Text),
            [](auto& s) -> auto& { return s.camera.model; }, models))
        .commands = kRenderCommand;
  }
  {
    Option& o = add(text(
        row("--lens", "lens", "FILE|NAME",
            "lens prescription: a .dat/.lens/.json/.zmx file or a library name, e.g. --lens "
            "dgauss-50mm; the thin, thick and pinhole models then derive from it",
            "dgauss-50mm", PyValue::Path),
        [](auto& s) -> auto& { return s.camera.lens; }));
    o.applies = notPinhole;
    o.usedBy =
        "gives the pinhole only its field of view; --camera lens traces it (thin and thick take its "
        "paraxial data)";
  }
  {
    Option o = row("--fstop", "fstop", "N|KEYFRAMES",
                   "f-number N, e.g. --fstop 2.8, or keyframes SECONDS:N,... read at --time, e.g. 0:2,1:8 "
                   "(default: the lens wide open, else 2.8)",
                   "4", PyValue::NumberOrText);
    o.set = [](RenderSpec& s, const std::string& text) {
      if (isKeyframes(text)) {
        s.camera.fNumberKeys = parseKeyframes(
            "--fstop", text, [](double n) { return n >= 0.5 && n <= 1024.0; },
            "an f-number from 0.5 to 1024");
        s.camera.fNumber.reset();
      } else {
        s.camera.fNumber = parseNumberIn("--fstop", text, 0.5, 1024.0, "the f-number");
        s.camera.fNumberKeys.clear();
      }
    };
    o.show = [](const RenderSpec& s) {
      return !s.camera.fNumberKeys.empty() ? keyframesText(s.camera.fNumberKeys)
             : s.camera.fNumber            ? numberText(*s.camera.fNumber)
                                           : std::string("default");
    };
    o.applies = [](const RenderSpec& s) {
      return notPinhole(s) || s.camera.film == FilmQuantity::Irradiance;
    };
    o.usedBy =
        "does nothing with the pinhole's radiance film: it applies to --camera thin, thick or lens (or "
        "to the pinhole's --film irradiance)";
    add(std::move(o));
  }
  {
    Option o = row("--focus", "focus", "METRES|auto|inf|KEYFRAMES",
                   "focus distance in metres from the entrance pupil, 'auto' (what the centre pixel, or "
                   "--focus-pixel, sees), 'inf', or keyframes SECONDS:METRES,... read at --time (a rack "
                   "focus, e.g. 0:1.2,2:4); default auto",
                   "2", PyValue::NumberOrText);
    o.set = [](RenderSpec& s, const std::string& text) {
      s.camera.focusKeys.clear();
      s.camera.focusMetres.reset();
      if (isKeyframes(text))
        s.camera.focusKeys = parseKeyframes(
            "--focus", text, [](double m) { return m > 0.0; }, "METRES");
      else
        s.camera.focusMetres = parseFocusDistance(text);
    };
    o.show = [](const RenderSpec& s) {
      return !s.camera.focusKeys.empty() ? keyframesText(s.camera.focusKeys)
             : s.camera.focusMetres      ? numberText(*s.camera.focusMetres)
                                         : std::string("auto");
    };
    o.applies = [](const RenderSpec& s) { return notPinhole(s) || !s.camera.lens.empty(); };
    o.usedBy = "does nothing with the pinhole without --lens: it applies to --camera thin, thick or lens";
    add(std::move(o));
  }
  {
    Option o = row("--focus-pixel", "focus_pixel", "X,Y",
                   "pixel X,Y that --focus auto focuses on, e.g. 320,180", "2,3", PyValue::Pair);
    o.set = [](RenderSpec& s, const std::string& text) {
      const std::optional<Vec2d> p = parseNumberPair(text, ',');
      if (!p) throw UsageError("--focus-pixel", "expected X,Y in pixels, got '" + text + "'");
      s.camera.focusPixel = *p;
    };
    o.show = [](const RenderSpec& s) {
      return s.camera.focusPixel
                 ? numberText(s.camera.focusPixel->x) + "," + numberText(s.camera.focusPixel->y)
                 : std::string("centre");
    };
    o.applies = [](const RenderSpec& s) { return notPinhole(s) || !s.camera.lens.empty(); };
    o.usedBy = "does nothing with the pinhole without --lens: it applies to --camera thin, thick or lens";
    add(std::move(o));
  }
  {
    Option o = row("--sensor", "sensor", "WxH|NAME",
                   "sensor size WxH in mm or full-frame (36x24), aps-c (23.6x15.6), mft (17.3x13), 1in "
                   "(13.2x8.8); cropped to the image's aspect ratio; default full-frame",
                   "aps-c", PyValue::Pair);
    o.separator = 'x';
    o.set = [](RenderSpec& s, const std::string& text) { s.camera.sensorMm = parseSensor(text); };
    o.show = [](const RenderSpec& s) {
      return numberText(s.camera.sensorMm.x) + "x" + numberText(s.camera.sensorMm.y);
    };
    add(std::move(o));
  }
  {
    Option o =
        row("--blades", "blades", "N",
            "aperture blades: 0 for a round aperture, else 3..64 (a regular polygon)", "6", PyValue::Integer);
    o.set = [](RenderSpec& s, const std::string& text) {
      const auto n = parseIntegerIn("--blades", text, 0, 64, "0 for a round aperture, else 3 or more");
      if (n == 1 || n == 2)
        throw UsageError("--blades", fmt::format("{} blades: an aperture needs 0 (round) or 3 to 64", n));
      s.camera.blades = int(n);
    };
    o.show = [](const RenderSpec& s) { return std::to_string(s.camera.blades); };
    o.applies = notPinhole;
    o.usedBy = kLensModels;
    add(std::move(o));
  }
  {
    Option& o = add(number(
        row("--blade-rotation", "blade_rotation", "DEG", "rotation of the blade polygon in degrees, e.g. 15",
            "15", PyValue::Number),
        [](auto& s) -> auto& { return s.camera.bladeRotationDegrees; }, -360.0, 360.0, "degrees"));
    o.applies = [](const RenderSpec& s) { return notPinhole(s) && s.camera.blades > 0; };
    o.usedBy = "turns the blades of --blades N with --camera thin, thick or lens; a round aperture has none";
  }
  add(optionalNumber(
      row("--focal-length", "focal_length", "MM",
          "focal length in mm: without --lens the thin lens's and pinhole's (default: from the "
          "glTF camera's field of view); with --lens the design is scaled to it",
          "35", PyValue::Number),
      [](auto& s) -> auto& { return s.camera.focalLengthMm; }, 0.1, 10000.0, "mm"));
  add(choice(
      row("--exposure", "exposure", "MODE",
          "normalized (an ideal lens records the scene radiance on axis at any f-number; default) or "
          "physical (exposure H = E t, 1.0 = ISO 12232 saturation: value = 683 E t ISO / 78)",
          "physical", PyValue::Text),
      [](auto& s) -> auto& { return s.camera.exposure; },
      std::vector<std::pair<std::string, ExposureMode>>{{"normalized", ExposureMode::Normalized},
                                                        {"physical", ExposureMode::Physical}}));
  {
    Option& o = add(optionalNumber(
        row("--iso", "iso", "N", "ISO speed for --exposure physical (default 100)", "400", PyValue::Number),
        [](auto& s) -> auto& { return s.camera.iso; }, 1.0, 1e7, "ISO speed"));
    o.applies = [](const RenderSpec& s) { return s.camera.exposure == ExposureMode::Physical; };
    o.usedBy = "only applies with --exposure physical; ignored";
  }
  {
    Option& o = add(onOff(
        row("--dispersion", "dispersion", "on|off",
            "on (default): when --lens has dispersion data (Abbe numbers), each sample is traced at its own "
            "wavelength: colour fringes with --camera lens, a focal length per wavelength with thin and "
            "thick; off: every ray at the d line (587.6 nm)",
            "off", PyValue::Switch),
        [](auto& s) -> auto& { return s.camera.dispersion; }));
    o.applies = notPinhole;
    o.usedBy = kLensModels;
  }
  {
    Option& o = add(onOff(
        row("--diffraction", "diffraction", "on|off",
            "on: bend each camera ray by the Fraunhofer far field of the stop's shape (round, --blades, "
            "--aperture-mask) at the ray's wavelength: the Airy disc of radius 1.22 lambda N and the "
            "blades' starbursts; thin, thick and the full lens (default off: geometric rays)",
            "on", PyValue::Switch),
        [](auto& s) -> auto& { return s.camera.diffraction; }));
    o.applies = notPinhole;
    o.usedBy = kLensModels;
  }
  {
    Option o =
        row("--film", "film", "radiance|irradiance",
            "what a pixel records: radiance (the mean radiance along the camera rays, no cos^4, no "
            "bellows factor, no exposure scale: pbrt's, Cycles' and Mitsuba's pinhole; the pinhole's "
            "default, pinhole only) or irradiance (the physical film, scaled by --exposure; the default "
            "of thin, thick and lens)",
            "irradiance", PyValue::Text);
    add(choice(
        std::move(o), [](auto& s) -> auto& { return s.camera.film; },
        std::vector<std::pair<std::string, std::optional<FilmQuantity>>>{
            {"radiance", FilmQuantity::Radiance}, {"irradiance", FilmQuantity::Irradiance}}));
  }

  {
    Option o = row("--shift", "shift", "X,Y",
                   "lens movements: the film slides X,Y mm in its plane (x right, y up as the picture is "
                   "seen), so the frame's centre shows what the unshifted film showed at X,Y: --shift 0,8 "
                   "is a rising front that keeps a building's verticals parallel; at most the sensor's width "
                   "and height (default 0,0)",
                   "0,8", PyValue::Pair);
    o.set = [](RenderSpec& s, const std::string& text) {
      const std::optional<Vec2d> p = parseNumberPair(text, ',');
      if (!p) throw UsageError("--shift", "expected X,Y in mm (e.g. 0,8), got '" + text + "'");
      s.camera.movements.shiftMm = *p;
    };
    o.show = [](const RenderSpec& s) {
      return numberText(s.camera.movements.shiftMm.x) + "," + numberText(s.camera.movements.shiftMm.y);
    };
    add(std::move(o));
  }
  {
    Option o = row("--tilt", "tilt", "DEG[,AXIS]",
                   "lens movements: the film tilts DEG degrees against the lens about a line through the "
                   "axis at AXIS degrees from the picture's horizontal (0: a tilt, 90: a swing), and the "
                   "plane of sharp focus turns by the Scheimpflug rule about the hinge line f / sin(DEG) "
                   "from the lens; positive DEG swings it down toward the ground, e.g. --tilt 4 "
                   "(|DEG| <= 30; default 0)",
                   "4", PyValue::Pair);
    o.set = [](RenderSpec& s, const std::string& text) {
      double tilt = 0, axis = 0;
      if (const std::optional<Vec2d> p = parseNumberPair(text, ',')) {
        tilt = p->x, axis = p->y;
      } else {
        tilt = parseNumberIn("--tilt", text, -kMaxTiltDegrees, kMaxTiltDegrees, "degrees");
      }
      if (!(std::abs(tilt) <= kMaxTiltDegrees) || !(std::abs(axis) <= kMaxTiltAxisDegrees))
        throw UsageError("--tilt",
                         fmt::format("expected DEG[,AXIS] in degrees with |DEG| <= {:g} and |AXIS| <= "
                                     "{:g}, got '{}'",
                                     kMaxTiltDegrees, kMaxTiltAxisDegrees, text));
      s.camera.movements.tiltDegrees = tilt;
      s.camera.movements.tiltAxisDegrees = axis;
    };
    o.show = [](const RenderSpec& s) {
      const LensMovements& m = s.camera.movements;
      return m.tiltAxisDegrees != 0 ? numberText(m.tiltDegrees) + "," + numberText(m.tiltAxisDegrees)
                                    : numberText(m.tiltDegrees);
    };
    o.applies = notPinhole;
    o.usedBy =
        "does nothing with the pinhole (it has no plane of focus to tilt): it applies to --camera thin, "
        "thick or lens";
    add(std::move(o));
  }
  // The rows of one model alone sit in its file (api/<name>_model.cpp).
  for (const CameraModelInfo& m : cameraModels())
    if (m.addRows) m.addRows(table);
}

}  // namespace lensrt
