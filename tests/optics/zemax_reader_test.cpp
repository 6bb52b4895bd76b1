// Zemax .zmx import: the test files in tests/optics/zemax/ were written in
// OpticStudio's exported layout from published prescriptions; their focal
// lengths are checked against the published values, and what the reader
// refuses against its messages.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "core/error.h"
#include "optics/lens_readers.h"
#include "optics/paraxial.h"
#include "optics_test_util.h"

namespace lensrt {
namespace {

const std::string kZemaxDir = std::string(LENSRT_TEST_DATA_DIR) + "/optics/zemax/";

std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A small file in the exported layout: object at infinity, `body` = the lens
// surfaces' SURF blocks (numbered from 1), then the image surface.
std::string zmx(const std::string& body, int imageSurface,
                const std::string& head = "UNIT MM X W X CM MR CPMM") {
  return "VERS 190513 80 123457\nMODE SEQ\nNAME test\n" + head +
         "\nENPD 10\nSURF 0\n  TYPE STANDARD\n  CURV 0.0 0 0 0 0 \"\"\n  DISZ INFINITY\n" + body + "SURF " +
         std::to_string(imageSurface) + "\n  TYPE STANDARD\n  CURV 0\n  DISZ 0\n  DIAM 5 0 0 0 1 \"\"\n";
}

// A biconvex singlet, R = +-50 mm, 5 mm thick, with a flat stop in front.
const std::string kSinglet =
    "SURF 1\n  STOP\n  TYPE STANDARD\n  CURV 0.0 0 0 0 0 \"\"\n  DISZ 1\n  DIAM 5 1 0 0 1 \"\"\n"
    "SURF 2\n  TYPE STANDARD\n  CURV 2.0E-002 0 0 0 0 \"\"\n  DISZ 5\n  GLAS N-BK7 0 0 0 0 0 0 0 0 0 0\n"
    "  DIAM 10 1 0 0 1 \"\"\n"
    "SURF 3\n  TYPE STANDARD\n  CURV -2.0E-002 0 0 0 0 \"\"\n  DISZ 48\n  DIAM 10 1 0 0 1 \"\"\n";

std::string errorOf(const std::string& text) {
  try {
    validatePrescription(parseZemaxLens(text, "t.zmx"));
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

// Thick-lens EFL of a singlet in air, closed form (lensmaker's equation).
double singletEfl(double r1, double r2, double t, double n) {
  return 1.0 / ((n - 1.0) * (1.0 / r1 - 1.0 / r2 + (n - 1.0) * t / (n * r1 * r2)));
}

TEST(Zemax, DoubleGaussInUtf16IsTheLecturesTable) {
  const LensPrescription lens = loadLens(kZemaxDir + "dgauss-100mm-utf16le.zmx");
  const LensPrescription table = test::libraryLens("dgauss-100mm");
  ASSERT_EQ(lens.surfaces.size(), table.surfaces.size());
  EXPECT_EQ(lens.stopIndex(), table.stopIndex());
  for (std::size_t i = 0; i < lens.surfaces.size(); ++i) {
    SCOPED_TRACE(i);
    const Surface &a = lens.surfaces[i], &b = table.surfaces[i];
    EXPECT_NEAR(a.radius, b.radius, 1e-9 * std::abs(b.radius));
    EXPECT_NEAR(a.thickness, b.thickness, 1e-12);
    EXPECT_NEAR(a.apertureDiameter, b.apertureDiameter, 1e-12);
    EXPECT_EQ(a.medium.nd, b.medium.nd);
    EXPECT_EQ(a.medium.vd, b.medium.vd);
  }
  EXPECT_EQ(lens.description, "Double Gauss F/2 (US 2,673,491), the seed lecture's table");
  // Published (the lecture, ../shared/seed/README.md): "an effective focal
  // length of about 100.7 mm" (nominally a 100 mm lens).
  const double efl = computeParaxial(lens).efl;
  EXPECT_NEAR(efl / 100.7, 1.0, 0.005);
  EXPECT_NEAR(efl, computeParaxial(table).efl, 1e-9);
}

// The same file as ASCII and as big-endian UTF-16 with a BOM reads the same.
TEST(Zemax, AsciiAndBigEndianUtf16ReadTheSame) {
  const std::string le = readBytes(kZemaxDir + "dgauss-100mm-utf16le.zmx");
  ASSERT_GT(le.size(), 100u);
  ASSERT_EQ(le.substr(0, 2), "\xFF\xFE");
  std::string ascii, be = "\xFE\xFF";
  for (std::size_t i = 2; i + 1 < le.size(); i += 2) {
    ASSERT_EQ(le[i + 1], '\0');  // the file is plain ASCII in UTF-16
    ascii += le[i];
    be += '\0';
    be += le[i];
  }
  const LensPrescription fromLe = parseZemaxLens(le, "le.zmx");
  for (const std::string& text : {ascii, be}) {
    const LensPrescription lens = parseZemaxLens(text, "x.zmx");
    ASSERT_EQ(lens.surfaces.size(), fromLe.surfaces.size());
    for (std::size_t i = 0; i < lens.surfaces.size(); ++i) {
      EXPECT_EQ(lens.surfaces[i].radius, fromLe.surfaces[i].radius);
      EXPECT_EQ(lens.surfaces[i].thickness, fromLe.surfaces[i].thickness);
      EXPECT_EQ(lens.surfaces[i].line, fromLe.surfaces[i].line);
    }
  }
  // A truncated UTF-16 file (odd byte count) is refused.
  EXPECT_NE(errorOf(be.substr(0, 101)).find("odd number of bytes"), std::string::npos);
}

TEST(Zemax, CookeTripletInInchesWithCatalogueGlasses) {
  const LensPrescription lens = loadLens(kZemaxDir + "cooke-triplet-inches.zmx");
  const LensPrescription table = test::libraryLens("cooke-triplet-100mm");
  ASSERT_EQ(lens.surfaces.size(), table.surfaces.size());
  for (std::size_t i = 0; i < lens.surfaces.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_NEAR(lens.surfaces[i].radius, table.surfaces[i].radius, 1e-9 * std::abs(table.surfaces[i].radius));
    EXPECT_NEAR(lens.surfaces[i].thickness, table.surfaces[i].thickness, 1e-9);
    EXPECT_NEAR(lens.surfaces[i].apertureDiameter, table.surfaces[i].apertureDiameter, 1e-9);
    EXPECT_EQ(lens.surfaces[i].medium.nd, table.surfaces[i].medium.nd);
  }
  EXPECT_EQ(lens.surfaces[0].medium.glass, "SK4");
  EXPECT_EQ(lens.surfaces[2].medium.glass, "SF2");
  EXPECT_TRUE(lens.surfaces[0].medium.sellmeier.has_value());
  // Smith: EFL 101.181 mm.
  EXPECT_NEAR(computeParaxial(lens).efl / 101.181, 1.0, 0.005);
}

TEST(Zemax, EvenAsphereWithTheStopOnIt) {
  const LensPrescription lens = loadLens(kZemaxDir + "thorlabs-al50100j-evenasph.zmx");
  // The stop on the aspheric (convex) surface becomes a flat stop at its
  // vertex, in front of it: the layout of lenses/thorlabs-al50100j-100mm.lens.
  ASSERT_EQ(lens.surfaces.size(), 3u);
  EXPECT_EQ(lens.stopIndex(), 0);
  EXPECT_EQ(lens.surfaces[0].thickness, 0.0);
  EXPECT_EQ(lens.surfaces[0].apertureDiameter, 45.0);
  const Surface& asphere = lens.surfaces[1];
  EXPECT_NEAR(asphere.radius, 50.3583, 1e-9);
  EXPECT_EQ(asphere.conic, -0.789119);
  EXPECT_EQ(asphere.aspheric[0], 2.10405e-7);  // PARM 2: r^4
  EXPECT_EQ(asphere.aspheric[1], 1.76468e-11);
  EXPECT_EQ(asphere.aspheric[2], 1.02641e-15);
  EXPECT_EQ(asphere.aspheric[3], 0.0);
  // Thorlabs: EFL 100.0 mm at 1310 nm (n = 1.5036); a plano-convex lens's EFL
  // is R / (n - 1) whatever its thickness.
  const double efl = computeParaxial(lens).efl;
  EXPECT_NEAR(efl / 100.0, 1.0, 0.005);
  EXPECT_NEAR(efl, 50.3583 / 0.5036, 1e-9);
}

TEST(Zemax, UnitsScaleLengthsAndAsphericTerms) {
  // The same asphere in cm: lengths x10, A_n x 10^(1-n).
  const std::string body =
      "SURF 1\n  STOP\n  TYPE EVENASPH\n  CURV 0.2\n  DISZ 0.5\n  GLAS ___BLANK 1 0 1.5 60 0 0 0 0 0 0\n"
      "  CONI -0.5\n  PARM 1 0\n  PARM 2 1E-3\n  PARM 3 2E-5\n  DIAM 1 1 0 0 1 \"\"\n"
      "SURF 2\n  TYPE STANDARD\n  CURV 0\n  DISZ 9\n  DIAM 1 0 0 0 1 \"\"\n";
  for (const auto& [unit, mm] : {std::pair{"MM", 1.0}, {"CM", 10.0}, {"IN", 25.4}, {"METER", 1000.0}}) {
    SCOPED_TRACE(unit);
    const LensPrescription lens =
        parseZemaxLens(zmx(body, 3, std::string("UNIT ") + unit + " X W X CM MR CPMM"), "u.zmx");
    ASSERT_EQ(lens.surfaces.size(), 3u);
    const Surface& s = lens.surfaces[1];
    EXPECT_NEAR(s.radius, 5.0 * mm, 1e-12 * mm);
    EXPECT_NEAR(s.thickness, 0.5 * mm, 1e-12 * mm);
    EXPECT_NEAR(s.apertureDiameter, 2.0 * mm, 1e-12 * mm);
    EXPECT_NEAR(lens.surfaces[2].thickness, 9.0 * mm, 1e-12 * mm);
    EXPECT_EQ(s.conic, -0.5);
    EXPECT_NEAR(s.aspheric[0], 1e-3 / (mm * mm * mm), 1e-15 / (mm * mm * mm));
    EXPECT_NEAR(s.aspheric[1], 2e-5 / std::pow(mm, 5), 1e-17 / std::pow(mm, 5));
    // The sag at the rim scales with the lens.
    EXPECT_NEAR(s.sag(mm), mm * (0.2 / (1.0 + std::sqrt(1.0 - 0.5 * 0.04)) + 1e-3 + 2e-5), 1e-12 * mm);
  }
}

TEST(Zemax, SingletFocalLengthAndCatalogueGlass) {
  const LensPrescription lens = parseZemaxLens(zmx(kSinglet, 4), "s.zmx");
  ASSERT_EQ(lens.surfaces.size(), 3u);
  EXPECT_EQ(lens.surfaces[1].medium.glass, "N-BK7");
  EXPECT_EQ(lens.surfaces[1].medium.nd, 1.5168);
  EXPECT_NEAR(computeParaxial(lens).efl, singletEfl(50, -50, 5, 1.5168), 1e-9);
}

TEST(Zemax, DummySurfacesAreDroppedAndTheirDistanceKept) {
  std::string body = kSinglet;
  // A flat air surface between the stop and the lens, semi-diameter 0.
  body.replace(body.find("SURF 2"), 0,
               "SURF 2\n  TYPE STANDARD\n  CURV 0\n  DISZ 2\n  DIAM 0 0 0 0 1 \"\"\n");
  body.replace(body.find("SURF 2\n  TYPE STANDARD\n  CURV 2.0"), 6, "SURF 3");
  body.replace(body.find("SURF 3\n  TYPE STANDARD\n  CURV -2"), 6, "SURF 4");
  const LensPrescription lens = parseZemaxLens(zmx(body, 5), "d.zmx");
  ASSERT_EQ(lens.surfaces.size(), 3u);
  EXPECT_EQ(lens.surfaces[0].thickness, 3.0);
  EXPECT_NO_THROW(validatePrescription(lens));
}

TEST(Zemax, StopOnAConcaveSurfaceGoesBehindIt) {
  // A meniscus whose front (concave toward the object) is the stop.
  const std::string body =
      "SURF 1\n  STOP\n  TYPE STANDARD\n  CURV -0.02\n  DISZ 4\n  GLAS ___BLANK 1 0 1.6 40 0 0 0 0 0 0\n"
      "  DIAM 8 0 0 0 1 \"\"\n"
      "SURF 2\n  TYPE STANDARD\n  CURV -0.04\n  DISZ 60\n  DIAM 9 0 0 0 1 \"\"\n";
  const LensPrescription lens = parseZemaxLens(zmx(body, 3), "m.zmx");
  ASSERT_EQ(lens.surfaces.size(), 3u);
  EXPECT_EQ(lens.stopIndex(), 1);
  EXPECT_EQ(lens.surfaces[0].thickness, 0.0);
  EXPECT_EQ(lens.surfaces[1].thickness, 4.0);
  EXPECT_EQ(lens.surfaces[1].medium.nd, 1.6);  // the stop sits in the glass
  EXPECT_EQ(lens.surfaces[1].apertureDiameter, 16.0);
  EXPECT_NO_THROW(validatePrescription(lens));
  EXPECT_NEAR(computeParaxial(lens).efl, singletEfl(-50, -25, 4, 1.6), 1e-9);
}

TEST(Zemax, UnknownNameWithNdOnTheLineUsesIt) {
  std::string body = kSinglet;
  body.replace(body.find("N-BK7 0 0 0 0"), 13, "S-BSL7 0 0 1.51633 64.14");
  const LensPrescription lens = parseZemaxLens(zmx(body, 4), "o.zmx");
  EXPECT_EQ(lens.surfaces[1].medium.nd, 1.51633);
  EXPECT_EQ(lens.surfaces[1].medium.vd, 64.14);
  EXPECT_EQ(lens.surfaces[1].medium.glass, "S-BSL7");
  EXPECT_FALSE(lens.surfaces[1].medium.sellmeier.has_value());
}

TEST(Zemax, RefusesWhatItDoesNotSupport) {
  const auto with = [](const std::string& from, const std::string& to) {
    std::string body = kSinglet;
    body.replace(body.find(from), from.size(), to);
    return errorOf(zmx(body, 4));
  };
  EXPECT_EQ(with("GLAS N-BK7", "GLAS UNOBTAINIUM"),
            "t.zmx:20: SURF 2: unknown glass 'UNOBTAINIUM' (not in the built-in catalogue, and the GLAS line "
            "gives no n_d; see lenses/README.md)");
  EXPECT_EQ(with("GLAS N-BK7 0 0 0 0 0 0 0 0 0 0", "GLAS MIRROR 0 0"),
            "t.zmx:20: SURF 2: glass MIRROR is not supported: lensrt traces refracting lenses only");
  EXPECT_EQ(with("TYPE STANDARD\n  CURV -2", "TYPE COORDBRK\n  CURV -2"),
            "t.zmx:23: SURF 3: coordinate breaks (TYPE COORDBRK) are not supported");
  EXPECT_EQ(with("TYPE STANDARD\n  CURV 2", "TYPE GRADIENT\n  CURV 2"),
            "t.zmx:17: SURF 2: gradient-index surfaces (TYPE GRADIENT) are not supported");
  EXPECT_EQ(with("TYPE STANDARD\n  CURV 2", "TYPE TOROIDAL\n  CURV 2"),
            "t.zmx:17: SURF 2: surface TYPE TOROIDAL is not supported (only STANDARD and EVENASPH)");
  EXPECT_EQ(
      with("TYPE STANDARD\n  CURV 2", "TYPE EVENASPH\n  PARM 1 1E-3\n  CURV 2"),
      "t.zmx:18: SURF 2: EVENASPH PARM 1 (the r^2 term) is not zero: lensrt's even asphere starts at r^4 "
      "(fold the r^2 term into CURV)");
  EXPECT_EQ(with("DISZ 48", "DISZ INFINITY"),
            "t.zmx:22: SURF 3: DISZ INFINITY is only allowed on the object surface (SURF 0)");
  EXPECT_EQ(errorOf(zmx(kSinglet, 4, "MODE NSC")),
            "t.zmx:4: non-sequential (MODE NSC) files are not supported: only sequential lenses");
  EXPECT_EQ(errorOf(zmx(kSinglet, 4, "UNIT FURLONG")),
            "t.zmx:4: unknown lens unit 'FURLONG' (expected MM, CM, IN or METER)");
  EXPECT_EQ(errorOf(zmx(kSinglet, 5)), "t.zmx:27: SURF 5 out of order (expected SURF 4)");
  EXPECT_EQ(
      errorOf("SURF 0\n  DISZ INFINITY\nSURF 1\n"),
      "t.zmx: expected an object surface (SURF 0), at least one lens surface and the image surface, got 2 "
      "SURF blocks");
  // Surface keywords before the first SURF are not read (nor refused).
  EXPECT_EQ(
      errorOf("CURV 0.1\nSTOP\n"),
      "t.zmx: expected an object surface (SURF 0), at least one lens surface and the image surface, got 0 "
      "SURF blocks");
  EXPECT_EQ(with("TYPE STANDARD\n  CURV 2", "TYPE EVENASPH\n  PARM 9 1E-3\n  CURV 2"),
            "t.zmx:18: SURF 2: EVENASPH has no PARM 9 (PARM 1..8 are the r^2..r^16 terms)");
  // Validation's messages name the SURF too.
  EXPECT_EQ(with("DIAM 10 1 0 0 1 \"\"\nSURF 3", "DIAM 0 1 0 0 1 \"\"\nSURF 3"),
            "t.zmx:16: SURF 2: aperture diameter must be positive, got 0 mm");
  EXPECT_EQ(errorOf(zmx(kSinglet + "SURF 4\n  CURV abc\n", 5)),
            "t.zmx:28: expected a finite number for CURV, got 'abc'");
  // Control characters are not echoed.
  EXPECT_EQ(
      with("GLAS N-BK7", "GLAS X\x1b[2J"),
      "t.zmx:20: SURF 2: unknown glass 'X?[2J' (not in the built-in catalogue, and the GLAS line gives no "
      "n_d; see lenses/README.md)");
  // Validation's own checks still apply, e.g. no stop.
  EXPECT_EQ(with("  STOP\n", ""), "t.zmx: no aperture stop (mark one surface as the stop)");
}

}  // namespace
}  // namespace lensrt
