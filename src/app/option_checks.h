// CLI11 checks for numeric flags that say what the flag needs. CLI11's own
// Range says "Value abc not in range 1 to 16777216" for a word, and a failed
// conversion "Could not convert: --seed = x"; these run on the text first and
// say e.g. "--spp: expected a positive integer up to 16777216 (samples per pixel), got 'abc'".
// Header-only, for the commands that check their own flags (the render settings are the option table's).
#pragma once

#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>
#include <system_error>

#include "core/error.h"

namespace lensrt {

// An integer in [lo, hi] written in decimal (no sign for unsigned types).
template <class Int>
CLI::Validator integerIn(Int lo, Int hi, const std::string& what = "") {
  const std::string range = lo == 1 ? fmt::format("a positive integer up to {}", hi)
                                    : fmt::format("an integer from {} to {}", lo, hi);
  const std::string meaning = what.empty() ? "" : " (" + what + ")";
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        Int v{};
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
        if (ec == std::errc() && end == text.data() + text.size() && v >= lo && v <= hi) return "";
        return "expected " + range + meaning + ", got '" + text + "'";
      },
      fmt::format("INT in [{} - {}]", lo, hi));
}

// A finite decimal number in [lo, hi].
inline CLI::Validator numberIn(double lo, double hi, const std::string& what = "") {
  const std::string meaning = what.empty() ? "" : " (" + what + ")";
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        double v = 0;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
        if (ec == std::errc() && end == text.data() + text.size() && std::isfinite(v) && v >= lo && v <= hi)
          return "";
        return fmt::format("expected a number from {:g} to {:g}{}, got '{}'", lo, hi, meaning, text);
      },
      fmt::format("NUMBER in [{:g} - {:g}]", lo, hi));
}

// Any finite decimal number; the command checks its range with its own words.
inline CLI::Validator aNumber(const std::string& what) {
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        double v = 0;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
        if (ec == std::errc() && end == text.data() + text.size() && std::isfinite(v)) return "";
        return "expected a number (" + what + "), got '" + text + "'";
      },
      "NUMBER");
}

// A CLI11 check from a parser that throws UsageError("--flag", why).
template <class Parse>
CLI::Validator checkWith(Parse parse, const std::string& description) {
  return CLI::Validator(
      [parse](std::string& text) -> std::string {
        try {
          parse(text);
          return "";
        } catch (const UsageError& e) {
          return e.message();
        }
      },
      description);
}

// A decimal number >= 0 (or > 0 when `positive`); with `infinity`, also
// "inf" or "infinity" for no limit. CLI11's NonNegativeNumber refuses inf and
// names its bound, the largest double, in 309 digits.
inline CLI::Validator numberFrom(double lo, const std::string& what, bool positive = false,
                                 bool infinity = false) {
  const std::string wanted =
      fmt::format("a number {} {:g}{}", positive ? ">" : ">=", lo, infinity ? " or inf" : "");
  const std::string meaning = what.empty() ? "" : " (" + what + ")";
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        double v = 0;
        // from_chars reads "inf" and "infinity" in any case, as strtod does.
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
        if (ec == std::errc() && end == text.data() + text.size() &&
            (std::isfinite(v) || (infinity && v > 0)) && (positive ? v > lo : v >= lo))
          return "";
        return "expected " + wanted + meaning + ", got '" + text + "'";
      },
      infinity ? "NUMBER|inf" : "NUMBER");
}

}  // namespace lensrt
