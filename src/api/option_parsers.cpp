#include "api/option_parsers.h"

#include <fmt/core.h>

#include <charconv>
#include <cmath>
#include <map>

#include "core/constants.h"
#include "core/error.h"

namespace lensrt {
namespace {

std::optional<double> wholeDouble(std::string_view s) {
  double v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::string meaning(const std::string& what) {
  return what.empty() ? "" : " (" + what + ")";
}

}  // namespace

double parseNumberIn(const std::string& flag, const std::string& text, double lo, double hi,
                     const std::string& what) {
  const std::optional<double> v = wholeDouble(text);
  if (!v || !(*v >= lo && *v <= hi))
    throw UsageError(
        flag, fmt::format("expected a number from {:g} to {:g}{}, got '{}'", lo, hi, meaning(what), text));
  return *v;
}

double parseNumberFrom(const std::string& flag, const std::string& text, double lo, const std::string& what,
                       bool positive) {
  const std::optional<double> v = wholeDouble(text);
  if (!v || !(positive ? *v > lo : *v >= lo))
    throw UsageError(flag, fmt::format("expected a number {} {:g}{}, got '{}'", positive ? ">" : ">=", lo,
                                       meaning(what), text));
  return *v;
}

template <class Int>
Int parseIntegerText(const std::string& flag, const std::string& text, Int lo, Int hi,
                     const std::string& what) {
  Int v{};
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec == std::errc() && end == text.data() + text.size() && v >= lo && v <= hi) return v;
  const std::string range = lo == 1 ? fmt::format("a positive integer up to {}", hi)
                                    : fmt::format("an integer from {} to {}", lo, hi);
  throw UsageError(flag, "expected " + range + meaning(what) + ", got '" + text + "'");
}

std::int64_t parseIntegerIn(const std::string& flag, const std::string& text, std::int64_t lo,
                            std::int64_t hi, const std::string& what) {
  return parseIntegerText(flag, text, lo, hi, what);
}

std::uint64_t parseUnsignedIn(const std::string& flag, const std::string& text, std::uint64_t lo,
                              std::uint64_t hi, const std::string& what) {
  return parseIntegerText(flag, text, lo, hi, what);
}

std::size_t parseOneOf(const std::string& flag, const std::string& text,
                       const std::vector<std::string>& names) {
  std::string list;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (text == names[i]) return i;
    list += (i ? "," : "") + names[i];
  }
  throw UsageError(flag, text + " not in {" + list + "}");
}

bool parseSwitch(const std::string& flag, const std::string& text) {
  return parseOneOf(flag, text, {"on", "off"}) == 0;
}

double parseSeconds(const std::string& flag, const std::string& text) {
  const std::size_t slash = text.find('/');
  std::optional<double> v;
  if (slash == std::string::npos) {
    v = wholeDouble(text);
  } else {
    const auto a = wholeDouble(text.substr(0, slash)), b = wholeDouble(text.substr(slash + 1));
    if (a && b && *b > 0.0) v = *a / *b;
  }
  if (!v || !(*v >= 0.0) || *v > 1e6)
    throw UsageError(flag,
                     fmt::format("expected a time in seconds >= 0 (e.g. 0.01 or 1/100), got '{}'", text));
  return *v;
}

std::optional<Vec2d> parseNumberPair(const std::string& text, char separator) {
  const std::size_t at = text.find(separator);
  if (at == std::string::npos) return std::nullopt;
  const auto a = wholeDouble(text.substr(0, at)), b = wholeDouble(text.substr(at + 1));
  if (!a || !b) return std::nullopt;
  return Vec2d{*a, *b};
}

Vec2d parseSensor(const std::string& text) {
  static const std::map<std::string, Vec2d> names{
      {"full-frame", {36.0, 24.0}}, {"aps-c", {23.6, 15.6}}, {"mft", {17.3, 13.0}}, {"1in", {13.2, 8.8}}};
  if (const auto it = names.find(text); it != names.end()) return it->second;
  const std::size_t x = text.find_first_of("xX");
  const auto w = x == std::string::npos ? std::nullopt : wholeDouble(text.substr(0, x));
  const auto h = x == std::string::npos ? std::nullopt : wholeDouble(text.substr(x + 1));
  if (!w || !h || !(*w > 0.0) || !(*h > 0.0) || *w > 1000.0 || *h > 1000.0)
    throw UsageError("--sensor",
                     "expected WxH in mm (e.g. 36x24) or full-frame, aps-c, mft, 1in; got '" + text + "'");
  return {*w, *h};
}

std::optional<double> parseFocusDistance(const std::string& text) {
  if (text == "auto") return std::nullopt;
  if (text == "inf" || text == "infinity") return kInfinity;
  const auto v = wholeDouble(text);
  if (!v || !(*v > 0.0))
    throw UsageError(
        "--focus",
        "expected a distance in metres > 0, auto, inf or keyframes SECONDS:METRES,..., got '" + text + "'");
  return *v;
}

std::string numberText(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return fmt::format("{}", v);
}

std::string keyframesText(const Keyframes& keys) {
  std::string s;
  for (const auto& [t, v] : keys) {
    if (!s.empty()) s += ',';
    s.append(numberText(t)).append(":").append(numberText(v));
  }
  return s;
}

}  // namespace lensrt
