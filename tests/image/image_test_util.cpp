#include "image_test_util.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>

namespace lensrt::test {

namespace fs = std::filesystem;

ScratchDir::ScratchDir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string name = info ? std::string(info->test_suite_name()) + "." + info->name() : "scratch";
  path_ = fs::temp_directory_path() / ("lensrt_image_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(path_);
  fs::create_directories(path_);
}

ScratchDir::~ScratchDir() {
  std::error_code ignored;
  // Restore write permission in case a test made the directory read-only.
  fs::permissions(path_, fs::perms::owner_all, fs::perm_options::add, ignored);
  fs::remove_all(path_, ignored);
}

std::vector<std::string> ScratchDir::entries() const {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(path_)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

Image constantImage(int width, int height, const std::vector<std::string>& channels, float value) {
  Image image(width, height, channels);
  std::fill(image.pixels.begin(), image.pixels.end(), value);
  return image;
}

std::string readFileBytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

CommandResult runCommand(const std::string& command) {
  CommandResult result;
  // popen/pclose pair up here with nothing in between that can throw.
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buffer;
  std::size_t n;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.output.append(buffer.data(), n);
  const int status = ::pclose(pipe);
  result.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

std::string shellQuote(const std::string& s) {
  std::string q = "'";
  for (const char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

}  // namespace lensrt::test

namespace lensrt::test {

double texturedTruth(int x, int y, int channel) {
  const bool check = ((x / 4) + (y / 4)) % 2 == 1;
  return 0.25 + (check ? 0.5 : 0.0) + 0.05 * channel + 0.1 * std::sin(0.37 * x + 0.21 * y);
}

Image noisyRender(int width, int height, unsigned seed, int spp, double sampleNoise, double gain,
                  int shiftX) {
  Image image(width, height, {"R", "G", "B", "variance.R", "variance.G", "variance.B"});
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  std::chi_squared_distribution<double> chiSquared(spp - 1);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c) {
        const double truth = texturedTruth(x + shiftX, y, c);
        const double meanSigma = sampleNoise * truth / std::sqrt(double(spp));
        // The sample mean and sample variance of normal samples are
        // independent: a normal and a scaled chi-square with spp-1 degrees.
        const double mean = truth + meanSigma * normal(rng);
        const double variance = meanSigma * meanSigma * chiSquared(rng) / (spp - 1);
        image.at(x, y, c) = float(gain * mean);
        image.at(x, y, 3 + c) = float(gain * gain * variance);
      }
  return image;
}

}  // namespace lensrt::test
