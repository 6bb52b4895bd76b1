#include "image/oiio_module.h"

#include <dlfcn.h>

#include <array>
#include <filesystem>
#include <system_error>

namespace lensrt {
namespace {

namespace fs = std::filesystem;

constexpr const char* kModuleName = "liblensrt_oiio.so";

struct Loaded {
  const oiio::Api* api = nullptr;
  std::string error;
};

// Beside the executable first (an installed or relocated tree), then where
// the build put it (tests run from their own directories).
Loaded load() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  const std::array<fs::path, 3> candidates{
      ec ? fs::path() : exe.parent_path() / kModuleName,
      ec ? fs::path() : exe.parent_path() / "../lib/lensrt" / kModuleName, fs::path(LENSRT_OIIO_MODULE_PATH)};
  std::string firstError;
  for (const fs::path& candidate : candidates) {
    if (candidate.empty() || !fs::exists(candidate, ec)) continue;
    // Never closed: OpenImageIO keeps threads and caches until exit.
    void* handle = ::dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      if (firstError.empty()) firstError = ::dlerror();
      continue;
    }
    using Entry = const oiio::Api* (*)();
    const auto entry = reinterpret_cast<Entry>(::dlsym(handle, oiio::kEntryPoint));
    const oiio::Api* api = entry ? entry() : nullptr;
    if (api && api->version == oiio::kApiVersion) return {api, ""};
    if (firstError.empty()) firstError = candidate.string() + " is not a matching lensrt OpenImageIO module";
  }
  return {nullptr, "cannot load OpenImageIO support (" + std::string(kModuleName) + ")" +
                       (firstError.empty() ? std::string(": not found") : ": " + firstError)};
}

const Loaded& loaded() {
  static const Loaded module = load();
  return module;
}

}  // namespace

const oiio::Api* oiioModule() {
  return loaded().api;
}

const std::string& oiioModuleError() {
  return loaded().error;
}

}  // namespace lensrt
