// The lens a user names on the command line (`--lens`, `lens info LENS`): a
// file or a library name. The optics layer knows prescriptions, not what the
// user typed, so its later complaints (focusing, exit pupils) name the lens
// by its library name or not at all; withLensErrors() relabels them so every
// error names the lens as the user gave it. Header-only: test_camera compiles
// the camera factory without the rest of the app.
#pragma once

#include <fmt/core.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/error.h"
#include "optics/lens_readers.h"
#include "optics/paraxial.h"
#include "optics/prescription.h"

namespace lensrt {

struct UserLens {
  std::string label;  // as typed: a path or a library name
  LensPrescription prescription;
};

// Throws InputError(spec, ...) when no such file or library lens exists or it is invalid.
inline UserLens loadUserLens(const std::string& spec, const std::filesystem::path& lensDir) {
  // findLens would call a directory or a FIFO "no such lens".
  std::error_code ec;
  if (std::filesystem::exists(spec, ec) && !std::filesystem::is_regular_file(spec, ec))
    throw InputError(spec, std::filesystem::is_directory(spec, ec) ? "is a directory, not a lens file"
                                                                   : "not a regular file");
  UserLens lens{spec, loadLens(findLens(spec, lensDir))};
  return lens;
}

namespace detail {

// Optics messages written for programmers, in the user's words.
inline std::string lensMessage(std::string message) {
  if (message.find("film must lie behind the rear vertex") != std::string::npos)
    return "at this focus the image falls inside the lens (no film position behind its last surface)";
  return message;
}

}  // namespace detail

// A diverging (or afocal) lens has no real image to put a film in.
inline void requireRealImage(const UserLens& lens) {
  const double efl = computeParaxial(lens.prescription).efl;
  if (!(efl > 0.0))
    throw InputError(
        lens.label,
        fmt::format("a diverging lens (focal length {:.4g} mm) forms no real image, so no film can "
                    "be focused behind it",
                    efl));
}

// Runs `f`; InputError naming the prescription (not a file) and the optics'
// std::invalid_argument / std::domain_error become InputError(lens.label, ...).
template <class F>
decltype(auto) withLensErrors(const UserLens& lens, F&& f) {
  try {
    return std::forward<F>(f)();
  } catch (const InputError& e) {
    if (e.file() != lens.prescription.name && !e.file().empty()) throw;
    throw InputError(lens.label, detail::lensMessage(e.message()), e.line());
  } catch (const std::invalid_argument& e) {
    throw InputError(lens.label, detail::lensMessage(e.what()));
  } catch (const std::domain_error& e) {
    throw InputError(lens.label, detail::lensMessage(e.what()));
  }
}

}  // namespace lensrt
