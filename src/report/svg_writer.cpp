#include "report/svg_writer.h"

#include <fmt/core.h>

#include <cmath>

#include "api/text_file.h"
#include "core/error.h"

namespace lensrt {

Svg::Svg(double width, double height) : width_(width), height_(height) {}

std::string Svg::num(double v) {
  if (!std::isfinite(v)) v = 0.0;  // never emit "nan" into a document
  std::string s = fmt::format("{:.2f}", v);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

std::string Svg::escape(std::string_view text) {
  std::string s;
  for (const char c : text) switch (c) {
      case '&':
        s += "&amp;";
        break;
      case '<':
        s += "&lt;";
        break;
      case '>':
        s += "&gt;";
        break;
      case '"':
        s += "&quot;";
        break;
      default:
        s += c;
    }
  return s;
}

void Svg::style(std::string_view css) {
  css_ += css;
}

void Svg::line(Vec2d a, Vec2d b, std::string_view attributes) {
  body_ += fmt::format("<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" {}/>\n", num(a.x), num(a.y), num(b.x),
                       num(b.y), attributes);
}

namespace {
std::string pointList(const std::vector<Vec2d>& points) {
  std::string s;
  for (const Vec2d& p : points) {
    if (!s.empty()) s += ' ';
    s += Svg::num(p.x);
    s += ',';
    s += Svg::num(p.y);
  }
  return s;
}
}  // namespace

void Svg::polyline(const std::vector<Vec2d>& points, std::string_view attributes) {
  body_ += fmt::format("<polyline points=\"{}\" fill=\"none\" {}/>\n", pointList(points), attributes);
}

void Svg::polygon(const std::vector<Vec2d>& points, std::string_view attributes) {
  body_ += fmt::format("<polygon points=\"{}\" {}/>\n", pointList(points), attributes);
}

void Svg::path(std::string_view d, std::string_view attributes) {
  body_ += fmt::format("<path d=\"{}\" {}/>\n", d, attributes);
}

void Svg::circle(Vec2d centre, double radius, std::string_view attributes) {
  body_ += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"{}\" {}/>\n", num(centre.x), num(centre.y),
                       num(radius), attributes);
}

void Svg::rect(Vec2d corner, double w, double h, std::string_view attributes) {
  body_ += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" {}/>\n", num(corner.x),
                       num(corner.y), num(w), num(h), attributes);
}

void Svg::text(Vec2d at, std::string_view text, std::string_view attributes) {
  body_ +=
      fmt::format("<text x=\"{}\" y=\"{}\" {}>{}</text>\n", num(at.x), num(at.y), attributes, escape(text));
}

void Svg::beginGroup(std::string_view attributes) {
  body_ += fmt::format("<g {}>\n", attributes);
  ++openGroups_;
}

void Svg::endGroup() {
  if (openGroups_ == 0) return;
  body_ += "</g>\n";
  --openGroups_;
}

void Svg::comment(std::string_view text) {
  // "--" may not appear inside an XML comment.
  std::string t(text);
  for (std::size_t i = t.find("--"); i != std::string::npos; i = t.find("--", i)) t.replace(i, 2, "- ");
  body_ += "<!-- " + t + " -->\n";
}

std::string Svg::str() const {
  std::string s = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  s += fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" "
      "font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n",
      num(width_), num(height_));
  if (!css_.empty()) s += "<style>\n" + css_ + "</style>\n";
  s += fmt::format("<rect x=\"0\" y=\"0\" width=\"{}\" height=\"{}\" fill=\"white\"/>\n", num(width_),
                   num(height_));
  s += body_;
  for (int i = 0; i < openGroups_; ++i) s += "</g>\n";
  s += "</svg>\n";
  return s;
}

void Svg::write(const std::filesystem::path& file) const {
  writeTextFileAtomically(file, str());
}

}  // namespace lensrt
