#include "app/camera_flags.h"

#include "app/option_checks.h"

namespace lensrt {

void addCameraOptions(CLI::App& cmd, CameraOptions& o) {
#ifdef LENSRT_LENS_DIR
  if (o.lensDir.empty()) o.lensDir = LENSRT_LENS_DIR;
#endif
  cmd.add_option("--camera", o.model,
                 "camera model: pinhole, thin (ideal thin lens), thick (the lens's paraxial model) or lens "
                 "(traced through every element of --lens); default pinhole")
      ->check(CLI::IsMember({"pinhole", "thin", "thick", "lens"}));
  cmd.add_option(
      "--lens", o.lens,
      "lens prescription: a .dat/.lens/.json/.zmx file or a library name, e.g. --lens dgauss-50mm; the "
      "thin, thick and pinhole models then derive from it");
  // A number, or keyframes SECONDS:N,... read at --time (api/keyframes.h).
  cmd.add_option_function<std::string>(
         "--fstop",
         [&o](const std::string& text) {
           if (isKeyframes(text)) {
             o.fNumberKeyframes = text;
             o.fNumber.reset();
           } else {
             o.fNumber = std::stod(text);
             o.fNumberKeyframes.clear();
           }
         },
         "f-number N, e.g. --fstop 2.8, or keyframes SECONDS:N,... read at --time, e.g. 0:2,1:8 (default: "
         "the "
         "lens wide open, else 2.8)")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            if (!isKeyframes(text)) return numberIn(0.5, 1024.0, "the f-number")(text);
            try {
              fNumberKeyframes(text);
              return "";
            } catch (const UsageError& e) {
              return e.message();
            }
          },
          "N|KEYFRAMES"));
  cmd.add_option("--focus", o.focus,
                 "focus distance in metres from the entrance pupil, 'auto' (what the centre pixel, or "
                 "--focus-pixel, sees), 'inf', or keyframes SECONDS:METRES,... read at --time (a rack focus, "
                 "e.g. 0:1.2,2:4); default auto")
      ->check(checkWith([](const std::string& s) { return parseFocus(s); }, "METRES|auto|inf|KEYFRAMES"));
  cmd.add_option("--focus-pixel", o.focusPixel, "pixel X,Y that --focus auto focuses on, e.g. 320,180")
      ->check(checkWith(parseFocusPixel, "X,Y"));
  cmd.add_option(
         "--sensor", o.sensor,
         "sensor size WxH in mm or full-frame (36x24), aps-c (23.6x15.6), mft (17.3x13), 1in (13.2x8.8); "
         "cropped to the image's aspect ratio; default full-frame")
      ->check(checkWith(parseSensor, "WxH|NAME"));
  cmd.add_option("--blades", o.blades,
                 "aperture blades: 0 for a round aperture, else 3..64 (a regular polygon)")
      ->check(integerIn(0, 64, "0 for a round aperture, else 3 or more") &
              CLI::Validator(
                  [](std::string& s) -> std::string {
                    return s == "1" || s == "2" ? "an aperture needs 0 or at least 3 blades" : "";
                  },
                  ""));
  cmd.add_option("--blade-rotation", o.bladeRotationDegrees,
                 "rotation of the blade polygon in degrees, e.g. 15")
      ->check(numberIn(-360.0, 360.0, "degrees"));
  cmd.add_option("--aperture-mask", o.apertureMask,
                 "grey-scale image (PNG, JPEG, BMP or TGA) over the stop of --camera lens, white transmits: "
                 "bokeh takes its "
                 "shape; instead of --blades");
  cmd.add_option("--focal-length", o.focalLengthMm,
                 "focal length in mm: without --lens the thin lens's and pinhole's (default: from the glTF "
                 "camera's field of view); with --lens the design is scaled to it")
      ->check(numberIn(0.1, 10000.0, "mm"));
  cmd.add_option("--exposure", o.exposure,
                 "normalized (an ideal lens records the scene radiance on axis at any f-number; default) or "
                 "physical (exposure H = E t, 1.0 = ISO 12232 saturation: value = 683 E t ISO / 78)")
      ->check(CLI::IsMember({"normalized", "physical"}));
  // A flag of the shutter's timing, checked by shutterTiming on options holding it alone.
  const auto timingCheck = [](std::string CameraOptions::*field, const std::string& description) {
    return checkWith(
        [field](const std::string& v) {
          CameraOptions c;
          c.*field = v;
          return shutterTiming(c);
        },
        description);
  };
  cmd.add_option(
         "--shutter", o.shutter,
         "shutter time in seconds, e.g. 1/125 (default 1/100): the exposure under --exposure physical, "
         "and the motion blur of an animated scene (0: an instant)")
      ->check(checkWith(parseShutter, "SECONDS"));
  cmd.add_option(
         "--shutter-curve", o.shutterCurve,
         "how the shutter opens: box (at once; default) or trapezoid:F (a leaf shutter taking the share F "
         "<= 0.5 of --shutter to open, and again to close), e.g. --shutter-curve trapezoid:0.2")
      ->check(timingCheck(&CameraOptions::shutterCurve, "box|trapezoid:F"));
  cmd.add_option("--rolling-shutter", o.rollingShutter,
                 "a CMOS rolling shutter: each row starts its exposure later by READOUT x row / rows, e.g. "
                 "--rolling-shutter 1/30 (default: a global shutter)")
      ->check(timingCheck(&CameraOptions::rollingShutter, "SECONDS"));
  cmd.add_option("--readout", o.readout,
                 "the rolling shutter's direction in the image as seen: top-down (default), bottom-up, "
                 "left-right or right-left")
      ->check(CLI::IsMember({"top-down", "bottom-up", "left-right", "right-left"}));
  cmd.add_option("--iso", o.iso, "ISO speed for --exposure physical (default 100)")
      ->check(numberIn(1.0, 1e7, "ISO speed"));
  cmd.add_option(
         "--dispersion", o.dispersion,
         "on (default): when --lens has dispersion data (Abbe numbers), each sample is traced at its own "
         "wavelength: colour fringes with --camera lens, a focal length per wavelength with thin and "
         "thick; off: every ray at the d line (587.6 nm)")
      ->check(CLI::IsMember({"on", "off"}));
  cmd.add_option("--coatings", o.coatings,
                 "Fresnel losses in the full lens (--camera lens): none (uncoated glass), single (a "
                 "quarter-wave MgF2 layer at 550 nm) or multi (0.5% reflectance per surface); default: "
                 "lossless glass, as pbrt")
      ->check(CLI::IsMember({"none", "single", "multi"}));
  cmd.add_option("--flare", o.flare,
                 "on: stray light in the full lens (--camera lens): every surface reflects its Fresnel share "
                 "(bare glass unless --coatings), so ghosts of bright sources and veiling glare appear; off "
                 "(default)")
      ->check(CLI::IsMember({"on", "off"}));
  cmd.add_option("--flare-bounces", o.flareBounces,
                 "with --flare on, the most reflections a path takes in the lens: 0, 2 (default: the ghosts) "
                 "or 4")
      ->check(CLI::IsMember({0, 2, 4}));
  cmd.add_option("--barrel-reflectance", o.barrelReflectance,
                 "with --flare on, the diffuse reflectance K in [0, 1) of the barrel: a ray that meets a "
                 "lens's mount (outside a surface's clear aperture, not the stop) scatters back with "
                 "probability K, for veiling glare; default 0 (black)");
  cmd.add_option("--film", o.film,
                 "what a pixel records: radiance (the mean radiance along the camera rays, no cos^4, no "
                 "bellows factor, no exposure scale: pbrt's, Cycles' and Mitsuba's pinhole; the pinhole's "
                 "default, pinhole only) or irradiance (the physical film, scaled by --exposure; the default "
                 "of thin, thick and lens)")
      ->check(CLI::IsMember({"radiance", "irradiance"}));
  cmd.add_option("--spectral", o.spectral,
                 "on (default): light travels at four wavelengths per sample (a hero and three rotated "
                 "copies), glTF colours upsampled to smooth spectra, the film the CIE 1931 observer in "
                 "linear sRGB; scene glass with KHR_materials_dispersion and the lens disperse in the same "
                 "transport. off: RGB transport")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  cmd.add_option(
      "--sensor-response", o.sensorResponse,
      "the sensor's spectral response with --spectral on: cie1931 (default; the CIE 1931 observer, "
      "colorimetric), a camera from `lensrt sensor list`, or a CSV file of wavelength_nm,r,g,b");
  cmd.add_option(
      "--white-balance", o.whiteBalance,
      "none (the default for cie1931: RGB (1,1,1) light is D65 and records white), auto (balance to "
      "the scene's most powerful light; the default for cameras) or a colour temperature in K, e.g. "
      "3200 (a black body below 4000 K, CIE daylight above): a grey card under that light records grey "
      "(Bradford adaptation)");
  cmd.add_option(
         "--output-space", o.outputSpace,
         "the RGB of the image: srgb (linear Rec. 709 primaries, D65), rec2020, acescg (AP1, ACES white), "
         "xyz (CIE XYZ), or camera (the camera response's own RGB); the EXR's chromaticities say which. "
         "PNG and JPEG previews need srgb")
      ->capture_default_str();
  cmd.add_option("--noise", o.noise,
                 "on: the sensor reads the exposure out as a camera does: photo-electrons (from the lux "
                 "seconds on a pixel with --exposure physical, else 1.0 = full well), shot noise, dark "
                 "current, read noise, PRNU/DSNU, full-well clipping, ISO gain and ADC; R,G,B hold the "
                 "reading, noiseless.R/G/B the render (default off)")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  cmd.add_option("--sensor-params", o.sensorParams,
                 "the sensor for --noise on: a preset (default, full-frame, smartphone, machine-vision) or "
                 "a JSON file of full_well_e, gain_dn_per_e, base_iso, read_noise_e, dark_current_e_per_s, "
                 "prnu_percent, dsnu_percent, adc_bits, black_level_dn, quantum_efficiency (see README)");
}

}  // namespace lensrt
