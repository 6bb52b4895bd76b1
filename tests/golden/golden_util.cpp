#include "golden/golden_util.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

extern char** environ;

namespace lensrt::golden {
namespace {

std::string readFile(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::atomic<int> tempCounter{0};

}  // namespace

std::vector<GoldenCase> loadCases(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  std::vector<GoldenCase> cases;
  int lineNumber = 0;
  for (std::string line; std::getline(in, line);) {
    ++lineNumber;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    GoldenCase c;
    if (!(words >> c.name)) continue;  // blank or comment
    if (!(words >> c.scene))
      throw std::runtime_error(file.string() + ":" + std::to_string(lineNumber) + ": case without a scene");
    for (std::string w; words >> w;) c.args.push_back(w);
    cases.push_back(std::move(c));
  }
  return cases;
}

std::vector<GoldenCase> loadCases() {
  return loadCases(std::string(LENSRT_TEST_DATA_DIR) + "/golden/cases.txt");
}

const GoldenCase& findCase(const std::string& name) {
  static const std::vector<GoldenCase> cases = loadCases();
  for (const auto& c : cases)
    if (c.name == name) return c;
  throw std::runtime_error("no golden case named " + name);
}

std::filesystem::path referencePath(const GoldenCase& c) {
  return std::filesystem::path(LENSRT_TEST_DATA_DIR) / "references" / (c.name + ".exr");
}

RunResult runLensrt(const std::vector<std::string>& args) {
  const TempDir io;
  const std::string outPath = (io / "stdout").string(), errPath = (io / "stderr").string();
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<std::string> argvStrings{LENSRT_BINARY};
  argvStrings.insert(argvStrings.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& s : argvStrings) argv.push_back(s.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, LENSRT_BINARY, &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw std::runtime_error(std::string("cannot run lensrt: ") + std::strerror(rc));
  int wstatus = 0;
  waitpid(pid, &wstatus, 0);
  RunResult r;
  r.status = WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : 128 + WTERMSIG(wstatus);
  r.out = readFile(outPath);
  r.err = readFile(errPath);
  return r;
}

RunResult renderCase(const GoldenCase& c, int seed, const std::filesystem::path& output,
                     const std::vector<std::string>& extra) {
  std::vector<std::string> args{"render", std::string(LENSRT_SOURCE_DIR) + "/scenes/" + c.scene};
  args.insert(args.end(), c.args.begin(), c.args.end());
  // Must match tools/update-references.
  args.insert(args.end(), {"--aov", "variance", "--threads", "1", "--seed", std::to_string(seed), "-q"});
  args.insert(args.end(), extra.begin(), extra.end());
  args.insert(args.end(), {"-o", output.string()});
  return runLensrt(args);
}

GoldenCase withOption(GoldenCase c, const std::string& option, const std::string& value) {
  const auto it = std::find(c.args.begin(), c.args.end(), option);
  if (it != c.args.end() && it + 1 != c.args.end())
    *(it + 1) = value;
  else
    c.args.insert(c.args.end(), {option, value});
  return c;
}

RunResult diffWithReference(const GoldenCase& c, const std::filesystem::path& candidate,
                            const std::vector<std::string>& extra) {
  std::vector<std::string> args{"diff", "--noise-aware", referencePath(c).string(), candidate.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  return runLensrt(args);
}

Image gained(Image image, double gain) {
  for (const char* c : {"R", "G", "B"}) {
    const int v = image.channelIndex(c), var = image.channelIndex(std::string("variance.") + c);
    if (v < 0 || var < 0)
      throw std::runtime_error(std::string("gained: no channel ") + c + " or its variance");
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        image.at(x, y, v) *= float(gain);
        image.at(x, y, var) *= float(gain * gain);
      }
  }
  return image;
}

Image shifted(const Image& original) {
  Image image = original;
  for (int y = 0; y < image.height; ++y)
    for (int x = 1; x < image.width; ++x)
      for (int c = 0; c < int(image.channelCount()); ++c) image.at(x, y, c) = original.at(x - 1, y, c);
  return image;
}

TempDir::TempDir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = info ? std::string(info->test_suite_name()) + "." + info->name() : "lensrt";
  for (char& ch : name)
    if (ch == '/') ch = '_';  // parameterised test names
  path_ = std::filesystem::temp_directory_path() /
          ("lensrt_golden_" + name + "_" + std::to_string(getpid()) + "_" + std::to_string(tempCounter++));
  std::filesystem::remove_all(path_);
  std::filesystem::create_directories(path_);
}

TempDir::~TempDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

}  // namespace lensrt::golden
