// The golden-image cases (tests/golden/cases.txt) and how to render and
// compare one: shared by the regression test and its sensitivity test.
#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "image/image.h"

namespace lensrt::golden {

// References are rendered with kReferenceSeed (tools/update-references),
// tests with kTestSeed: a different seed, so the comparison is statistical.
inline constexpr int kReferenceSeed = 1;
inline constexpr int kTestSeed = 2;

struct GoldenCase {
  std::string name;               // also the reference's file stem
  std::string scene;              // relative to scenes/
  std::vector<std::string> args;  // render arguments
};

// How GoogleTest names a case in test listings (else it dumps the bytes).
inline void PrintTo(const GoldenCase& c, std::ostream* os) {
  *os << c.name;
}

// Parses cases.txt (throws std::runtime_error naming the line when malformed).
std::vector<GoldenCase> loadCases(const std::filesystem::path& file);
std::vector<GoldenCase> loadCases();  // the project's tests/golden/cases.txt
const GoldenCase& findCase(const std::string& name);

std::filesystem::path referencePath(const GoldenCase& c);

struct RunResult {
  int status = -1;  // exit status, or 128 + signal number
  std::string out, err;
};
RunResult runLensrt(const std::vector<std::string>& args);

// Renders the case as the references are, with the given seed and extra
// arguments appended (options the case does not set already).
RunResult renderCase(const GoldenCase& c, int seed, const std::filesystem::path& output,
                     const std::vector<std::string>& extra = {});

// The case with `option` set to `value` (replaced when the case sets it,
// since lensrt refuses a repeated option; appended otherwise).
GoldenCase withOption(GoldenCase c, const std::string& option, const std::string& value);

// `lensrt diff --noise-aware reference candidate`: exit 0 passes, 2 fails.
RunResult diffWithReference(const GoldenCase& c, const std::filesystem::path& candidate,
                            const std::vector<std::string>& extra = {});

// Perturbations a regression would make, for the tests that the suite can
// fail: R,G,B times `gain` (variance.R/G/B times its square, as a scaled
// estimate's), and every channel moved right by one pixel (the first column
// repeated).
Image gained(Image image, double gain);
Image shifted(const Image& image);

// A fresh empty directory for the current test, removed by the destructor.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

}  // namespace lensrt::golden
