// How the plugin's C entry points report failure: the reason goes to a
// per-thread string (lensrt_oiio_last_error) and the call returns an error
// code; no exception ever crosses into lensrt.
#pragma once

#include <exception>
#include <stdexcept>
#include <string>

#include "image/oiio_plugin_abi.h"

namespace lensrt::oiio {

// A failure whose message is the caller's reason.
class Failure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

void setLastError(const std::string& reason);

// Runs `body` (returning a status) with the error cleared first, turning
// any exception into LENSRT_OIIO_FAILED and its message.
template <class Body>
int guarded(Body&& body) noexcept {
  setLastError("");
  try {
    return body();
  } catch (const std::bad_alloc&) {
    setLastError("out of memory");
  } catch (const std::exception& e) {
    setLastError(e.what());
  } catch (...) {
    setLastError("an unknown error");
  }
  return LENSRT_OIIO_FAILED;
}

// OpenImageIO's error text on one line, or `fallback` when it gave none.
std::string oneLine(const std::string& text, const std::string& fallback);

}  // namespace lensrt::oiio
