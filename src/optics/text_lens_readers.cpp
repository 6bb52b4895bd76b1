// The two line-oriented formats: pbrt's .dat and the seed's table (.lens).
#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <filesystem>
#include <string>
#include <vector>

#include "core/ascii_lower.h"
#include "core/error.h"
#include "optics/lens_readers.h"
#include "optics/text_lines.h"

namespace lensrt {
namespace {

// "# key: value" header comments fill the metadata; the first other comment
// becomes the description when none is given.
void readMetadataComment(std::string_view comment, LensPrescription& lens, std::string& firstComment,
                         const std::string& file, int line) {
  const std::size_t colon = comment.find(':');
  if (colon != std::string_view::npos) {
    const std::string key = asciiLower(trim(comment.substr(0, colon)));
    const std::string value(trim(comment.substr(colon + 1)));
    if (key == "name") return void(lens.name = value);
    if (key == "description") return void(lens.description = value);
    if (key == "source") return void(lens.source = value);
    if (key == "focal-length-mm" || key == "focal length mm") {
      const auto v = parseNumber(value);
      if (!v || !(*v > 0.0) || *v > kMaxLengthMm)
        throw InputError(file, "focal-length-mm must be a positive number, got '" + value + "'", line);
      return void(lens.nominalFocalLengthMm = *v);
    }
  }
  if (firstComment.empty()) firstComment = std::string(comment);
}

void finish(LensPrescription& lens, const std::string& firstComment, const std::string& file) {
  if (lens.description.empty()) lens.description = firstComment;
  if (lens.name.empty()) lens.name = std::filesystem::path(file).stem().string();
  lens.file = file;
}

void checkRowLimit(const LensPrescription& lens, const std::string& file, int line) {
  if (static_cast<int>(lens.surfaces.size()) >= kMaxSurfaces)
    throw InputError(file, "more than " + std::to_string(kMaxSurfaces) + " surfaces: refusing (not a lens?)",
                     line);
}

double number(std::string_view token, const char* what, const std::string& file, int line) {
  const auto v = parseNumber(token);
  if (!v)
    throw InputError(
        file, std::string("expected a number for ") + what + ", got '" + std::string(token) + "'", line);
  return *v;
}

// Optional "k=-0.5 A4=1.2e-6 ... A16=..." tokens at the end of a table row:
// the surface's conic constant and aspheric coefficients. Removed from tokens.
void readAsphericTokens(std::vector<std::string_view>& tokens, Surface& s, const std::string& file,
                        int line) {
  std::array<bool, 1 + kAsphericTerms> seen{};
  while (!tokens.empty() && tokens.back().find('=') != std::string_view::npos) {
    const std::string_view token = tokens.back();
    const std::size_t eq = token.find('=');
    const std::string key = asciiLower(token.substr(0, eq));
    int slot = -1;  // 0: k, 1 + j: A_{2j+4}
    if (key == "k") {
      slot = 0;
    } else if (key.size() > 1 && key[0] == 'a' && key[1] != '0') {
      // A4, A6, ... A16 (parsed rather than compared with "a" + to_string,
      // which sets off GCC 12's false -Wrestrict alarm, bug 105329).
      int order = 0;
      const char* end = key.data() + key.size();
      const auto [last, ec] = std::from_chars(key.data() + 1, end, order);
      if (ec == std::errc() && last == end && order >= 4 && order % 2 == 0 &&
          (order - 4) / 2 < kAsphericTerms)
        slot = 1 + (order - 4) / 2;
    }
    if (slot < 0)
      throw InputError(file,
                       "unknown aspheric term '" + std::string(token.substr(0, eq)) +
                           "' (expected k, A4, A6, A8, A10, A12, A14 or A16)",
                       line);
    if (seen[slot])
      throw InputError(file, "aspheric term '" + std::string(token.substr(0, eq)) + "' given twice", line);
    seen[slot] = true;
    const std::string what = "aspheric term " + std::string(token.substr(0, eq));
    const double v = number(token.substr(eq + 1), what.c_str(), file, line);
    (slot == 0 ? s.conic : s.aspheric[slot - 1]) = v;
    tokens.pop_back();
  }
  for (const std::string_view t : tokens)
    if (t.find('=') != std::string_view::npos)
      throw InputError(file, "aspheric terms (" + std::string(t) + ") must come after the other columns",
                       line);
}

}  // namespace

LensPrescription parsePbrtLens(std::string_view text, const std::string& file) {
  LensPrescription lens;
  std::string firstComment;
  bool loneFocalLength = false;
  for (const TextLine& l : splitLines(text)) {
    if (const std::string_view c = commentOf(l.text); !c.empty() && lens.surfaces.empty())
      readMetadataComment(c, lens, firstComment, file, l.number);
    const auto tokens = tokenize(l.text);
    if (tokens.empty()) continue;
    // ISET's and pbrt-v3's files give the nominal focal length as a lone
    // number before the first surface row ("# Focal length (mm)", "50.000").
    if (tokens.size() == 1 && lens.surfaces.empty() && !loneFocalLength) {
      if (const auto f = parseNumber(tokens[0])) {
        if (!(*f > 0.0) || *f > kMaxLengthMm)
          throw InputError(
              file,
              "the focal length before the first surface must be a positive number of mm, got '" +
                  std::string(tokens[0]) + "'",
              l.number);
        lens.nominalFocalLengthMm = *f;
        loneFocalLength = true;
        continue;
      }
    }
    if (tokens.size() != 4)
      throw InputError(file,
                       "expected 4 columns (radius, thickness, index, aperture diameter), got " +
                           std::to_string(tokens.size()),
                       l.number);
    checkRowLimit(lens, file, l.number);
    Surface s;
    s.line = l.number;
    s.radius = number(tokens[0], "the radius", file, l.number);
    s.thickness = number(tokens[1], "the thickness", file, l.number);
    const double n = number(tokens[2], "the index", file, l.number);
    s.apertureDiameter = number(tokens[3], "the aperture diameter", file, l.number);
    s.medium.nd = (n == 0.0) ? 1.0 : n;  // pbrt writes 0 for air at the stop
    s.isStop = s.radius == 0.0;
    lens.surfaces.push_back(s);
  }
  finish(lens, firstComment, file);
  return lens;
}

LensPrescription parseTableLens(std::string_view text, const std::string& file) {
  LensPrescription lens;
  std::string firstComment;
  bool headerAllowed = true;
  for (const TextLine& l : splitLines(text)) {
    if (const std::string_view c = commentOf(l.text); !c.empty() && lens.surfaces.empty())
      readMetadataComment(c, lens, firstComment, file, l.number);
    auto tokens = tokenize(l.text);
    if (tokens.empty()) continue;
    const std::string first = asciiLower(tokens[0]);
    if (headerAllowed && first == "radius") {
      headerAllowed = false;
      continue;
    }
    headerAllowed = false;
    checkRowLimit(lens, file, l.number);
    Surface s;
    s.line = l.number;
    const bool stopWord = first == "stop" || first == "(stop)";
    const bool flatWord = first == "flat";
    s.radius = (stopWord || flatWord) ? 0.0 : number(tokens[0], "the radius", file, l.number);
    s.isStop = stopWord || (!flatWord && s.radius == 0.0);
    readAsphericTokens(tokens, s, file, l.number);
    // An optional trailing glass name on a glass row.
    if (tokens.size() == 6 && !parseNumber(tokens[5])) {
      s.medium.glass = std::string(tokens[5]);
      tokens.pop_back();
    }
    if (tokens.size() == 5) {
      s.thickness = number(tokens[1], "the thickness", file, l.number);
      s.medium.nd = number(tokens[2], "n_d", file, l.number);
      s.medium.vd = number(tokens[3], "V_d (Abbe number)", file, l.number);
      s.apertureDiameter = number(tokens[4], "the aperture diameter", file, l.number);
    } else if (tokens.size() == 3) {
      s.thickness = number(tokens[1], "the thickness", file, l.number);
      s.apertureDiameter = number(tokens[2], "the aperture diameter", file, l.number);
    } else {
      throw InputError(file,
                       "expected 5 columns (radius thickness n_d V_d aperture) or 3 (radius thickness "
                       "aperture, in air), got " +
                           std::to_string(tokens.size()),
                       l.number);
    }
    lens.surfaces.push_back(s);
  }
  finish(lens, firstComment, file);
  return lens;
}

}  // namespace lensrt
