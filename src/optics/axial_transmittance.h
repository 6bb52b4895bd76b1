// The fraction of the light of an axial bundle (an on-axis object at
// infinity filling the entrance pupil) that the lens's surfaces transmit.
#pragma once

#include "optics/lens_system.h"

namespace lensrt {

// The mean Fresnel transmittance of collimated rays along the axis on a
// grid x grid lattice over a disc 1.3 times the paraxial entrance pupil
// (within the front clear aperture), among those that pass (so the stop
// selects the bundle), at the d line. It depends on the f-number: wider
// bundles meet the surfaces more obliquely. 1 when the system models
// no coating; 0 when nothing passes.
double axialTransmittance(const LensSystem& lens, int grid = 48);

}  // namespace lensrt
