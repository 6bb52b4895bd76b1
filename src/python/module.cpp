// The Python module `lensrt` (its compiled part, lensrt._lensrt; the package's
// __init__.py re-exports it with TraceResult).
#include <pybind11/pybind11.h>

#include "python/bindings.h"
#include "python/errors.h"

PYBIND11_MODULE(_lensrt, m) {
  m.doc() = "lensrt: render glTF scenes through real camera optics, into numpy arrays.";
  m.attr("__version__") = LENSRT_VERSION;
  lensrt::python::registerErrors(m);
  lensrt::python::bindLens(m);
  lensrt::python::bindScene(m);
  lensrt::python::bindDiff(m);
}
