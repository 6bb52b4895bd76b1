// Loading lens files by extension and finding library lenses by name.
#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>

#include "core/error.h"
#include "optics/lens_readers.h"

namespace lensrt {
namespace {

constexpr std::uintmax_t kMaxFileBytes = 4u << 20;  // far beyond any real prescription
const char* const kExtensions[] = {".lens", ".json", ".dat", ".zmx"};

}  // namespace

LensPrescription loadLens(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError(file, "no such lens file");
  if (std::filesystem::file_size(path, ec) > kMaxFileBytes)
    throw InputError(file, "file is larger than 4 MiB: refusing (not a lens?)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(file, "cannot open");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  const std::string ext = path.extension().string();
  LensPrescription lens;
  if (ext == ".dat")
    lens = parsePbrtLens(text, file);
  else if (ext == ".lens")
    lens = parseTableLens(text, file);
  else if (ext == ".json")
    lens = parseJsonLens(text, file);
  else if (ext == ".zmx" || ext == ".ZMX")
    lens = parseZemaxLens(text, file);
  else
    throw InputError(file, "unknown lens file extension '" + ext + "' (expected .lens, .json, .dat or .zmx)");
  validatePrescription(lens);
  return lens;
}

std::vector<std::filesystem::path> listLenses(const std::filesystem::path& lensDir) {
  std::vector<std::filesystem::path> out;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(lensDir, ec)) {
    const std::string ext = entry.path().extension().string();
    if (entry.is_regular_file() &&
        std::find(std::begin(kExtensions), std::end(kExtensions), ext) != std::end(kExtensions))
      out.push_back(entry.path());
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.stem() < b.stem(); });
  return out;
}

std::filesystem::path findLens(const std::string& nameOrPath, const std::filesystem::path& lensDir) {
  std::error_code ec;
  if (std::filesystem::is_regular_file(nameOrPath, ec)) return nameOrPath;
  // A bare name (no directory part) is looked up in the library.
  if (std::filesystem::path(nameOrPath).parent_path().empty()) {
    if (std::filesystem::is_regular_file(lensDir / nameOrPath, ec)) return lensDir / nameOrPath;
    for (const char* ext : kExtensions) {
      const std::filesystem::path candidate = lensDir / (nameOrPath + ext);
      if (std::filesystem::is_regular_file(candidate, ec)) return candidate;
    }
  }
  // Appended piece by piece: GCC 12 warns falsely about "..." + std::string (bug 105329).
  std::string names;
  for (const auto& p : listLenses(lensDir)) names.append(names.empty() ? "" : ", ").append(p.stem().string());
  std::string message = "no such lens file or library lens";
  if (!names.empty()) message.append(" (library: ").append(names).append(")");
  throw InputError(nameOrPath, message);
}

}  // namespace lensrt
