#include "core/shared_library.h"

#include <dlfcn.h>

#include <stdexcept>
#include <utility>

namespace lensrt {

SharedLibrary::SharedLibrary(const std::filesystem::path& file)
    // RTLD_NODELETE: the code stays mapped after dlclose, as libraries such
    // as OpenImageIO keep worker threads and static objects until exit.
    : file_(file), handle_(::dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE)) {
  if (!handle_) {
    const char* reason = ::dlerror();
    throw std::runtime_error(reason ? reason : "cannot be loaded");
  }
}

SharedLibrary::~SharedLibrary() {
  if (handle_) ::dlclose(handle_);
}

SharedLibrary::SharedLibrary(SharedLibrary&& other) noexcept
    : file_(std::move(other.file_)), handle_(std::exchange(other.handle_, nullptr)) {}

SharedLibrary& SharedLibrary::operator=(SharedLibrary&& other) noexcept {
  if (this != &other) {
    if (handle_) ::dlclose(handle_);
    file_ = std::move(other.file_);
    handle_ = std::exchange(other.handle_, nullptr);
  }
  return *this;
}

void* SharedLibrary::symbol(const char* name) const {
  return ::dlsym(handle_, name);
}

}  // namespace lensrt
