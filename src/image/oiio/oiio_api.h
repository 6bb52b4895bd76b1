// The interface between lensrt_image and liblensrt_oiio.so, the one module
// that links OpenImageIO. Debian's OpenImageIO pulls in ~260 shared libraries
// (0.3-1 s and ~130 MB per process start), so lensrt loads it with dlopen
// only when a command reads or writes an image, draws text or maps colours.
// Both sides are built by the same compiler from the same tree, so the table
// may use standard C++ types; the one exported symbol is extern "C".
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace lensrt::oiio {

using Attributes = std::vector<std::pair<std::string, std::string>>;

enum class Format { Exr, Png, Jpeg };

// A file's layout: the data window (x, y, width, height) inside the display
// window (fullX, fullY, fullWidth, fullHeight).
struct Layout {
  int width = 0, height = 0, depth = 1;
  std::vector<std::string> channels;
  int x = 0, y = 0, fullX = 0, fullY = 0, fullWidth = 0, fullHeight = 0;
};

// Errors are returned as one-line reasons ("" on success), never thrown:
// exceptions stay on their side of the module boundary.
struct Api {
  int version;
  // Writes `data` (float, interleaved, layout.channels.size() values per
  // pixel). EXR: float or half, ZIP, alpha channel index (-1: none).
  std::string (*write)(const std::string& path, Format format, const Layout& layout, bool halfFloat,
                       int alphaChannel, const Attributes& attributes, const float* data);
  // Reads the first subimage as float; attributes as strings when non-null.
  std::string (*read)(const std::string& path, Layout& layout, std::vector<float>& pixels,
                      Attributes* attributes);
  // The bounding box (xbegin, xend, ybegin, yend) of `text` at pixel height
  // `size` in `font`; false when the font is missing.
  bool (*textSize)(const std::string& text, int size, const char* font, int box[4]);
  // Renders coverage of `text` into a zeroed width x height float mask with
  // its origin at (x, y); false on failure.
  bool (*renderText)(std::vector<float>& mask, int width, int height, int x, int y, const std::string& text,
                     int size, const char* font);
  // Maps width x height values in [0,1] through the named map to linear RGB.
  std::string (*colorMap)(const std::vector<float>& values, int width, int height, const char* map,
                          std::vector<float>& rgb);
};

inline constexpr int kApiVersion = 1;
inline constexpr const char* kEntryPoint = "lensrt_oiio_api";

}  // namespace lensrt::oiio
