// Our own JSON lens format (documented in lens_readers.h and lenses/README.md).
#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "core/error.h"
#include "optics/lens_readers.h"

namespace lensrt {
namespace {

using nlohmann::json;

int lineOfByte(std::string_view text, std::size_t byte) {
  byte = std::min(byte, text.size());
  return 1 +
         static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(byte), '\n'));
}

void rejectUnknownKeys(const json& object, const std::set<std::string>& known, const std::string& where,
                       const std::string& file) {
  for (const auto& [key, value] : object.items())
    if (!known.contains(key)) throw InputError(file, where + "unknown key \"" + key + "\"");
}

double getNumber(const json& object, const char* key, const std::string& where, const std::string& file,
                 std::optional<double> fallback = std::nullopt) {
  const auto it = object.find(key);
  if (it == object.end()) {
    if (fallback) return *fallback;
    throw InputError(file, where + "missing \"" + key + "\"");
  }
  if (!it->is_number()) throw InputError(file, where + "\"" + key + "\" must be a number");
  return it->get<double>();
}

std::string getString(const json& object, const char* key, const std::string& file) {
  const auto it = object.find(key);
  if (it == object.end()) return {};
  if (!it->is_string()) throw InputError(file, std::string("\"") + key + "\" must be a string");
  return it->get<std::string>();
}

}  // namespace

LensPrescription parseJsonLens(std::string_view text, const std::string& file) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    std::string what = e.what();
    // nlohmann prefixes "[json.exception.parse_error.101] parse error at line 2, column 3: ".
    if (const std::size_t colon = what.find(": "); colon != std::string::npos) what = what.substr(colon + 2);
    throw InputError(file, "invalid JSON: " + what, lineOfByte(text, e.byte > 0 ? e.byte - 1 : 0));
  } catch (const json::out_of_range& e) {
    // A number too large for a double (e.g. 1e999) is out_of_range.406, not a parse error.
    std::string what = e.what();
    if (const std::size_t bracket = what.find("] "); bracket != std::string::npos)
      what = what.substr(bracket + 2);
    throw InputError(file, "invalid JSON: " + what);
  }
  if (!doc.is_object()) throw InputError(file, "a lens file must hold a JSON object");
  rejectUnknownKeys(doc,
                    {"format", "version", "name", "description", "source", "focal_length_mm",
                     "closest_focus_m", "surfaces", "notes"},
                    "", file);
  if (getString(doc, "format", file) != "lensrt-lens")
    throw InputError(file, "\"format\" must be \"lensrt-lens\"");
  if (getNumber(doc, "version", "", file, 1.0) != 1.0) throw InputError(file, "only \"version\": 1 is known");
  LensPrescription lens;
  lens.name = getString(doc, "name", file);
  lens.description = getString(doc, "description", file);
  lens.source = getString(doc, "source", file);
  lens.nominalFocalLengthMm = getNumber(doc, "focal_length_mm", "", file, 0.0);
  const double closestFocusM = getNumber(doc, "closest_focus_m", "", file, 0.0);
  if (!(closestFocusM >= 0.0 && closestFocusM <= kMaxLengthMm / 1000.0))
    throw InputError(file, "\"closest_focus_m\" must be a distance from 0 to " +
                               std::to_string(int(kMaxLengthMm / 1000.0)) + " m");
  lens.closestFocusMm = 1000.0 * closestFocusM;
  const auto surfaces = doc.find("surfaces");
  if (surfaces == doc.end() || !surfaces->is_array()) throw InputError(file, "\"surfaces\" must be an array");
  if (surfaces->size() > static_cast<std::size_t>(kMaxSurfaces))
    throw InputError(file, "more than " + std::to_string(kMaxSurfaces) + " surfaces: refusing (not a lens?)");
  for (std::size_t i = 0; i < surfaces->size(); ++i) {
    const json& js = (*surfaces)[i];
    const std::string where = "surface " + std::to_string(i + 1) + ": ";
    if (!js.is_object()) throw InputError(file, where + "must be an object");
    rejectUnknownKeys(js,
                      {"radius", "thickness", "aperture", "nd", "vd", "glass", "stop", "conic", "aspheric"},
                      where, file);
    Surface s;
    s.radius = getNumber(js, "radius", where, file);
    s.thickness = getNumber(js, "thickness", where, file);
    s.apertureDiameter = getNumber(js, "aperture", where, file);
    s.medium.nd = getNumber(js, "nd", where, file, 1.0);
    s.medium.vd = getNumber(js, "vd", where, file, 0.0);
    s.medium.glass = getString(js, "glass", file);
    s.conic = getNumber(js, "conic", where, file, 0.0);
    if (const auto a = js.find("aspheric"); a != js.end()) {
      if (!a->is_array() || a->size() > static_cast<std::size_t>(kAsphericTerms))
        throw InputError(file, where + "\"aspheric\" must be an array of at most " +
                                   std::to_string(kAsphericTerms) + " numbers (A4, A6, ..., A16)");
      for (std::size_t j = 0; j < a->size(); ++j) {
        if (!(*a)[j].is_number()) throw InputError(file, where + "\"aspheric\" must hold numbers only");
        s.aspheric[j] = (*a)[j].get<double>();
      }
    }
    if (const auto stop = js.find("stop"); stop != js.end()) {
      if (!stop->is_boolean()) throw InputError(file, where + "\"stop\" must be true or false");
      s.isStop = stop->get<bool>();
    }
    lens.surfaces.push_back(s);
  }
  if (lens.name.empty()) lens.name = std::filesystem::path(file).stem().string();
  lens.file = file;
  return lens;
}

}  // namespace lensrt
