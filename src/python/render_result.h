// lensrt.RenderResult's C++ side: a render whose pixels the numpy arrays of
// .rgb and .channels view (scene_bindings) and lensrt.diff reads (diff_bindings).
#pragma once

#include "api/render_request.h"

namespace lensrt::python {

struct PyRenderResult {
  RenderResult result;
};

}  // namespace lensrt::python
