#include "api/option_table.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <utility>

#include "api/camera_factory.h"
#include "api/camera_models.h"
#include "api/option_parsers.h"
#include "core/error.h"
#include "render/adaptive_sampling.h"
#include "sensor/mosaic.h"

namespace lensrt {
namespace {

// Row builders. `get` is a generic lambda giving the field of a spec, const
// or not, so one accessor serves the parser and show.
Option row(std::string flag, std::string keyword, std::string valueName, std::string help,
           std::string example, PyValue python) {
  Option o;
  o.flag = std::move(flag);
  o.keyword = std::move(keyword);
  o.valueName = std::move(valueName);
  o.help = std::move(help);
  o.example = std::move(example);
  o.python = python;
  return o;
}

template <class Get>
Option number(Option o, Get get, double lo, double hi, std::string what) {
  const std::string flag = o.flag;
  o.set = [=](RenderSpec& s, const std::string& t) { get(s) = parseNumberIn(flag, t, lo, hi, what); };
  o.show = [=](const RenderSpec& s) { return numberText(get(s)); };
  return o;
}

template <class Get>
Option optionalNumber(Option o, Get get, double lo, double hi, std::string what) {
  const std::string flag = o.flag;
  o.set = [=](RenderSpec& s, const std::string& t) { get(s) = parseNumberIn(flag, t, lo, hi, what); };
  o.show = [=](const RenderSpec& s) { return get(s) ? numberText(*get(s)) : std::string("default"); };
  return o;
}

template <class Get>
Option integer(Option o, Get get, std::int64_t lo, std::int64_t hi, std::string what) {
  const std::string flag = o.flag;
  o.set = [=](RenderSpec& s, const std::string& t) {
    get(s) = static_cast<std::remove_reference_t<decltype(get(s))>>(parseIntegerIn(flag, t, lo, hi, what));
  };
  o.show = [=](const RenderSpec& s) { return std::to_string(get(s)); };
  return o;
}

template <class Get>
Option onOff(Option o, Get get) {
  const std::string flag = o.flag;
  o.set = [=](RenderSpec& s, const std::string& t) { get(s) = parseSwitch(flag, t); };
  o.show = [=](const RenderSpec& s) { return std::string(get(s) ? "on" : "off"); };
  return o;
}

template <class Get, class Value>
Option choice(Option o, Get get, std::vector<std::pair<std::string, Value>> values) {
  const std::string flag = o.flag;
  std::vector<std::string> names;
  for (const auto& v : values) names.push_back(v.first);
  o.set = [=](RenderSpec& s, const std::string& t) { get(s) = values[parseOneOf(flag, t, names)].second; };
  o.show = [=](const RenderSpec& s) {
    for (const auto& v : values)
      if (Value(get(s)) == v.second) return v.first;
    return std::string("default");
  };
  return o;
}

template <class Get>
Option text(Option o, Get get) {
  o.set = [=](RenderSpec& s, const std::string& t) { get(s) = t; };
  o.show = [=](const RenderSpec& s) { return std::string(get(s)); };
  return o;
}

bool notPinhole(const RenderSpec& s) {
  return s.camera.model != CameraModel::Pinhole;
}

const char* kLensModels = "does nothing with the pinhole: it applies to --camera thin, thick or lens";

std::string checkedCrop(const std::string& t) {
  int v[4];
  char end = 0;
  if (std::sscanf(t.c_str(), "%d,%d,%d,%d%c", &v[0], &v[1], &v[2], &v[3], &end) != 4)
    throw UsageError("--crop", "expected X0,X1,Y0,Y1 in pixels, e.g. --crop 0,320,0,180");
  if (v[0] < 0 || v[2] < 0 || v[1] <= v[0] || v[3] <= v[2])
    throw UsageError("--crop", "expected 0 <= X0 < X1 and 0 <= Y0 < Y1 (X1, Y1 exclusive), got " + t);
  return t;
}

std::vector<Option> makeTable() {
  std::vector<Option> t;
  std::string group;  // each section's rows fill one spec
  const auto add = [&t, &group](Option o) -> Option& {
    o.group = group;
    return t.emplace_back(std::move(o));
  };

  // --- The camera (api/camera_spec.h).
  group = "camera";
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

  // --- The shutter (api/shutter_spec.h).
  group = "shutter";
  {
    Option o = row("--shutter", "shutter", "SECONDS",
                   "shutter time in seconds, e.g. 1/125 (default 1/100): the exposure under --exposure "
                   "physical, and the motion blur of an animated scene (0: an instant)",
                   "1/250", PyValue::NumberOrText);
    o.set = [](RenderSpec& s, const std::string& text) {
      s.shutter.seconds = parseSeconds("--shutter", text);
    };
    o.show = [](const RenderSpec& s) { return numberText(s.shutter.shutterSeconds()); };
    add(std::move(o));
  }
  {
    Option o = row("--shutter-curve", "shutter_curve", "box|trapezoid:F",
                   "how the shutter opens: box (at once; default) or trapezoid:F (a leaf shutter taking the "
                   "share F <= 0.5 of --shutter to open, and again to close), e.g. --shutter-curve "
                   "trapezoid:0.2",
                   "trapezoid:0.2", PyValue::Text);
    o.set = [](RenderSpec& s, const std::string& text) {
      if (text == "box") {
        s.shutter.rampFraction = 0;
        return;
      }
      const std::string prefix = "trapezoid:";
      std::optional<double> f;
      if (text.starts_with(prefix)) {
        try {
          f = parseNumberFrom("--shutter-curve", text.substr(prefix.size()), 0.0, "", true);
        } catch (const UsageError&) {
        }
      }
      if (!f || *f > 0.5)
        throw UsageError(
            "--shutter-curve",
            fmt::format("expected box or trapezoid:F with 0 < F <= 0.5 (the share of the interval the "
                        "shutter takes to open, and to close), got '{}'",
                        text));
      s.shutter.rampFraction = *f;
    };
    o.show = [](const RenderSpec& s) {
      return s.shutter.rampFraction > 0 ? "trapezoid:" + numberText(s.shutter.rampFraction)
                                        : std::string("box");
    };
    add(std::move(o));
  }
  {
    Option o = row("--rolling-shutter", "rolling_shutter", "SECONDS",
                   "a CMOS rolling shutter: each row starts its exposure later by READOUT x row / rows, e.g. "
                   "--rolling-shutter 1/30 (default: a global shutter)",
                   "1/30", PyValue::NumberOrText);
    o.set = [](RenderSpec& s, const std::string& text) {
      s.shutter.readoutSeconds = parseSeconds("--rolling-shutter", text);
    };
    o.show = [](const RenderSpec& s) { return numberText(s.shutter.readoutSeconds); };
    add(std::move(o));
  }
  {
    using R = ShutterTiming::Readout;
    Option& o = add(choice(
        row("--readout", "readout", "DIRECTION",
            "the rolling shutter's direction in the image as seen: top-down (default), "
            "bottom-up, left-right or right-left",
            "left-right", PyValue::Text),
        [](auto& s) -> auto& { return s.shutter.readout; },
        std::vector<std::pair<std::string, R>>{{"top-down", R::TopDown},
                                               {"bottom-up", R::BottomUp},
                                               {"left-right", R::LeftRight},
                                               {"right-left", R::RightLeft}}));
    o.applies = [](const RenderSpec& s) { return s.shutter.readoutSeconds > 0; };
    o.usedBy = "is the direction of a rolling shutter: it needs --rolling-shutter SECONDS";
  }

  // --- Stray light (api/flare_spec.h).
  group = "flare";
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

  // --- Colour (api/colour_spec.h).
  group = "colour";
  add(onOff(
      row("--spectral", "spectral", "on|off",
          "on (default): light travels at four wavelengths per sample (a hero and three rotated "
          "copies), glTF colours upsampled to smooth spectra, the film the CIE 1931 observer in "
          "linear sRGB; scene glass with KHR_materials_dispersion and the lens disperse in the same "
          "transport. off: RGB transport",
          "off", PyValue::Switch),
      [](auto& s) -> auto& { return s.colour.spectral; }));
  add(text(
      row("--sensor-response", "sensor_response", "NAME|FILE.csv",
          "the sensor's spectral response with --spectral on: cie1931 (default; the CIE 1931 observer, "
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

  // --- The sensor's readout (api/sensor_spec.h).
  group = "sensor";
  add(onOff(
      row("--noise", "noise", "on|off",
          "on: the sensor reads the exposure out as a camera does: photo-electrons (from the lux "
          "seconds on a pixel with --exposure physical, else 1.0 = full well), shot noise, dark "
          "current, read noise, PRNU/DSNU, full-well clipping, ISO gain and ADC; R,G,B hold the "
          "reading, noiseless.R/G/B the render (default off)",
          "on", PyValue::Switch),
      [](auto& s) -> auto& { return s.sensor.noise; }));
  add(text(
      row("--sensor-params", "sensor_params", "NAME|FILE.json",
          "the sensor for --noise on: a preset (default, full-frame, smartphone, machine-vision) or a "
          "JSON file of full_well_e, gain_dn_per_e, base_iso, read_noise_e, dark_current_e_per_s, "
          "prnu_percent, dsnu_percent, adc_bits, black_level_dn, quantum_efficiency (see README)",
          "smartphone", PyValue::Path),
      [](auto& s) -> auto& { return s.sensor.params; }));

  // --- Samples and the integrator (api/render_spec.h's SamplingSpec).
  group = "sampling";
  {
    Option& o = add(integer(
        row("--spp", "spp", "N",
            "samples per pixel (>= 1; with --noise-threshold, the most a pixel takes), e.g. "
            "--spp 64 (default 16)",
            "64", PyValue::Integer),
        [](auto& s) -> auto& { return s.sampling.spp; }, 1, 1 << 24, "samples per pixel"));
    // A render resumed to more samples is the same render.
    o.identity = Identity::Extent;
  }
  {
    Option o = row("--noise-threshold", "noise_threshold", "E",
                   "adaptive sampling: a pixel stops once the relative standard error of its mean is below "
                   "this (dark pixels: of a floor of 0.05), between --min-spp and --spp samples, e.g. "
                   "--noise-threshold 0.01",
                   "0.05", PyValue::Number);
    o.set = [](RenderSpec& s, const std::string& text) {
      s.sampling.noiseThreshold = parseNumberFrom("--noise-threshold", text, 0,
                                                  "the relative standard error at which a pixel stops", true);
    };
    o.show = [](const RenderSpec& s) {
      return s.sampling.noiseThreshold > 0 ? numberText(s.sampling.noiseThreshold) : std::string("default");
    };
    add(std::move(o));
  }
  {
    Option& o = add(row("--min-spp", "min_spp", "N",
                        "adaptive sampling: samples every pixel takes before it may stop (default 16), e.g. "
                        "--min-spp 32",
                        "4", PyValue::Integer));
    o.set = [](RenderSpec& s, const std::string& text) {
      s.sampling.minSpp = int(parseIntegerIn("--min-spp", text, 1, 1 << 24, "samples per pixel"));
    };
    o.show = [](const RenderSpec& s) {
      return s.sampling.minSpp ? std::to_string(*s.sampling.minSpp) : std::string("default");
    };
  }
  {
    Option o = row("--seed", "seed", "N", "random seed; same seed, same image on any machine, e.g. --seed 7",
                   "7", PyValue::Integer);
    o.set = [](RenderSpec& s, const std::string& text) {
      s.sampling.seed = parseUnsignedIn("--seed", text, 0, std::numeric_limits<std::uint64_t>::max());
    };
    o.show = [](const RenderSpec& s) { return std::to_string(s.sampling.seed); };
    add(std::move(o));
  }
  add(integer(
      row("--max-depth", "max_depth", "N",
          "maximum scattering events per path (0: emitters only, 1: direct light), e.g. --max-depth 8 "
          "(default 8)",
          "3", PyValue::Integer),
      [](auto& s) -> auto& { return s.sampling.maxDepth; }, 0, 1024, "scattering events per path"));
  {
    Option o = row("--light-sampler", "light_sampler", "tree|power",
                   "how next-event estimation picks a light: tree (a light tree, by what each light can give "
                   "the shading point: for many lights; default) or power (by power alone, wherever the "
                   "point), e.g. --light-sampler power",
                   "power", PyValue::Text);
    o.set = [](RenderSpec& s, const std::string& text) {
      const std::optional<LightSampling> sampling = parseLightSampling(text);
      if (!sampling) throw UsageError("--light-sampler", "expected tree or power, got '" + text + "'");
      s.sampling.lightSampling = *sampling;
    };
    o.show = [](const RenderSpec& s) { return std::string(lightSamplingName(s.sampling.lightSampling)); };
    add(std::move(o));
  }
  add(integer(
          row("--threads", "threads", "N", "worker threads (0: all cores), e.g. --threads 4", "2",
              PyValue::Integer),
          [](auto& s) -> auto& { return s.sampling.threads; }, 0, 4096, "worker threads, 0 for all cores"))
      .identity = Identity::None;
  {
    Option& o = add(integer(
        row("--tile-size", "tile_size", "PIXELS",
            "tile size in pixels for scheduling threads (does not change the image; default "
            "16)",
            "8", PyValue::Integer),
        [](auto& s) -> auto& { return s.sampling.tileSize; }, 1, 4096, "pixels"));
    o.identity = Identity::None;
  }

  // --- The frame: raster, camera node, environment.
  group = "frame";
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

  // --- Outputs.
  group = "output";
  {
    Option o = row("--aov", "aov", "NAMES",
                   "extra EXR channels, comma separated: depth (depth.Z, metres), normal (normal.X/Y/Z, "
                   "world), albedo (albedo.R/G/B), variance (variance.R/G/B of the pixel mean), e.g. --aov "
                   "depth,variance",
                   "depth", PyValue::List);
    o.repeatable = true;
    o.set = [](RenderSpec& s, const std::string& text) {
      std::vector<std::string> names;
      std::size_t start = 0;
      while (start <= text.size()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        if (comma > start) names.push_back(text.substr(start, comma - start));
        start = comma + 1;
      }
      const AovSelection more = parseAovs(names);
      s.aovs.depth |= more.depth;
      s.aovs.normal |= more.normal;
      s.aovs.albedo |= more.albedo;
      s.aovs.variance |= more.variance;
    };
    o.show = [](const RenderSpec& s) {
      std::string names;
      for (const auto& [on, name] :
           {std::pair{s.aovs.depth, "depth"}, std::pair{s.aovs.normal, "normal"},
            std::pair{s.aovs.albedo, "albedo"}, std::pair{s.aovs.variance, "variance"}})
        if (on) {
          if (!names.empty()) names += ',';
          names += name;
        }
      return names;
    };
    add(std::move(o));
  }
  {
    Option o =
        row("--raw", "raw", "FILE.dng",
            "also write the raw file a camera would: the colour filter mosaic (--cfa) as a 16-bit linear "
            "DNG that raw developers read (with --noise on the sensor's DN; else an image value of 1.0 "
            "at the white level 65535), e.g. --raw out/a.dng",
            "a.dng", PyValue::Path);
    o = text(
        std::move(o), [](auto& s) -> auto& { return s.raw.file; });
    o.commands = kRenderCommand;
    o.identity = Identity::Output;
    add(std::move(o));
  }
  {
    Option o = row("--cfa", "cfa", "PATTERN",
                   "the raw file's colour filter pattern: RGGB (default), BGGR, GRBG or GBRG", "BGGR",
                   PyValue::Text);
    o.set = [](RenderSpec& s, const std::string& text) {
      if (!parseCfaPattern(text))
        throw UsageError("--cfa", "expected RGGB, BGGR, GRBG or GBRG, got '" + text + "'");
      s.raw.cfa = text;
    };
    o.show = [](const RenderSpec& s) { return s.raw.cfa; };
    o.commands = kRenderCommand;
    o.identity = Identity::Output;
    o.applies = [](const RenderSpec& s) { return !s.raw.file.empty(); };
    o.usedBy = "is the raw file's pattern: it needs --raw FILE.dng";
    add(std::move(o));
  }
  {
    Option o = row("--crop", "crop", "X0,X1,Y0,Y1",
                   "render only pixels X0 <= x < X1, Y0 <= y < Y1 of the frame into an EXR whose data window "
                   "places them (join parts with lensrt merge), e.g. --crop 0,320,0,180",
                   "0,16,0,8", PyValue::List);
    o.set = [](RenderSpec& s, const std::string& text) {
      checkedCrop(text);
      PixelRegion r;
      std::sscanf(text.c_str(), "%d,%d,%d,%d", &r.x0, &r.x1, &r.y0, &r.y1);
      s.crop = r;
    };
    o.show = [](const RenderSpec& s) { return s.crop ? s.crop->describe() : std::string("frame"); };
    o.commands = kRenderCommand;
    // A part of the frame: parts of one render join (lensrt merge).
    o.identity = Identity::Extent;
    add(std::move(o));
  }
  {
    Option o =
        row("--tile", "", "I/N",
            "render only tile I (from 0) of N: horizontal strips top to bottom, heights differing by at "
            "most a row (for job arrays; join with lensrt merge), e.g. --tile 0/8",
            "0/2", PyValue::Text);
    o.set = [](RenderSpec& s, const std::string& text) {
      int index = 0, count = 0;
      char end = 0;
      if (std::sscanf(text.c_str(), "%d/%d%c", &index, &count, &end) != 2)
        throw UsageError("--tile", "expected I/N (tile I of N, I from 0), e.g. --tile 0/8");
      if (count < 1 || index < 0 || index >= count)
        throw UsageError("--tile", "expected 0 <= I < N, got " + text);
      s.tile = RenderSpec::Strip{index, count};
    };
    o.show = [](const RenderSpec& s) {
      return s.tile ? fmt::format("{}/{}", s.tile->index, s.tile->count) : std::string("frame");
    };
    o.commands = kRenderCommand;
    o.identity = Identity::Extent;
    o.renderKeyword = false;
    add(std::move(o));
  }

  // --- The scene file and its moment (Python: the Scene constructor's).
  group = "scene";
  {
    Option& o = add(integer(
        row("--scene-index", "scene_index", "N",
            "which glTF scene to render (0-based; default: the file's default scene), e.g. "
            "--scene-index 1",
            "0", PyValue::Integer),
        [](auto& s) -> auto& { return s.scene.sceneIndex; }, 0, 1 << 20, "0-based"));
    o.renderKeyword = false;
  }
  {
    Option o = row("--allow-external-files", "allow_external_files", "",
                   "let the scene read files outside its folder (absolute paths, '..', symbolic links out of "
                   "it), naming each one read; only for scenes you trust (default: off, or "
                   "LENSRT_ALLOW_EXTERNAL_FILES=1)",
                   "1", PyValue::Switch);
    o.isFlag = true;
    o.environmentVariable = "LENSRT_ALLOW_EXTERNAL_FILES";
    o.renderKeyword = false;
    o.identity = Identity::None;  // what the scene reads is in its digest
    o.set = [](RenderSpec& s, const std::string& text) { s.scene.access.allowExternalFiles = text == "1"; };
    o.show = [](const RenderSpec& s) { return std::string(s.scene.access.allowExternalFiles ? "1" : "0"); };
    add(std::move(o));
  }
  {
    Option o = row("--max-texture-memory", "max_texture_memory", "MIB",
                   "MiB the scene's textures may take as held for rendering (16 bytes a texel), e.g. "
                   "--max-texture-memory 4096 (default: half this machine's memory)",
                   "4096", PyValue::Integer);
    o.set = [](RenderSpec& s, const std::string& text) {
      s.scene.access.maxTextureMiB =
          parseUnsignedIn("--max-texture-memory", text, 1, std::uint64_t{1} << 40, "MiB");
    };
    o.show = [](const RenderSpec& s) { return std::to_string(s.scene.access.maxTextureMiB); };
    o.renderKeyword = false;
    o.identity = Identity::None;  // a limit: a render it allows is the same render
    add(std::move(o));
  }
  {
    Option o = row("--time", "time", "SECONDS",
                   "when the shutter opens, in seconds of the glTF's animations, e.g. --time 1.5 (default 0)",
                   "1.5", PyValue::Number);
    o.set = [](RenderSpec& s, const std::string& text) {
      s.time.seconds = parseNumberIn("--time", text, -1e9, 1e9, "seconds");
    };
    o.show = [](const RenderSpec& s) { return numberText(s.time.atSeconds()); };
    o.renderKeyword = false;
    add(std::move(o));
  }
  {
    Option o = row("--frame", "", "N", "the same counted in frames of --fps, e.g. --frame 36", "36",
                   PyValue::Integer);
    o.set = [](RenderSpec& s, const std::string& text) {
      s.time.frame = int(parseIntegerIn("--frame", text, -1000000000, 1000000000, "a frame number"));
    };
    o.show = [](const RenderSpec& s) { return numberText(s.time.atSeconds()); };
    o.renderKeyword = false;
    add(std::move(o));
  }
  {
    Option& o = add(number(
        row("--fps", "", "F", "frames per second for --frame, e.g. --fps 30 (default 24)", "30",
            PyValue::Number),
        [](auto& s) -> auto& { return s.time.fps; }, 1e-3, 1e6, "frames per second"));
    o.renderKeyword = false;
    o.show = [](const RenderSpec& s) { return numberText(s.time.fps); };
    // Alone it changes nothing; with --frame the moment changes, which --frame's row shows.
    o.identity = Identity::None;
  }
  {
    Option& o = add(text(
        row("--animation", "animation", "NAME|INDEX",
            "which glTF animation plays: a name or a 0-based index (default: all of them)", "0",
            PyValue::NumberOrText),
        [](auto& s) -> auto& { return s.time.animation; }));
    o.renderKeyword = false;
  }
  return t;
}

}  // namespace

const std::vector<Option>& optionTable() {
  static const std::vector<Option> table = makeTable();
  return table;
}

const Option* findOption(std::string_view name) {
  for (const Option& o : optionTable())
    if (o.flag == name || o.keyword == name) return &o;
  return nullptr;
}

void checkSpec(const RenderSpec& s, unsigned command) {
  const CameraSpec& c = s.camera;
  if (!c.apertureMask.empty() && c.model != CameraModel::Lens && command == kRenderCommand)
    throw UsageError("--aperture-mask", "needs --camera lens (the mask sits at the lens's stop)");
  checkCameraSpec(c);
  if (c.exposure == ExposureMode::Physical && !(s.shutter.shutterSeconds() > 0))
    throw UsageError("--shutter", "--exposure physical records no light in a shutter time of 0");
  if (s.flare.on && c.model != CameraModel::Lens && command == kRenderCommand)
    throw UsageError("--flare", "stray light comes from the full lens's surfaces: it needs --camera lens");
  if (s.flare.barrelReflectance > 0.0 && !s.flare.on)
    throw UsageError("--barrel-reflectance", "the barrel's stray light needs --flare on");
  if (!s.colour.spectral) {
    if (!s.colour.sensorResponse.empty())
      throw UsageError("--sensor-response", "needs spectral transport (--spectral on)");
    if (s.colour.whiteBalance)
      throw UsageError("--white-balance", "needs spectral transport (--spectral on)");
    if (s.colour.outputSpace != ColorSpaceId::Srgb)
      throw UsageError("--output-space", "needs spectral transport (--spectral on)");
  }
  if (!s.sensor.noise && !s.sensor.params.empty())
    throw UsageError("--sensor-params", "describes the sensor's noise, which needs --noise on");
  if (command == kCompareCommand && (s.sensor.noise || !s.sensor.params.empty()))
    throw UsageError(s.sensor.noise ? "--noise" : "--sensor-params",
                     "lensrt compare compares the models' noiseless images; lensrt render --noise on reads "
                     "one out through a sensor");
  if (s.time.seconds && s.time.frame)
    throw UsageError("--frame", "give --time SECONDS or --frame N, not both");
  if (s.tile && s.crop) throw UsageError("--tile", "excludes --crop: give one of them");
  adaptiveSampling(s.sampling);
}

std::optional<AdaptiveSampling> adaptiveSampling(const SamplingSpec& s) {
  return adaptiveSampling(s.noiseThreshold, s.minSpp, s.spp);
}

std::vector<std::string> unusedSettings(const RenderSpec& given, const std::vector<const Option*>& rows,
                                        unsigned command) {
  RenderSpec spec = given;
  // compare renders every model: what applies to one of them is used.
  if (command == kCompareCommand) spec.camera.model = CameraModel::Lens;
  std::vector<std::string> warnings;
  for (const Option* o : rows)
    if (o->applies && !o->applies(spec)) warnings.push_back(o->flag + " " + o->usedBy);
  return warnings;
}

std::string optionsIdentity(const RenderSpec& spec) {
  static const RenderSpec defaults;
  std::string s;
  for (const Option& o : optionTable()) {
    if (o.identity != Identity::Image) continue;
    const std::string value = o.show(spec);
    const std::string name = o.keyword.empty() ? o.flag.substr(2) : o.keyword;
    if (value == o.show(defaults)) continue;
    if (!s.empty()) s += ' ';
    s.append(name).append("=").append(value);
  }
  return s;
}

std::string optionReferenceMarkdown() {
  static const std::vector<std::pair<std::string, std::string>> groups{
      {"camera", "The camera"}, {"shutter", "The shutter"}, {"flare", "Stray light"},
      {"colour", "Colour"},     {"sensor", "The sensor"},   {"sampling", "Samples and the integrator"},
      {"frame", "The frame"},   {"output", "Outputs"},      {"scene", "The scene file and its moment"}};
  std::string md =
      "# Render settings\n\n"
      "Generated by `lensrt options --markdown` from the option table (`src/api/option_table.cpp`); a test\n"
      "fails when this page differs from it. Each setting is a flag of `lensrt render` (and of `lensrt\n"
      "compare` where marked) and a keyword of Python's `Scene.render` (or of `lensrt.Scene(...)` where\n"
      "marked). *Identity*: whether it is part of the render's identity (`lensrt:options`), which "
      "`--resume`\n"
      "and `lensrt merge` check.\n";
  for (const auto& [group, title] : groups) {
    md +=
        "\n## " + title + "\n\n| flag | Python | value | identity | what it does |\n|---|---|---|---|---|\n";
    for (const Option& o : optionTable()) {
      if (o.group != group) continue;
      std::string python = o.keyword.empty() ? "(command line only)"
                           : o.renderKeyword ? "`" + o.keyword + "=`"
                                             : "`Scene(" + o.keyword + "=)`";
      std::string flag = "`" + o.flag + "`";
      if (!(o.commands & kCompareCommand)) flag += " (render)";
      static const char* kIdentity[] = {"yes", "extent", "no", "output"};
      std::string help = o.help;
      if (o.applies) help += " *Does nothing unless it applies: it " + o.usedBy + ".*";
      std::string escaped;
      for (const char c : help) escaped += c == '|' ? std::string("\\|") : std::string(1, c);
      std::string value = o.valueName;
      std::string valueEscaped;
      for (const char c : value) valueEscaped += c == '|' ? std::string("\\|") : std::string(1, c);
      md += "| " + flag + " | " + python + " | " + (valueEscaped.empty() ? "" : "`" + valueEscaped + "`") +
            " | " + kIdentity[int(o.identity)] + " | " + escaped + " |\n";
    }
  }
  return md;
}

namespace {

// Whether `token` is a value `row` takes, and the row is not free text
// (a free-text row would take the next English word too).
bool isValueOf(const Option& row, const std::string& token) {
  const auto parses = [&](const std::string& t) {
    RenderSpec scratch;
    try {
      row.set(scratch, t);
      return true;
    } catch (const UsageError&) {
      return false;
    }
  };
  return !token.empty() && !row.isFlag && parses(token) && !parses("not-a-value-of-any-row");
}

}  // namespace

std::string inKeywords(const std::string& message) {
  std::string out;
  for (std::size_t i = 0; i < message.size();) {
    if (message.compare(i, 2, "--") == 0 &&
        (i == 0 || !std::isalnum(static_cast<unsigned char>(message[i - 1])))) {
      std::size_t end = i + 2;
      while (end < message.size() &&
             (std::isalnum(static_cast<unsigned char>(message[end])) || message[end] == '-'))
        ++end;
      if (const Option* o = findOption(message.substr(i, end - i)); o && !o->keyword.empty()) {
        // "--camera lens" reads keyword='lens' in Python.
        std::size_t valueEnd = end + 1;
        while (valueEnd < message.size() && message[valueEnd] != ' ') ++valueEnd;
        while (valueEnd > end + 1 && std::string(",;)").find(message[valueEnd - 1]) != std::string::npos)
          --valueEnd;
        const std::string token =
            end < message.size() && message[end] == ' ' ? message.substr(end + 1, valueEnd - end - 1) : "";
        if (isValueOf(*o, token)) {
          const bool number = o->python == PyValue::Number || o->python == PyValue::Integer;
          out += o->keyword + "=" + (number ? token : "'" + token + "'");
          i = valueEnd;
        } else {
          out += o->keyword;
          i = end;
        }
        continue;
      }
    }
    out += message[i++];
  }
  return out;
}

}  // namespace lensrt
