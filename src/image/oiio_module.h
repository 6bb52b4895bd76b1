// Loads liblensrt_oiio.so (OpenImageIO behind a small table, see
// oiio/oiio_api.h) on first use, so commands that never touch an image do
// not pay for OpenImageIO's ~260 shared libraries at start-up.
#pragma once

#include "image/oiio/oiio_api.h"

namespace lensrt {

// The module's table, loaded once (thread-safe); null when it cannot be
// loaded, with the reason in oiioModuleError().
const oiio::Api* oiioModule();
const std::string& oiioModuleError();

}  // namespace lensrt
