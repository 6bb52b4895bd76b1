// `lensrt lens info`: the JSON carries the paraxial quantities, and bad input
// exits 1 (file problems) or 2 (flag values) with one error line.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

namespace {

struct CommandRun {
  int status = -1;
  std::string out;
};

CommandRun run(const std::string& args) {
  const std::string command = std::string(LENSRT_BINARY) + " " + args + " 2>&1";
  CommandRun r;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buf{};
  while (const std::size_t n = fread(buf.data(), 1, buf.size(), pipe)) r.out.append(buf.data(), n);
  const int status = pclose(pipe);
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

TEST(LensInfo, JsonHasTheSeedsNumbers) {
  const CommandRun r = run("lens info dgauss-100mm --json --focus inf");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["efl_mm"].get<double>(), 100.7, 0.1);
  EXPECT_NEAR(j["bfl_mm"].get<double>(), 72.2, 0.1);
  EXPECT_NEAR(j["film_distance_mm"].get<double>(), 72.2, 0.1);
  for (const char* key : {"ffl_mm", "front_principal_plane_mm", "rear_principal_plane_mm",
                          "entrance_pupil_pos_mm", "entrance_pupil_diameter_mm", "exit_pupil_pos_mm",
                          "exit_pupil_diameter_mm", "f_number", "exit_pupil_efficiency"})
    EXPECT_TRUE(j[key].is_number()) << key;
  // 2 atan(21.63 / 100.7): the diagonal field of a 100 mm lens on full frame.
  EXPECT_NEAR(j["fov_deg"]["diagonal"].get<double>(), 24.25, 0.05);
  EXPECT_NEAR(j["f_number"].get<double>(),
              j["efl_mm"].get<double>() / j["entrance_pupil_diameter_mm"].get<double>(), 1e-9);
  EXPECT_GE(j["exit_pupil_efficiency"].get<double>(), 0.9);
}

TEST(LensInfo, StopDownAndFocusChangeTheAnswer) {
  const auto j = nlohmann::json::parse(run("lens info dgauss-50mm --json --fstop 4 --focus 1").out);
  EXPECT_NEAR(j["f_number"].get<double>(), 4.0, 1e-6);
  EXPECT_GT(j["film_distance_mm"].get<double>(), j["bfl_mm"].get<double>());
  EXPECT_LT(j["magnification"].get<double>(), 0.0);
}

TEST(LensInfo, BadInputExitsWithOneErrorLine) {
  const CommandRun badFile =
      run("lens info " + std::string(LENSRT_TEST_DATA_DIR) + "/optics/bad-lenses/two-stops.lens");
  EXPECT_EQ(badFile.status, 1);
  EXPECT_NE(badFile.out.find("two-stops.lens:5: "), std::string::npos) << badFile.out;
  EXPECT_EQ(run("lens info dgauss-50mm --sensor 36by24").status, 2);
  const CommandRun tooClose = run("lens info dgauss-50mm --focus 0.01");
  EXPECT_EQ(tooClose.status, 1);
  EXPECT_NE(tooClose.out.find("closer than the lens can focus"), std::string::npos) << tooClose.out;
}

}  // namespace
