// A shared library opened with dlopen and closed with it (RAII): lensrt's
// optional plugins, loaded only when a feature needs them.
#pragma once

#include <filesystem>
#include <string>

namespace lensrt {

class SharedLibrary {
 public:
  // Opens `file`, every symbol resolved now and none shared with libraries
  // loaded later. Throws std::runtime_error with dlerror()'s text when it
  // cannot be loaded.
  explicit SharedLibrary(const std::filesystem::path& file);
  ~SharedLibrary();
  SharedLibrary(SharedLibrary&& other) noexcept;
  SharedLibrary& operator=(SharedLibrary&& other) noexcept;
  SharedLibrary(const SharedLibrary&) = delete;
  SharedLibrary& operator=(const SharedLibrary&) = delete;

  // The address of `name`, or nullptr when the library has no such symbol.
  void* symbol(const char* name) const;
  const std::filesystem::path& file() const { return file_; }

 private:
  std::filesystem::path file_;
  void* handle_ = nullptr;
};

}  // namespace lensrt
