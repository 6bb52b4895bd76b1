// Shared helpers for the optics tests.
#pragma once

#include <filesystem>
#include <string>

#include "optics/lens_readers.h"
#include "optics/prescription.h"

namespace lensrt::test {

inline std::filesystem::path lensDir() {
  return std::filesystem::path(LENSRT_SOURCE_DIR) / "lenses";
}
inline LensPrescription libraryLens(const std::string& name) {
  return loadLens(findLens(name, lensDir()));
}

// A singlet in air: radii r1, r2, centre thickness t, index n, with a stop
// just in front of it (so the entrance pupil is at the first vertex).
inline LensPrescription singlet(double r1, double r2, double t, double n, double aperture = 20.0) {
  LensPrescription lens;
  lens.name = "singlet";
  Surface stop;
  stop.isStop = true;
  stop.apertureDiameter = aperture;
  stop.thickness = 0.0;
  Surface a;
  a.radius = r1;
  a.thickness = t;
  a.apertureDiameter = aperture;
  a.medium.nd = n;
  Surface b;
  b.radius = r2;
  b.thickness = 0.0;
  b.apertureDiameter = aperture;
  lens.surfaces = {stop, a, b};
  return lens;
}

}  // namespace lensrt::test
