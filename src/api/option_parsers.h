// The parsers of the option table's rows (api/option_table.h): each takes
// the flag's text, returns the typed value and throws UsageError(flag, why)
// with the words the command line has always used.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include "api/keyframes.h"
#include "core/vec.h"

namespace lensrt {

// A finite decimal number in [lo, hi] ("expected a number from 0.5 to 1024 (the f-number), got 'x'").
double parseNumberIn(const std::string& flag, const std::string& text, double lo, double hi,
                     const std::string& what = "");
// A finite number > lo (or >= lo unless `positive`).
double parseNumberFrom(const std::string& flag, const std::string& text, double lo, const std::string& what,
                       bool positive);
// A decimal integer in [lo, hi].
std::int64_t parseIntegerIn(const std::string& flag, const std::string& text, std::int64_t lo,
                            std::int64_t hi, const std::string& what = "");
std::uint64_t parseUnsignedIn(const std::string& flag, const std::string& text, std::uint64_t lo,
                              std::uint64_t hi, const std::string& what = "");
// One of `names`; its index ("maybe not in {on,off}").
std::size_t parseOneOf(const std::string& flag, const std::string& text,
                       const std::vector<std::string>& names);
// "on" or "off".
bool parseSwitch(const std::string& flag, const std::string& text);
// Seconds >= 0 from "0.004", "1/250" or "2".
double parseSeconds(const std::string& flag, const std::string& text);
// Two numbers "A<sep>B"; nullopt when the text is not that.
std::optional<Vec2d> parseNumberPair(const std::string& text, char separator);
// The sensor in mm: "WxH" or full-frame, aps-c, mft, 1in.
Vec2d parseSensor(const std::string& text);
// --focus: auto (nullopt), inf, metres > 0.
std::optional<double> parseFocusDistance(const std::string& text);
// The shortest text that reads back as `v` ("0.1", "inf").
std::string numberText(double v);
// "0:2,1:8".
std::string keyframesText(const Keyframes& keys);

}  // namespace lensrt
