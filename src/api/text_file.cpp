#include "api/text_file.h"

#include <fmt/core.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>

#include "core/error.h"

namespace lensrt {

namespace {

std::string reason(int err) {
  if (err == ENOSPC) return "disk full";
  return err ? std::strerror(err) : "I/O error";
}

}  // namespace

void writeTextFileAtomically(const std::filesystem::path& file, const std::string& contents) {
  const std::filesystem::path dir = file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
  const std::filesystem::path temp = dir / fmt::format(".{}.tmp{}-{}", file.filename().string(),
                                                       static_cast<long>(::getpid()), std::random_device{}());
  {
    errno = 0;
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError(file.string(), "cannot write: " + reason(errno));
    out << contents;
    out.close();
    if (!out) {
      const int err = errno;
      std::error_code ignored;
      std::filesystem::remove(temp, ignored);
      throw InputError(file.string(), "cannot write: " + reason(err));
    }
  }
  std::error_code ec;
  std::filesystem::rename(temp, file, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(temp, ignored);
    throw InputError(file.string(), "cannot write: " + ec.message());
  }
}

void writeTextOutput(const std::string& output, const std::string& contents) {
  if (output != "-") return writeTextFileAtomically(output, contents);
  if (std::fwrite(contents.data(), 1, contents.size(), stdout) != contents.size() || std::fflush(stdout) != 0)
    throw InputError("<stdout>", "cannot write: " + reason(errno));
}

}  // namespace lensrt
