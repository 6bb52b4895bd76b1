// Camera settings that change over time: "SECONDS:VALUE,SECONDS:VALUE,..."
// (e.g. --focus 0:1.2,2:4, a rack focus from 1.2 m to 4 m over two seconds),
// linear between keyframes and held before the first and after the last.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace lensrt {

using Keyframes = std::vector<std::pair<double, double>>;  // (seconds, value), seconds increasing

// True when `text` is written as keyframes (it holds a ':').
bool isKeyframes(const std::string& text);

// Throws UsageError(flag, ...) for a bad list: not SECONDS:VALUE pairs,
// times that do not increase, a value `valid` refuses (it names what it
// expects in `expected`).
Keyframes parseKeyframes(const std::string& flag, const std::string& text, bool (*valid)(double),
                         const std::string& expected);

double valueAt(const Keyframes& keys, double seconds);

}  // namespace lensrt
