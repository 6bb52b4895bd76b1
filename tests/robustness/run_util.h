// Runs a program as a child process with a time limit and captures its output.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace lensrt::robustness {

struct RunResult {
  int status = -1;        // exit status, or 128 + signal number
  bool timedOut = false;  // killed after the time limit
  std::string out;
  std::string err;
};

// argv[0] is the program path. The child is killed (SIGKILL) after
// `timeoutSeconds`, so a hang fails the test instead of stalling CI.
RunResult runWithTimeout(const std::vector<std::string>& argv, double timeoutSeconds);

// A fresh empty directory, removed (made writable first) by the destructor.
class TempDir {
 public:
  explicit TempDir(const std::string& tag);
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

std::string readFile(const std::filesystem::path& file);
void writeFile(const std::filesystem::path& file, const std::string& contents);
std::vector<std::string> lines(const std::string& text);

}  // namespace lensrt::robustness
