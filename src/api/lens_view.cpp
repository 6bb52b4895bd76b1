#include "api/lens_view.h"

#include <fmt/core.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "api/lens_loading.h"
#include "core/constants.h"
#include "core/error.h"
#include "optics/focus.h"
#include "optics/lens_readers.h"

namespace lensrt {
Vec2d parseSensorSize(const std::string& text) {
  double w = 0.0, h = 0.0;
  const std::size_t x = text.find_first_of("xX");
  try {
    if (x != std::string::npos) {
      std::size_t used1 = 0, used2 = 0;
      const std::string a = text.substr(0, x), b = text.substr(x + 1);
      w = std::stod(a, &used1);
      h = std::stod(b, &used2);
      if (used1 == a.size() && used2 == b.size() && w > 0 && h > 0 && w < 1e4 && h < 1e4) return {w, h};
    }
  } catch (const std::exception&) {
  }
  throw UsageError("--sensor", "expected WIDTHxHEIGHT in mm, e.g. 36x24, got '" + text + "'");
}

double parseFocusDistanceMm(const std::string& text) {
  const double m = parseFocusMetres(text);
  return std::isinf(m) ? kInfinity : m * 1000.0;
}

double parseFocusMetres(const std::string& text) {
  if (text == "inf" || text == "infinity") return kInfinity;
  try {
    std::size_t used = 0;
    const double m = std::stod(text, &used);
    if (used == text.size() && m > 0 && std::isfinite(m)) return m;
  } catch (const std::exception&) {
  }
  throw UsageError("--focus", "expected a distance in metres > 0 or 'inf', got '" + text + "'");
}

void checkSvgOutput(const std::string& output) {
  const std::filesystem::path file(output);
  if (file.extension() != ".svg") throw UsageError("--output", "expected a .svg file, got '" + output + "'");
  checkOutputDirectory(output);
}

void checkOutputDirectory(const std::string& output) {
  const std::filesystem::path file(output);
  // Fail before the tracing, not after: the directory must take a new file.
  const std::filesystem::path dir = file.has_parent_path() ? file.parent_path() : ".";
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec))
    throw InputError(output, "cannot write: directory '" + dir.string() + "' does not exist");
  if (::access(dir.c_str(), W_OK) != 0)
    throw InputError(output, "cannot write: directory '" + dir.string() + "' is not writable");
}

double LensView::halfDiagonalMm() const {
  return std::hypot(sensorWidthMm, sensorHeightMm) / 2.0;
}

std::string LensView::focusText() const {
  return std::isinf(focusMm) ? "infinity" : fmt::format("{:.3g} m", focusMm / 1000.0);
}

std::string LensView::summary() const {
  const ParaxialData& p = lens.paraxial();
  return fmt::format("EFL {:.2f} mm, f/{:.3g}, focus {}, sensor {:g} x {:g} mm", p.efl, p.fNumber,
                     focusText(), sensorWidthMm, sensorHeightMm);
}

LensView prepareLensView(const LensViewOptions& o, Warnings& warnings) {
  if (!o.output.empty()) checkSvgOutput(o.output);
  parseSensorSize(o.sensor);
  parseFocusDistanceMm(o.focus);
  checkFNumber(o.fNumber);
  // The same lens errors, worded the same way, as lensrt render's.
  return prepareLensView(loadUserLens(o.lens, LENSRT_LENS_DIR), o, warnings);
}

void checkFNumber(const std::optional<double>& fNumber) {
  if (fNumber && !(*fNumber > 0.0 && std::isfinite(*fNumber)))
    throw UsageError("--fstop", "must be a positive f-number");
}

LensView prepareLensView(const UserLens& user, const LensViewOptions& o, Warnings& warnings) {
  const Vec2d sensor = parseSensorSize(o.sensor);
  const double w = sensor.x, h = sensor.y;
  const double focusMm = parseFocusDistanceMm(o.focus);
  checkFNumber(o.fNumber);
  requireRealImage(user);
  return withLensErrors(user, [&] {
    const double widest = computeParaxial(user.prescription).fNumber;
    LensSystem lens(o.fNumber ? stopDown(user.prescription, *o.fNumber, warnings) : user.prescription,
                    parseCoating(o.coatings));
    const double film = focusFilmDistance(lens, focusMm);
    return LensView{std::move(lens), widest, focusMm, film, w, h};
  });
}

}  // namespace lensrt
