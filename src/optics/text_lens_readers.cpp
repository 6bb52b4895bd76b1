// The two line-oriented formats: pbrt's .dat and the seed's table (.lens).
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

#include "core/error.h"
#include "optics/lens_readers.h"
#include "optics/text_lines.h"

namespace lensrt {
namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return std::tolower(c); });
  return out;
}

// "# key: value" header comments fill the metadata; the first other comment
// becomes the description when none is given.
void readMetadataComment(std::string_view comment, LensPrescription& lens, std::string& firstComment,
                         const std::string& file, int line) {
  const std::size_t colon = comment.find(':');
  if (colon != std::string_view::npos) {
    const std::string key = lower(trim(comment.substr(0, colon)));
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

}  // namespace

LensPrescription parsePbrtLens(std::string_view text, const std::string& file) {
  LensPrescription lens;
  std::string firstComment;
  for (const TextLine& l : splitLines(text)) {
    if (const std::string_view c = commentOf(l.text); !c.empty() && lens.surfaces.empty())
      readMetadataComment(c, lens, firstComment, file, l.number);
    const auto tokens = tokenize(l.text);
    if (tokens.empty()) continue;
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
    const std::string first = lower(tokens[0]);
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
