// --spectral auto: which transport a render uses, and why (the EXR's
// lensrt:transport). Decided once, by the plan (api/render_plan.h).
#pragma once

#include <string>

#include "api/colour_spec.h"

namespace lensrt {

// What in a render depends on wavelengths.
struct WavelengthNeeds {
  bool cameraResponse = false;   // --sensor-response other than cie1931 (with or without --noise)
  bool colourSettings = false;   // --white-balance, or --output-space other than srgb
  bool sceneDispersion = false;  // KHR_materials_dispersion glass (RenderJob::sceneDisperses)
  bool lensDispersion = false;   // a lens traced with its dispersion (CameraInfo::dispersion)
  bool flareCoatings = false;    // the camera traces wavelengths for its coatings under flare
  bool diffraction = false;      // --diffraction on: the spikes' colour
};

struct TransportChoice {
  bool spectral = true;
  std::string description;  // e.g. "rgb (auto: nothing needs wavelengths)"
};

// on and off are what they say. auto is spectral when any need holds (the
// first one, in WavelengthNeeds' order, names the reason) and RGB otherwise:
// RGB reaches the same error sooner (issue 39: 1.5x on the pinhole), and
// without these needs the spectral image has the same mean.
TransportChoice chooseTransport(Transport asked, const WavelengthNeeds& needs);

}  // namespace lensrt
