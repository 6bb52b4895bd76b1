// Zemax OpticStudio sequential lens files (.zmx): see lens_readers.h and
// lenses/README.md for what is read and what is refused.
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "core/error.h"
#include "optics/glass_catalog.h"
#include "optics/lens_readers.h"
#include "optics/text_lines.h"

namespace lensrt {
namespace {

// EVENASPH has eight parameters: PARM 1 is the r^2 coefficient, PARM 2..8
// are r^4..r^16 (lensrt's A4..A16).
constexpr int kEvenAsphereParms = 8;

std::string upper(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return std::toupper(c); });
  return out;
}

// A token echoed in a message: printable ASCII only and short, so that the
// error stays one readable line whatever the file holds.
std::string shown(std::string_view token) {
  std::string out;
  for (const char c : token.substr(0, 40)) out += (c >= 0x20 && c < 0x7f) ? c : '?';
  if (token.size() > 40) out += "...";
  return out;
}

void appendUtf8(std::string& out, std::uint32_t cp) {
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xC0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    out += static_cast<char>(0xE0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (cp >> 18));
    out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  }
}

// OpticStudio writes UTF-16 (little-endian, with a byte order mark) by
// default and ASCII on request. UTF-16 becomes UTF-8 here; a file without a
// BOM whose first character has a zero high byte is UTF-16 too.
std::string decodeText(std::string_view bytes, const std::string& file) {
  bool utf16 = false, bigEndian = false;
  if (bytes.starts_with("\xFF\xFE") || bytes.starts_with("\xFE\xFF")) {
    utf16 = true;
    bigEndian = bytes[0] == '\xFE';
    bytes.remove_prefix(2);
  } else if (bytes.size() >= 2 && (bytes[0] == '\0') != (bytes[1] == '\0')) {
    utf16 = true;
    bigEndian = bytes[0] == '\0';
  }
  if (!utf16) return std::string(bytes);
  if (bytes.size() % 2 != 0) throw InputError(file, "UTF-16 text with an odd number of bytes (truncated?)");
  std::string out;
  out.reserve(bytes.size() / 2);
  const auto unit = [&](std::size_t i) {
    const auto hi = static_cast<unsigned char>(bytes[bigEndian ? i : i + 1]);
    const auto lo = static_cast<unsigned char>(bytes[bigEndian ? i + 1 : i]);
    return static_cast<std::uint32_t>(hi << 8 | lo);
  };
  for (std::size_t i = 0; i < bytes.size(); i += 2) {
    std::uint32_t cp = unit(i);
    if (cp >= 0xD800 && cp < 0xDC00 && i + 2 < bytes.size() && unit(i + 2) >= 0xDC00 &&
        unit(i + 2) < 0xE000) {
      cp = 0x10000 + ((cp - 0xD800) << 10) + (unit(i + 2) - 0xDC00);
      i += 2;
    } else if (cp >= 0xD800 && cp < 0xE000) {
      cp = 0xFFFD;  // an unpaired surrogate
    }
    appendUtf8(out, cp);
  }
  return out;
}

// One SURF block as written, in the file's lens units.
struct ZmxSurface {
  int number = 0;
  int line = 0;
  std::string type = "STANDARD";
  int typeLine = 0;
  double curvature = 0.0;
  double thickness = 0.0;
  bool infiniteThickness = false;
  double conic = 0.0;
  std::array<double, kEvenAsphereParms> parm{};
  int parmLine = 0;   // of PARM 1
  int extraParm = 0;  // a non-zero PARM beyond 8, if any
  int extraParmLine = 0;
  double semiDiameter = 0.0;
  bool stop = false;
  Medium medium;  // after the surface; air unless GLAS says otherwise
  bool glass = false;
  int glassLine = 0;
};

class ZemaxParser {
 public:
  ZemaxParser(const std::string& file) : file_(file) {}

  LensPrescription parse(std::string_view bytes) {
    const std::string text = decodeText(bytes, file_);
    for (const TextLine& l : splitLines(text)) readLine(l);
    LensPrescription lens = build();
    lens.name = std::filesystem::path(file_).stem().string();
    lens.file = file_;
    // Validation numbers surfaces as lensrt does (no object surface, dummies
    // dropped); the user knows them by their SURF numbers.
    try {
      validatePrescription(lens);
    } catch (const InputError& e) {
      const std::string prefix = "surface ";
      const std::size_t colon = e.message().find(": ");
      if (e.line() > 0 && e.message().starts_with(prefix) && colon != std::string::npos)
        for (const ZmxSurface& z : surfaces_)
          if (z.line == e.line()) failSurface(z, e.message().substr(colon + 2), e.line());
      throw;
    }
    return lens;
  }

 private:
  const std::string& file_;
  std::vector<ZmxSurface> surfaces_;
  double mmPerUnit_ = 1.0;
  std::string description_;

  [[noreturn]] void fail(const std::string& message, int line) const {
    throw InputError(file_, message, line);
  }
  [[noreturn]] void failSurface(const ZmxSurface& s, const std::string& message, int line) const {
    fail("SURF " + std::to_string(s.number) + ": " + message, line);
  }

  double number(std::string_view token, const char* what, int line) const {
    const auto v = parseNumber(token);
    if (!v || !std::isfinite(*v))
      fail(std::string("expected a finite number for ") + what + ", got '" + shown(token) + "'", line);
    return *v;
  }

  // The SURF block a surface keyword belongs to; nullptr before the first
  // SURF (the system section: skipped like every keyword not read here).
  ZmxSurface* current() { return surfaces_.empty() ? nullptr : &surfaces_.back(); }

  void readLine(const TextLine& l) {
    // Zemax has no comment syntax, and '#' may occur in names: split on
    // white space only (tokenize would cut at '#').
    std::vector<std::string_view> tokens;
    const std::string_view text = l.text;
    for (std::size_t i = 0; i < text.size();) {
      while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
      const std::size_t start = i;
      while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i]))) ++i;
      if (i > start) tokens.push_back(text.substr(start, i - start));
    }
    if (tokens.empty()) return;
    const std::string key = upper(tokens[0]);
    const int line = l.number;
    const auto need = [&](std::size_t n) {
      if (tokens.size() < n + 1) fail(key + " needs a value", line);
    };
    if (key == "MODE") {
      need(1);
      const std::string mode = upper(tokens[1]);
      if (mode == "NSC")
        fail("non-sequential (MODE NSC) files are not supported: only sequential lenses", line);
      if (mode != "SEQ") fail("unknown MODE '" + shown(tokens[1]) + "' (expected SEQ)", line);
    } else if (key == "NAME") {
      description_ = std::string(trim(text.substr(text.find(tokens[0]) + tokens[0].size())));
      for (char& c : description_)
        if (static_cast<unsigned char>(c) < 0x20) c = ' ';
    } else if (key == "UNIT") {
      need(1);
      const std::string unit = upper(tokens[1]);
      if (unit == "MM")
        mmPerUnit_ = 1.0;
      else if (unit == "CM")
        mmPerUnit_ = 10.0;
      else if (unit == "IN")
        mmPerUnit_ = 25.4;
      else if (unit == "METER" || unit == "M")
        mmPerUnit_ = 1000.0;
      else
        fail("unknown lens unit '" + shown(tokens[1]) + "' (expected MM, CM, IN or METER)", line);
    } else if (key == "SURF") {
      need(1);
      const auto n = parseNumber(tokens[1]);
      const int expected = static_cast<int>(surfaces_.size());
      if (!n || *n != expected)
        fail("SURF " + shown(tokens[1]) + " out of order (expected SURF " + std::to_string(expected) + ")",
             line);
      if (expected >= kMaxSurfaces + 2)
        fail("more than " + std::to_string(kMaxSurfaces) + " surfaces: refusing (not a lens?)", line);
      ZmxSurface s;
      s.number = expected;
      s.line = line;
      surfaces_.push_back(s);
    }
    if (key == "MODE" || key == "NAME" || key == "UNIT" || key == "SURF") return;
    // Surface keywords; before the first SURF they are not ours to read.
    ZmxSurface* const block = current();
    if (!block) return;
    ZmxSurface& s = *block;
    if (key == "TYPE") {
      need(1);
      s.type = upper(tokens[1]);
      s.typeLine = line;
      checkType(s);
    } else if (key == "STOP") {
      s.stop = true;
    } else if (key == "CURV") {
      need(1);
      s.curvature = number(tokens[1], "CURV", line);
    } else if (key == "DISZ") {
      need(1);
      s.infiniteThickness = upper(tokens[1]) == "INFINITY";
      s.thickness = s.infiniteThickness ? 0.0 : number(tokens[1], "DISZ", line);
    } else if (key == "CONI") {
      need(1);
      s.conic = number(tokens[1], "CONI", line);
    } else if (key == "PARM") {
      need(2);
      const auto index = parseNumber(tokens[1]);
      if (!index || *index != std::floor(*index) || *index < 0 || *index > 1000)
        fail("PARM needs a parameter number, got '" + shown(tokens[1]) + "'", line);
      const double value = number(tokens[2], "PARM", line);
      // EVENASPH has eight; other parameter numbers (other types use them)
      // are kept only to refuse a non-zero one on an even asphere.
      if (*index >= 1 && *index <= kEvenAsphereParms) {
        s.parm[static_cast<std::size_t>(*index) - 1] = value;
        if (*index == 1) s.parmLine = line;
      } else if (value != 0.0) {
        s.extraParm = static_cast<int>(*index);
        s.extraParmLine = line;
      }
    } else if (key == "DIAM") {
      need(1);
      s.semiDiameter = number(tokens[1], "DIAM (semi-diameter)", line);
    } else if (key == "GLAS") {
      need(1);
      readGlass(s, tokens, line);
    }
    // Every other keyword (fields, wavelengths, tolerances, ...) is skipped.
  }

  void checkType(const ZmxSurface& s) const {
    const std::string& t = s.type;
    if (t == "STANDARD" || t == "EVENASPH") return;
    if (t == "COORDBRK") failSurface(s, "coordinate breaks (TYPE COORDBRK) are not supported", s.typeLine);
    if (t.starts_with("GRAD") || t.starts_with("GRIN"))
      failSurface(s, "gradient-index surfaces (TYPE " + shown(t) + ") are not supported", s.typeLine);
    if (t.starts_with("NONSEQ"))
      failSurface(s, "non-sequential components (TYPE " + shown(t) + ") are not supported", s.typeLine);
    failSurface(s, "surface TYPE " + shown(t) + " is not supported (only STANDARD and EVENASPH)", s.typeLine);
  }

  // GLAS name solve pickup n_d V_d ...: a catalogue name, a model glass
  // (___BLANK) with n_d and V_d on the line, or MIRROR.
  void readGlass(ZmxSurface& s, const std::vector<std::string_view>& tokens, int line) {
    const std::string name = upper(tokens[1]);
    s.glass = true;
    s.glassLine = line;
    const auto field = [&](std::size_t i) -> double {
      if (i >= tokens.size()) return 0.0;
      return number(tokens[i], i == 4 ? "n_d on the GLAS line" : "V_d on the GLAS line", line);
    };
    if (name == "MIRROR")
      failSurface(s, "glass MIRROR is not supported: lensrt traces refracting lenses only", line);
    if (name == "___BLANK") {
      const double nd = field(4), vd = field(5);
      if (!(nd >= 1.0)) failSurface(s, "model glass (___BLANK) needs n_d >= 1 on the GLAS line", line);
      s.medium = Medium{nd, vd, "", std::nullopt};
      return;
    }
    if (std::optional<Medium> m = findCatalogGlass(name)) {
      s.medium = *m;
      return;
    }
    // Not in the built-in catalogue: OpticStudio writes a catalogue glass's
    // n_d and V_d on the line too when it has them; with them zero, all that
    // is known is the name.
    const double nd = field(4), vd = field(5);
    if (nd > 1.0) {
      s.medium = Medium{nd, vd, std::string(tokens[1]), std::nullopt};
      return;
    }
    failSurface(s,
                "unknown glass '" + shown(tokens[1]) +
                    "' (not in the built-in catalogue, and the GLAS line gives no n_d; see lenses/README.md)",
                line);
  }

  Surface toSurface(const ZmxSurface& z) const {
    if (z.infiniteThickness)
      failSurface(z, "DISZ INFINITY is only allowed on the object surface (SURF 0)", z.line);
    Surface s;
    s.line = z.line;
    s.radius = z.curvature != 0.0 ? 1.0 / z.curvature : 0.0;
    s.thickness = z.thickness;
    s.apertureDiameter = 2.0 * z.semiDiameter;
    s.medium = z.medium;
    s.conic = z.conic;
    if (z.type == "EVENASPH") {
      if (z.extraParm != 0)
        failSurface(
            z, "EVENASPH has no PARM " + std::to_string(z.extraParm) + " (PARM 1..8 are the r^2..r^16 terms)",
            z.extraParmLine);
      if (z.parm[0] != 0.0)
        failSurface(z,
                    "EVENASPH PARM 1 (the r^2 term) is not zero: lensrt's even asphere starts at r^4 "
                    "(fold the r^2 term into CURV)",
                    z.parmLine);
      for (int j = 0; j < kAsphericTerms; ++j) s.aspheric[j] = z.parm[j + 1];
    }
    return s;
  }

  LensPrescription build() const {
    if (surfaces_.size() < 3)
      fail("expected an object surface (SURF 0), at least one lens surface and the image surface, got " +
               std::to_string(surfaces_.size()) + " SURF blocks",
           0);
    const ZmxSurface& object = surfaces_.front();
    const ZmxSurface& image = surfaces_.back();
    if (object.stop) failSurface(object, "the object surface cannot be the stop", object.line);
    if (image.stop) failSurface(image, "the image surface cannot be the stop", image.line);
    if (!object.medium.isAir())
      failSurface(object, "an object in glass is not supported (object space must be air)", object.glassLine);
    if (image.infiniteThickness)
      failSurface(image, "DISZ INFINITY is only allowed on the object surface (SURF 0)", image.line);

    LensPrescription lens;
    lens.description = description_;
    lens.source = "Zemax OpticStudio file";
    const Medium* before = &object.medium;
    for (std::size_t k = 1; k + 1 < surfaces_.size(); ++k) {
      const ZmxSurface& z = surfaces_[k];
      Surface s = toSurface(z);
      const bool sameMedium = s.medium.nd == before->nd && s.medium.vd == before->vd;
      if (!z.stop && s.radius == 0.0 && !s.isAspheric() && sameMedium) {
        // A dummy surface (flat, no change of medium): no optical effect, and
        // its semi-diameter is often 0. Its distance goes to the previous one.
        if (!lens.surfaces.empty()) lens.surfaces.back().thickness += s.thickness;
        before = &z.medium;
        continue;
      }
      if (z.stop && (s.radius != 0.0 || s.isAspheric() || !sameMedium)) {
        // The stop on a refracting surface: lensrt's stop is a flat surface
        // of its own. It goes at the surface's vertex plane (paraxially the
        // same place), on the side its rim does not cross: in front when
        // the surface bulges toward the film, behind otherwise.
        Surface stop;
        stop.line = z.line;
        stop.isStop = true;
        stop.apertureDiameter = s.apertureDiameter;
        if (s.minSag() >= 0.0) {
          stop.medium = *before;
          lens.surfaces.push_back(stop);
          lens.surfaces.push_back(s);
        } else {
          stop.medium = s.medium;
          stop.thickness = s.thickness;
          s.thickness = 0.0;
          lens.surfaces.push_back(s);
          lens.surfaces.push_back(stop);
        }
      } else {
        s.isStop = z.stop;
        lens.surfaces.push_back(s);
      }
      before = &z.medium;
    }
    if (lens.surfaces.empty()) fail("no lens surfaces between the object and the image surface", 0);
    if (!lens.surfaces.back().medium.isAir())
      failSurface(surfaces_[surfaces_.size() - 2], "the image space must be air",
                  surfaces_[surfaces_.size() - 2].glassLine);
    return mmPerUnit_ == 1.0 ? lens : lens.scaled(mmPerUnit_);
  }
};

}  // namespace

LensPrescription parseZemaxLens(std::string_view text, const std::string& file) {
  LensPrescription lens = ZemaxParser(file).parse(text);
  lens.name = std::filesystem::path(file).stem().string();
  lens.file = file;
  return lens;
}

}  // namespace lensrt
