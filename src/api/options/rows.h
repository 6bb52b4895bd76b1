// The option table's row builders, for the files that fill its groups
// (api/options/<group>_rows.cpp). `get` is a generic lambda giving the field
// of a spec, const or not, so one accessor serves the parser and show.
#pragma once

#include <fmt/core.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "api/option_parsers.h"
#include "api/option_table.h"
#include "core/error.h"

namespace lensrt {

// Appends a row to the table as one of `group`'s.
inline Option& addRow(std::vector<Option>& table, const char* group, Option o) {
  o.group = group;
  return table.emplace_back(std::move(o));
}

inline Option row(std::string flag, std::string keyword, std::string valueName, std::string help,
                  std::string example, PyValue python) {
  Option o;
  o.flag = std::move(flag);
  o.keyword = std::move(keyword);
  o.valueName = std::move(valueName);
  o.help = std::move(help);
  o.example = std::move(example);
  o.python = python;
  return o;
}

template <class Get>
Option number(Option o, Get get, double lo, double hi, std::string what) {
  const std::string flag = o.flag;
  o.set = [=](RenderSpec& s, const std::string& t) { get(s) = parseNumberIn(flag, t, lo, hi, what); };
  o.show = [=](const RenderSpec& s) { return numberText(get(s)); };
  return o;
}

template <class Get>
Option optionalNumber(Option o, Get get, double lo, double hi, std::string what) {
  const std::string flag = o.flag;
  o.set = [=](RenderSpec& s, const std::string& t) { get(s) = parseNumberIn(flag, t, lo, hi, what); };
  o.show = [=](const RenderSpec& s) { return get(s) ? numberText(*get(s)) : std::string("default"); };
  return o;
}

template <class Get>
Option integer(Option o, Get get, std::int64_t lo, std::int64_t hi, std::string what) {
  const std::string flag = o.flag;
  o.set = [=](RenderSpec& s, const std::string& t) {
    get(s) = static_cast<std::remove_reference_t<decltype(get(s))>>(parseIntegerIn(flag, t, lo, hi, what));
  };
  o.show = [=](const RenderSpec& s) { return std::to_string(get(s)); };
  return o;
}

template <class Get>
Option onOff(Option o, Get get) {
  const std::string flag = o.flag;
  o.set = [=](RenderSpec& s, const std::string& t) { get(s) = parseSwitch(flag, t); };
  o.show = [=](const RenderSpec& s) { return std::string(get(s) ? "on" : "off"); };
  return o;
}

template <class Get, class Value>
Option choice(Option o, Get get, std::vector<std::pair<std::string, Value>> values) {
  const std::string flag = o.flag;
  std::vector<std::string> names;
  for (const auto& v : values) names.push_back(v.first);
  o.set = [=](RenderSpec& s, const std::string& t) { get(s) = values[parseOneOf(flag, t, names)].second; };
  o.show = [=](const RenderSpec& s) {
    for (const auto& v : values)
      if (Value(get(s)) == v.second) return v.first;
    return std::string("default");
  };
  return o;
}

template <class Get>
Option text(Option o, Get get) {
  o.set = [=](RenderSpec& s, const std::string& t) { get(s) = t; };
  o.show = [=](const RenderSpec& s) { return std::string(get(s)); };
  return o;
}

inline bool notPinhole(const RenderSpec& s) {
  return s.camera.model != CameraModel::Pinhole;
}

inline constexpr const char* kLensModels =
    "does nothing with the pinhole: it applies to --camera thin, thick or lens";

// Each group's rows, in the order of the reference page.
void addCameraRows(std::vector<Option>& table);
void addShutterRows(std::vector<Option>& table);
void addFlareRows(std::vector<Option>& table);
void addColourRows(std::vector<Option>& table);
void addSensorRows(std::vector<Option>& table);
void addSamplingRows(std::vector<Option>& table);
void addFrameRows(std::vector<Option>& table);
void addOutputRows(std::vector<Option>& table);
void addSceneRows(std::vector<Option>& table);

}  // namespace lensrt
