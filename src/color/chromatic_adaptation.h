// Chromatic adaptation: what a white balance applies to XYZ.
#pragma once

#include "core/mat3.h"
#include "core/vec.h"

namespace lensrt {

// The Bradford transform (von Kries scaling in the Bradford cone space)
// taking colours seen under a source white to the same appearance under a
// target white: source white XYZ -> target white XYZ.
Mat3d bradfordAdaptation(const Vec3d& sourceWhiteXyz, const Vec3d& targetWhiteXyz);

}  // namespace lensrt
