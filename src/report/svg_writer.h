// A minimal SVG document builder for the lens diagrams and plots: elements
// are appended as text with numbers rounded to 0.01 px, styles come from CSS
// classes declared once in a <style> block.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "core/vec.h"

namespace lensrt {

class Svg {
 public:
  Svg(double width, double height);

  double width() const { return width_; }
  double height() const { return height_; }

  // `attributes` is raw attribute text, e.g. R"(class="ray" stroke="#c00")".
  void style(std::string_view css);
  void line(Vec2d a, Vec2d b, std::string_view attributes);
  void polyline(const std::vector<Vec2d>& points, std::string_view attributes);
  void polygon(const std::vector<Vec2d>& points, std::string_view attributes);
  void path(std::string_view d, std::string_view attributes);
  void circle(Vec2d centre, double radius, std::string_view attributes);
  void rect(Vec2d corner, double w, double h, std::string_view attributes);
  void text(Vec2d at, std::string_view text, std::string_view attributes);
  void beginGroup(std::string_view attributes);
  void endGroup();
  void comment(std::string_view text);

  std::string str() const;
  // Atomic: writes a temporary file beside `file`, then renames it over the
  // target. Throws InputError(file, reason) on failure.
  void write(const std::filesystem::path& file) const;

  // Number and XML text formatting shared by the drawing code.
  static std::string num(double v);
  static std::string escape(std::string_view text);

 private:
  double width_, height_;
  std::string css_;
  std::string body_;
  int openGroups_ = 0;
};

}  // namespace lensrt
