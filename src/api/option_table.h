// The option table: one row per render setting, the one place that knows
// its command-line flag and Python keyword, its help text (units and an
// example), how its text is parsed into the RenderSpec (api/render_spec.h)
// and checked, whether it is part of the render's identity, and which
// models and modes it applies to. Built from it: the CLI11 options of
// `lensrt render` and `lensrt compare` (app/option_flags.h), Python's
// Scene.render keywords, their checks and stub (python/), the CLI reference
// (`lensrt options --markdown`), the identity (lensrt:options) and the
// warnings for settings that do nothing (as pbrt-v4's ReportUnused).
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "api/render_spec.h"

namespace lensrt {

// How Python hands a keyword's value to the row's parser: as text, or a
// number, pair, list, ... turned into the flag's text (python/keywords.cpp).
enum class PyValue {
  Text,          // str
  Path,          // str or os.PathLike
  Number,        // int or float, finite
  Integer,       // int
  Switch,        // bool, or "on"/"off"
  NumberOrText,  // a number, or text the flag takes ("inf", "1/100", "0:2,1:8")
  Pair,          // (a, b) numbers, or the flag's text
  List,          // a sequence of str, or one comma-separated str
};

// What a setting does to the render's identity (render/render_identity.h):
// renders that differ in an Image row are different renders, whose
// checkpoints and parts never join.
enum class Identity {
  Image,   // changes the pixels: part of the identity
  Extent,  // how far or which part of one render (--spp, --crop, --tile): a resumed
           // render and the parts of a frame are the same render, so not part of it
  None,    // never changes the pixels (threads, tile size, limits)
  Output,  // what is written besides the image (the raw file): not part of it
};

// The commands that take a row (a bit mask).
inline constexpr unsigned kRenderCommand = 1, kCompareCommand = 2, kBothCommands = 3;

struct Option {
  std::string
      group;  // the spec it fills: camera, shutter, flare, colour, sensor, sampling, frame, output, scene
  std::string flag;       // "--fstop"
  std::string keyword;    // "fstop"
  std::string valueName;  // "N|KEYFRAMES", shown in --help
  std::string help;       // what it does, units, the default and an example
  std::string example;    // a valid value other than the default (the identity test sets it)
  PyValue python = PyValue::Text;
  unsigned commands = kBothCommands;
  Identity identity = Identity::Image;
  bool repeatable = false;  // given several times, the values add up (--aov)
  bool isFlag = false;      // takes no value on the command line (set gets "1" or "0")
  // Python: a keyword of Scene.render (true), or of the Scene constructor or
  // the command line alone (false; `keyword` empty for the command line's).
  bool renderKeyword = true;
  // Python numbers for NumberOrText are written with this prefix ("constant:" for --env).
  std::string numberPrefix;
  char separator = ',';             // between the numbers of a Pair or List
  std::string environmentVariable;  // also set by this variable (a flag's "1" or "0")
  // Parses the flag's text into the spec. Throws UsageError(flag, why).
  std::function<void(RenderSpec&, const std::string&)> set;
  // The spec's value as canonical text (the default's when not set).
  std::function<std::string(const RenderSpec&)> show;
  // Whether the setting does anything with the rest of the spec (null:
  // always); `usedBy` says what would use it.
  std::function<bool(const RenderSpec&)> applies;
  std::string usedBy;
};

const std::vector<Option>& optionTable();
// The row of a flag ("--fstop") or a keyword ("fstop"); null when none.
const Option* findOption(std::string_view flagOrKeyword);

// Checks across settings, once every row is set (the checks of one value
// are its row's). `command` is kRenderCommand or kCompareCommand. Throws
// UsageError naming the flag.
void checkSpec(const RenderSpec& spec, unsigned command = kRenderCommand);

// One warning for each given row that does nothing with the rest of the
// spec, naming it and what would use it. `compare` renders every model, so
// its model-dependent rows count as used.
std::vector<std::string> unusedSettings(const RenderSpec& spec, const std::vector<const Option*>& given,
                                        unsigned command = kRenderCommand);

// "fstop=4 focus=2 ...": every Image row whose value differs from the
// default's (lensrt:options, part of the render's identity).
std::string optionsIdentity(const RenderSpec& spec);

// A message in Python's words: each "--flag" of the table becomes its keyword.
std::string inKeywords(const std::string& message);

// The CLI reference page (docs/cli-reference.md): every row, by command.
std::string optionReferenceMarkdown();

}  // namespace lensrt
