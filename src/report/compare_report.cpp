#include "report/compare_report.h"

#include <fmt/core.h>

#include <cmath>
#include <limits>
#include <system_error>

#include "core/error.h"

namespace lensrt {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double pixelLuminance(const Image& image, int x, int y, int r, int g, int b) {
  return 0.2126 * image.at(x, y, r) + 0.7152 * image.at(x, y, g) + 0.0722 * image.at(x, y, b);
}

std::string escapeHtml(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string cell(const nlohmann::json& value) {
  if (value.is_null()) return "&ndash;";
  if (value.is_number_float()) return fmt::format("{:.4g}", value.get<double>());
  if (value.is_string()) return escapeHtml(value.get<std::string>());
  return escapeHtml(value.dump());
}

// Distinct, colour-blind-safe line colours (Okabe-Ito).
constexpr const char* kLineColours[] = {"#0072B2", "#E69F00", "#009E73", "#D55E00", "#CC79A7", "#56B4E9"};

}  // namespace

std::vector<double> vignettingProfile(const Image& image) {
  const int r = image.channelIndex("R"), g = image.channelIndex("G"), b = image.channelIndex("B");
  std::vector<double> profile(kVignettingBins, kNaN);
  if (r < 0 || g < 0 || b < 0 || image.width < 1 || image.height < 1) return profile;
  // Pixel centres: the farthest corner pixel lands in the last bin.
  const double cx = 0.5 * image.width, cy = 0.5 * image.height;
  const double maxRadius = std::hypot(cx - 0.5, cy - 0.5);
  std::vector<double> sum(kVignettingBins, 0.0);
  std::vector<long long> count(kVignettingBins, 0);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const double radius = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
      const int bin =
          maxRadius > 0 ? std::min(kVignettingBins - 1, int(radius / maxRadius * kVignettingBins)) : 0;
      const double v = pixelLuminance(image, x, y, r, g, b);
      if (!std::isfinite(v)) continue;
      sum[bin] += v;
      ++count[bin];
    }
  const double centre = count[0] ? sum[0] / double(count[0]) : 0.0;
  if (!(centre > 0)) return profile;
  for (int i = 0; i < kVignettingBins; ++i)
    if (count[i]) profile[i] = sum[i] / double(count[i]) / centre;
  return profile;
}

double channelMean(const Image& image, const std::string& channel) {
  const int c = image.channelIndex(channel);
  if (c < 0 || image.width < 1 || image.height < 1) return kNaN;
  double sum = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) sum += image.at(x, y, c);
  return sum / (double(image.width) * image.height);
}

double meanLuminance(const Image& image) {
  return 0.2126 * channelMean(image, "R") + 0.7152 * channelMean(image, "G") +
         0.0722 * channelMean(image, "B");
}

std::string vignettingChartSvg(const std::vector<std::string>& models,
                               const std::vector<std::vector<double>>& profiles) {
  // Plot area in SVG units; y from 0 to the largest value (at least 1).
  constexpr double left = 50, top = 15, width = 420, height = 220;
  double yMax = 1.0;
  for (const auto& p : profiles)
    for (const double v : p)
      if (std::isfinite(v)) yMax = std::max(yMax, v);
  yMax = std::ceil(yMax * 10.0) / 10.0;
  const auto px = [&](double binCentre) { return left + binCentre / kVignettingBins * width; };
  const auto py = [&](double v) { return top + height * (1.0 - v / yMax); };
  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" "
      "font-family=\"sans-serif\" font-size=\"12\">\n",
      left + width + 130, top + height + 45);
  svg += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#888\"/>\n",
                     left, top, width, height);
  for (int i = 0; i <= 4; ++i) {
    const double v = yMax * i / 4.0;
    svg += fmt::format(
        "<line x1=\"{0}\" x2=\"{1}\" y1=\"{2:.1f}\" y2=\"{2:.1f}\" stroke=\"#ddd\"/>"
        "<text x=\"{3}\" y=\"{4:.1f}\" text-anchor=\"end\">{5:.2f}</text>\n",
        left, left + width, py(v), left - 6, py(v) + 4, v);
  }
  for (int i = 0; i <= kVignettingBins; i += 2)
    svg += fmt::format("<text x=\"{:.1f}\" y=\"{}\" text-anchor=\"middle\">{:.1f}</text>\n", px(i),
                       top + height + 16, double(i) / kVignettingBins);
  svg += fmt::format("<text x=\"{:.1f}\" y=\"{}\" text-anchor=\"middle\">radius / half diagonal</text>\n",
                     left + width / 2, top + height + 36);
  for (std::size_t m = 0; m < profiles.size(); ++m) {
    const char* colour = kLineColours[m % std::size(kLineColours)];
    std::string points;
    for (int i = 0; i < kVignettingBins && i < int(profiles[m].size()); ++i)
      if (std::isfinite(profiles[m][i]))
        points += fmt::format("{:.1f},{:.1f} ", px(i + 0.5), py(profiles[m][i]));
    svg += fmt::format("<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"2\" points=\"{}\"/>\n", colour,
                       points);
    const double ly = top + 10 + 18 * double(m);
    svg += fmt::format(
        "<line x1=\"{0}\" x2=\"{1}\" y1=\"{2}\" y2=\"{2}\" stroke=\"{3}\" stroke-width=\"2\"/>"
        "<text x=\"{4}\" y=\"{5}\">{6}</text>\n",
        left + width + 10, left + width + 34, ly, colour, left + width + 40, ly + 4,
        escapeHtml(m < models.size() ? models[m] : ""));
  }
  svg += "</svg>\n";
  return svg;
}

std::string compareReportHtml(const nlohmann::json& report) {
  const nlohmann::json& models = report.at("models");
  std::vector<std::string> names;
  std::vector<std::vector<double>> profiles;
  for (const auto& [name, model] : models.items()) {
    names.push_back(name);
    std::vector<double> p;
    for (const auto& v : model.at("vignetting_profile")) p.push_back(v.is_number() ? v.get<double>() : kNaN);
    profiles.push_back(p);
  }
  // Keep the models in report order (pinhole, thin, thick, lens).
  if (report.contains("model_order")) {
    std::vector<std::string> ordered;
    std::vector<std::vector<double>> orderedProfiles;
    for (const auto& n : report.at("model_order")) {
      const auto it = std::find(names.begin(), names.end(), n.get<std::string>());
      if (it == names.end()) continue;
      ordered.push_back(*it);
      orderedProfiles.push_back(profiles[std::size_t(it - names.begin())]);
    }
    names = ordered;
    profiles = orderedProfiles;
  }

  std::string html =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<title>lensrt compare</title>\n<style>\n"
      "body{font-family:sans-serif;margin:2em;max-width:1400px;color:#222}\n"
      "table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #bbb;padding:3px 8px;"
      "text-align:right}th{background:#eee}td:first-child,th:first-child{text-align:left}\n"
      "img{max-width:100%;image-rendering:pixelated}figure{display:inline-block;margin:0 1em 1em 0}\n"
      "</style>\n</head>\n<body>\n";
  const nlohmann::json& settings = report.at("settings");
  html += fmt::format("<h1>Camera models compared: {}</h1>\n",
                      escapeHtml(settings.value("scene", std::string())));
  html += "<h2>Settings</h2>\n<table>\n";
  for (const auto& [key, value] : settings.items())
    html += fmt::format("<tr><th>{}</th><td>{}</td></tr>\n", escapeHtml(key), cell(value));
  html += "</table>\n";

  html += "<h2>Renders</h2>\n<p>sRGB previews of the linear EXRs (";
  for (std::size_t i = 0; i < names.size(); ++i)
    html += fmt::format("{}<a href=\"{}.exr\">{}.exr</a>", i ? ", " : "", escapeHtml(names[i]),
                        escapeHtml(names[i]));
  html +=
      "), no tone mapping.</p>\n<img src=\"contact-sheet.png\" alt=\"contact sheet of the four models\">\n";
  html +=
      settings.value("pinhole_film", std::string()) == "radiance"
          ? "<p>Film: the pinhole records radiance (the ideal reference: the mean radiance along its rays, "
            "no cos<sup>4</sup> fall-off, no bellows factor); thin, thick and lens record film irradiance "
            "scaled by the exposure.</p>\n"
          : "<p>Film: all four models record film irradiance scaled by the exposure (the pinhole as an "
            "ideal lens shrunk to a point: cos<sup>4</sup> fall-off included).</p>\n";

  html +=
      "<h2>Figures</h2>\n<table>\n<tr><th>model</th><th>camera</th><th>render s</th><th>camera-ray "
      "efficiency</th><th>mean luminance</th><th>mean R</th><th>mean G</th><th>mean B</th><th>mean "
      "|model &minus; lens|</th><th>RMSE vs lens</th></tr>\n";
  for (const std::string& name : names) {
    const nlohmann::json& m = models.at(name);
    const nlohmann::json& mean = m.at("mean");
    html += fmt::format(
        "<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</"
        "td>"
        "<td>{}</td></tr>\n",
        escapeHtml(name), cell(m.at("camera")), cell(m.at("render_seconds")),
        cell(m.at("camera_ray_efficiency")), cell(mean.at("luminance")), cell(mean.at("R")),
        cell(mean.at("G")), cell(mean.at("B")), cell(m.at("mean_abs_diff_vs_lens")),
        cell(m.at("rmse_vs_lens")));
  }
  html += "</table>\n";

  html +=
      "<h2>Vignetting</h2>\n<p>Mean luminance in " + std::to_string(kVignettingBins) +
      " rings of equal width from the centre to the corner, relative to the centre ring. It mixes the "
      "optics' fall-off with what the scene shows in each ring; compare the models with each other.</p>\n";
  html += vignettingChartSvg(names, profiles);
  html += "<table>\n<tr><th>model</th>";
  for (int i = 0; i < kVignettingBins; ++i)
    html += fmt::format("<th>{:.2f}</th>", (i + 0.5) / kVignettingBins);
  html += "</tr>\n";
  for (std::size_t m = 0; m < names.size(); ++m) {
    html += "<tr><td>" + escapeHtml(names[m]) + "</td>";
    for (const double v : profiles[m])
      html += "<td>" + (std::isfinite(v) ? fmt::format("{:.3f}", v) : "&ndash;") + "</td>";
    html += "</tr>\n";
  }
  html += "</table>\n";

  html +=
      "<h2>Differences from the full lens</h2>\n<p>Per pixel, the largest |model &minus; lens| over R,G,B, "
      "on one colour scale for all three maps.</p>\n";
  for (const std::string& name : names)
    if (models.at(name).contains("heatmap"))
      html += fmt::format(
          "<figure><img src=\"{0}\" alt=\"{1} vs lens\"><figcaption>{1} vs lens</figcaption></figure>\n",
          escapeHtml(models.at(name).at("heatmap").get<std::string>()), escapeHtml(name));

  if (report.contains("lens")) {
    html += "<h2>Lens (paraxial, mm)</h2>\n<table>\n";
    for (const auto& [key, value] : report.at("lens").items())
      html += fmt::format("<tr><th>{}</th><td>{}</td></tr>\n", escapeHtml(key), cell(value));
    html += "</table>\n";
  }
  html += "</body>\n</html>\n";
  return html;
}

}  // namespace lensrt
