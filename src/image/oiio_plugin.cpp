#include "image/oiio_plugin.h"

#include <dlfcn.h>

#include <cstdlib>
#include <exception>
#include <memory>
#include <optional>
#include <stdexcept>
#include <system_error>

#include "core/error.h"

namespace lensrt {

namespace fs = std::filesystem;

namespace {

constexpr const char* kPluginFile = "lensrt_oiio.so";

// Where lensrt's own code lives: the executable's folder, and the Python
// module's when this code is in it.
std::vector<fs::path> searchFolders() {
  std::vector<fs::path> folders;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    folders.push_back(exe.parent_path());
    folders.push_back((exe.parent_path() / ".." / "lib" / "lensrt").lexically_normal());
  }
  Dl_info info{};
  if (::dladdr(reinterpret_cast<void*>(&searchFolders), &info) && info.dli_fname) {
    const fs::path self = fs::weakly_canonical(info.dli_fname, ec);
    if (!ec && !self.empty() && self != exe) folders.push_back(self.parent_path());
  }
  return folders;
}

std::string listed(const std::vector<fs::path>& folders) {
  std::string text;
  for (std::size_t i = 0; i < folders.size(); ++i) {
    if (i > 0) text += i + 1 == folders.size() ? " or " : ", ";
    text += folders[i].string();
  }
  return text;
}

// dlopen's reason, with where to get OpenImageIO when it is what is missing.
std::string loadProblem(const fs::path& file, const std::string& reason) {
  std::string problem = file.string();
  problem += " cannot be loaded: ";
  problem += reason;
  if (reason.find("libOpenImageIO") != std::string::npos)
    problem += " (OpenImageIO is not installed: on Debian, apt-get install libopenimageio2.4)";
  return problem;
}

}  // namespace

// The process's one plugin, or why there is none.
struct OiioPluginLoader {
  std::optional<OiioPlugin> plugin;
  std::string problem;

  OiioPluginLoader() {
    const char* named = std::getenv("LENSRT_OIIO_PLUGIN");
    std::vector<fs::path> candidates;
    std::vector<fs::path> folders;
    if (named && *named) {
      candidates.emplace_back(named);
    } else {
      folders = searchFolders();
      for (const fs::path& folder : folders) candidates.push_back(folder / kPluginFile);
    }
    for (const fs::path& file : candidates) {
      std::error_code ec;
      if (!fs::exists(file, ec)) continue;
      try {
        plugin.emplace(OiioPlugin(SharedLibrary(file)));
      } catch (const std::exception& e) {
        problem = loadProblem(file, e.what());
      }
      return;
    }
    problem = named && *named ? std::string("LENSRT_OIIO_PLUGIN names ") + named + ", which does not exist"
                              : std::string(kPluginFile) + " is not in " + listed(folders) +
                                    " (LENSRT_OIIO_PLUGIN=FILE names it elsewhere)";
  }
};

namespace {

const OiioPluginLoader& loader() {
  static const OiioPluginLoader loaded;  // thread-safe; loaded once
  return loaded;
}

}  // namespace

const OiioPlugin& OiioPlugin::get(const std::string& file, const std::string& purpose) {
  std::string problem;
  if (const OiioPlugin* plugin = find(problem)) return *plugin;
  throw InputError(file, purpose + " needs lensrt's OpenImageIO plugin: " + problem);
}

const OiioPlugin* OiioPlugin::find(std::string& problem) {
  const OiioPluginLoader& l = loader();
  if (l.plugin) return &*l.plugin;
  problem = l.problem;
  return nullptr;
}

template <class F>
F OiioPlugin::function(const char* name) const {
  void* address = library_.symbol(name);
  if (!address)
    throw std::runtime_error(std::string("it has no ") + name + " (a plugin of another lensrt version)");
  return reinterpret_cast<F>(address);
}

OiioPlugin::OiioPlugin(SharedLibrary library)
    : library_(std::move(library)),
      libraryVersion_(function<decltype(libraryVersion_)>("lensrt_oiio_library_version")),
      readFile_(function<decltype(readFile_)>("lensrt_oiio_read_file")),
      readMemory_(function<decltype(readMemory_)>("lensrt_oiio_read_memory")),
      write_(function<decltype(write_)>("lensrt_oiio_write")),
      displayTransform_(function<decltype(displayTransform_)>("lensrt_oiio_display_transform")),
      displays_(function<decltype(displays_)>("lensrt_oiio_displays")),
      free_(function<decltype(free_)>("lensrt_oiio_free")),
      lastError_(function<decltype(lastError_)>("lensrt_oiio_last_error")) {
  const int abi = function<decltype(&lensrt_oiio_abi_version)>("lensrt_oiio_abi_version")();
  if (abi != LENSRT_OIIO_ABI_VERSION)
    throw std::runtime_error(std::string("it speaks version ") + std::to_string(abi) +
                             " of the plugin interface, lensrt " + std::to_string(LENSRT_OIIO_ABI_VERSION) +
                             " (a plugin of another lensrt version)");
}

std::string OiioPlugin::lastError() const {
  const char* text = lastError_();
  return text && *text ? text : "OpenImageIO gave no reason";
}

std::string OiioPlugin::libraryVersion() const {
  return libraryVersion_();
}

namespace {

// The size check as the C interface calls it: an exception it throws waits
// here and is thrown again once the plugin has returned.
struct SizeCheckCall {
  const OiioPlugin::SizeCheck& check;
  std::exception_ptr refusal;

  static int call(void* context, int width, int height, int channels) {
    auto* self = static_cast<SizeCheckCall*>(context);
    try {
      if (self->check) self->check(width, height, channels);
      return 1;
    } catch (...) {
      self->refusal = std::current_exception();
      return 0;
    }
  }
};

std::vector<std::string> splitNames(const char* names) {
  std::vector<std::string> out;
  std::string current;
  for (const char* c = names ? names : ""; *c; ++c) {
    if (*c == ',') {
      out.push_back(current);
      current.clear();
    } else {
      current += *c;
    }
  }
  if (!current.empty() || !out.empty()) out.push_back(current);
  return out;
}

}  // namespace

PluginImage OiioPlugin::take(lensrt_oiio_image& image) const {
  // The plugin's buffers go back to it whatever happens here.
  const auto release = [this](void* p) { free_(p); };
  const std::unique_ptr<float, decltype(release)> pixels(image.pixels, release);
  const std::unique_ptr<char, decltype(release)> names(image.channel_names, release);
  PluginImage out;
  out.width = image.width;
  out.height = image.height;
  out.channels = splitNames(names.get());
  out.channels.resize(std::size_t(std::max(image.channels, 0)));
  out.pixels.assign(pixels.get(), pixels.get() + std::size_t(image.width) * std::size_t(image.height) *
                                                     std::size_t(image.channels));
  out.encoding = image.encoding == LENSRT_OIIO_SRGB     ? StoredEncoding::Srgb
                 : image.encoding == LENSRT_OIIO_CINEON ? StoredEncoding::Cineon
                                                        : StoredEncoding::Linear;
  return out;
}

PluginImage OiioPlugin::readFile(const fs::path& file, const SizeCheck& check) const {
  SizeCheckCall call{check, nullptr};
  lensrt_oiio_image image{};
  const int status = readFile_(file.c_str(), &SizeCheckCall::call, &call, &image);
  if (call.refusal) std::rethrow_exception(call.refusal);
  if (status != LENSRT_OIIO_OK)
    throw InputError(file.string(), std::string("cannot read image: ") + lastError());
  return take(image);
}

PluginImage OiioPlugin::readMemory(std::string_view bytes, const char* format, const std::string& name,
                                   const SizeCheck& check) const {
  SizeCheckCall call{check, nullptr};
  lensrt_oiio_image image{};
  const int status = readMemory_(bytes.data(), bytes.size(), format, &SizeCheckCall::call, &call, &image);
  if (call.refusal) std::rethrow_exception(call.refusal);
  if (status != LENSRT_OIIO_OK) throw InputError(name, std::string("cannot read image: ") + lastError());
  return take(image);
}

void OiioPlugin::write(const fs::path& file, const std::vector<float>& pixels, int width, int height,
                       int channels, const PluginWriteOptions& options) const {
  std::vector<const char*> metadata;
  for (const auto& [key, value] : options.metadata) {
    metadata.push_back(key.c_str());
    metadata.push_back(value.c_str());
  }
  metadata.push_back(nullptr);
  const lensrt_oiio_write_options c{options.format.c_str(),
                                    options.bits,
                                    options.quality,
                                    options.colorSpace.c_str(),
                                    options.dpxTransfer.empty() ? nullptr : options.dpxTransfer.c_str(),
                                    metadata.data()};
  if (write_(file.c_str(), pixels.data(), width, height, channels, &c) != LENSRT_OIIO_OK)
    throw InputError(file.string(), std::string("cannot write: ") + lastError());
}

void OiioPlugin::displayTransform(const std::string& option, std::vector<float>& rgb,
                                  const std::string& display, const std::string& view) const {
  if (displayTransform_(rgb.data(), rgb.size() / 3, display.c_str(), view.c_str()) == LENSRT_OIIO_OK) return;
  std::string message = lastError();
  char* names = nullptr;
  if (displays_(&names) == LENSRT_OIIO_OK && names) {
    const auto release = [this](void* p) { free_(p); };
    const std::unique_ptr<char, decltype(release)> owned(names, release);
    message += *owned ? std::string(" (displays and their views: ") + owned.get() + ")"
                      : std::string(" ($OCIO names the config file, e.g. an ACES config)");
  }
  throw UsageError(option, message);
}

}  // namespace lensrt
