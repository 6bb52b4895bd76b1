// `lensrt lens diagram` and `lensrt lens plot` end to end: well-formed SVG
// with the expected elements, rays that end on the film, and one-line
// errors with the right exit status that leave an existing output untouched.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "cli/cli_util.h"

namespace lensrt {
namespace {

using cli::readFile;
using cli::runLensrt;
using cli::RunResult;
using cli::TempDir;

struct Element {
  std::string name;
  std::map<std::string, std::string> attributes;
};

// A minimal XML check: every tag closes in order, attributes are quoted,
// text holds no raw '<' and only known entities. Returns every element, or
// fails the test.
std::vector<Element> parseXml(const std::string& text) {
  std::vector<Element> elements;
  std::vector<std::string> open;
  std::size_t i = 0;
  while (i < text.size()) {
    if (text[i] != '<') {
      if (text[i] == '&') {
        const std::size_t semi = text.find(';', i);
        const std::string entity = text.substr(i, semi == std::string::npos ? 1 : semi - i + 1);
        EXPECT_TRUE(entity == "&amp;" || entity == "&lt;" || entity == "&gt;" || entity == "&quot;")
            << "bad entity at " << i;
      }
      ++i;
      continue;
    }
    if (text.compare(i, 4, "<!--") == 0) {
      const std::size_t end = text.find("-->", i);
      if (end == std::string::npos) ADD_FAILURE() << "unterminated comment";
      i = end == std::string::npos ? text.size() : end + 3;
      continue;
    }
    if (text.compare(i, 2, "<?") == 0) {
      i = text.find("?>", i) + 2;
      continue;
    }
    std::size_t j = i + 1;
    bool quoted = false;
    while (j < text.size() && (quoted || text[j] != '>')) {
      if (text[j] == '"') quoted = !quoted;
      ++j;
    }
    if (j >= text.size()) {
      ADD_FAILURE() << "unterminated tag at " << i;
      break;
    }
    const std::string tag = text.substr(i + 1, j - i - 1);
    i = j + 1;
    if (tag[0] == '/') {
      if (open.empty() || open.back() != tag.substr(1)) {
        ADD_FAILURE() << "unbalanced </" << tag.substr(1) << ">";
        return elements;
      }
      open.pop_back();
      continue;
    }
    const bool selfClosing = tag.back() == '/';
    std::istringstream in(selfClosing ? tag.substr(0, tag.size() - 1) : tag);
    Element e;
    in >> e.name;
    std::string rest((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (std::size_t k = 0; k < rest.size();) {
      const std::size_t eq = rest.find("=\"", k);
      if (eq == std::string::npos) break;
      const std::size_t close = rest.find('"', eq + 2);
      if (close == std::string::npos) {
        ADD_FAILURE() << "unquoted attribute in <" << e.name << ">";
        break;
      }
      std::string key = rest.substr(k, eq - k);
      key.erase(0, key.find_first_not_of(" \n\t"));
      e.attributes[key] = rest.substr(eq + 2, close - eq - 2);
      k = close + 1;
    }
    elements.push_back(e);
    if (!selfClosing) open.push_back(e.name);
  }
  EXPECT_TRUE(open.empty()) << "unclosed <" << (open.empty() ? "" : open.back()) << ">";
  return elements;
}

std::vector<Element> withClass(const std::vector<Element>& all, const std::string& name,
                               const std::string& cls) {
  std::vector<Element> out;
  for (const Element& e : all) {
    const auto c = e.attributes.find("class");
    if (e.name == name && c != e.attributes.end() &&
        (" " + c->second + " ").find(" " + cls + " ") != std::string::npos)
      out.push_back(e);
  }
  return out;
}

std::vector<double> numbers(const std::string& points) {
  std::vector<double> v;
  std::string s = points;
  for (char& c : s)
    if (c == ',') c = ' ';
  std::istringstream in(s);
  for (double x; in >> x;) v.push_back(x);
  return v;
}

// Glass gaps in a pbrt .dat: rows whose third column (index after) exceeds 1.
int glassGaps(const std::string& datFile) {
  std::istringstream in(readFile(datFile));
  int n = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream row(line);
    double r, t, nd, a;
    if (row >> r >> t >> nd >> a && nd > 1.0) ++n;
  }
  return n;
}

const std::string kLensDir = std::string(LENSRT_SOURCE_DIR) + "/lenses/";

TEST(LensDiagramCli, DrawsEveryElementStopFilmMarksAndRaysEndingOnTheFilm) {
  const TempDir dir;
  const std::string out = (dir / "dgauss.svg").string();
  const RunResult r = runLensrt({"lens", "diagram", "dgauss-50mm", "-o", out});
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string svg = readFile(out);
  const auto all = parseXml(svg);
  ASSERT_FALSE(all.empty());
  EXPECT_EQ(all.front().name, "svg");
  EXPECT_EQ(static_cast<int>(withClass(all, "polygon", "element").size()),
            glassGaps(kLensDir + "dgauss-50mm.dat"));
  EXPECT_EQ(withClass(all, "line", "stop").size(), 4u);  // two blades, each with its edge
  const auto film = withClass(all, "line", "film");
  ASSERT_EQ(film.size(), 1u);
  const double filmX = std::stod(film[0].attributes.at("x1"));
  const auto rays = withClass(all, "polyline", "ray");
  EXPECT_EQ(rays.size(), 27u);  // three fans of nine passing rays
  for (const Element& ray : rays) {
    const auto v = numbers(ray.attributes.at("points"));
    ASSERT_GE(v.size(), 4u);
    EXPECT_NEAR(v[v.size() - 2], filmX, 0.01) << "a passing ray ends on the film";
    EXPECT_LT(v[0], v[v.size() - 2]) << "rays travel from the scene (left) to the film";
  }
  EXPECT_EQ(withClass(all, "polyline", "chief").size(), 3u);
  for (const char* text : {">H<", ">H\u2032<", ">F\u2032<", ">EP<", ">XP<", ">film<", " mm</text>",
                           "dgauss-50mm \u2014 EFL 50.", "id=\"scalebar\""})
    EXPECT_NE(svg.find(text), std::string::npos) << text;
}

TEST(LensPlotCli, EachPlotIsWellFormedWithItsCurveAxesAndLabels) {
  const TempDir dir;
  const std::map<std::string, std::vector<std::string>> expected = {
      {"relative-illumination",
       {"id=\"relative-illumination\"", "image height on the film (mm)", "cos\u2074"}},
      {"distortion", {"id=\"distortion\"", "distortion (%)", "real image height on the film (mm)"}},
      {"spot", {"id=\"spot-0\"", "id=\"spot-1\"", "id=\"spot-2\"", "RMS radius", "(\u00b5m)"}},
      {"chromatic", {"id=\"focal-shift\"", "id=\"lateral-color\"", "wavelength (nm)", "No dispersion data"}}};
  for (const auto& [what, texts] : expected) {
    const std::string out = (dir / (what + ".svg")).string();
    const RunResult r = runLensrt(
        {"lens", "plot", kLensDir + "telephoto-250mm.dat", "--what", what, "-o", out, "--fstop", "8"});
    ASSERT_EQ(r.status, 0) << what << ": " << r.err;
    const std::string svg = readFile(out);
    const auto all = parseXml(svg);
    EXPECT_GE(withClass(all, "text", "ticklabel").size(), 8u) << what;
    EXPECT_GE(withClass(all, "text", "axistitle").size(), 2u) << what;
    EXPECT_NE(svg.find("f/8"), std::string::npos) << what << ": the title gives the f-number";
    for (const std::string& t : texts) EXPECT_NE(svg.find(t), std::string::npos) << what << ": " << t;
  }
}

// Parses `lens plot --csv` output: the header's names, then rows of numbers
// (every row as wide as the header, or the test fails).
struct Csv {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  std::size_t column(const std::string& name) const {
    const auto it = std::find(columns.begin(), columns.end(), name);
    EXPECT_NE(it, columns.end()) << "no column " << name;
    return static_cast<std::size_t>(it - columns.begin());
  }
};

Csv parseCsv(const std::string& text) {
  Csv csv;
  const auto all = cli::lines(text);
  if (all.empty()) {
    ADD_FAILURE() << "empty CSV";
    return csv;
  }
  std::istringstream header(all[0]);
  for (std::string name; std::getline(header, name, ',');) csv.columns.push_back(name);
  for (std::size_t i = 1; i < all.size(); ++i) {
    std::vector<double> row;
    std::istringstream in(all[i]);
    for (std::string cell; std::getline(in, cell, ',');) {
      std::size_t used = 0;
      row.push_back(std::stod(cell, &used));
      EXPECT_EQ(used, cell.size()) << "not a number: " << cell;
      EXPECT_TRUE(std::isfinite(row.back())) << "line " << i + 1;
    }
    EXPECT_EQ(row.size(), csv.columns.size()) << "line " << i + 1;
    csv.rows.push_back(row);
  }
  return csv;
}

// --csv writes the plotted series with the documented columns, with or
// without the SVG, to a file or to standard output. The numbers obey closed
// forms: relative illumination is 1 on the axis and the radii reach the
// sensor's half diagonal; the paraxial height is EFL tan(theta) (focused at
// infinity) with the EFL of the lens (50 mm nominal); each spot's offsets
// from its centroid average to zero.
TEST(LensPlotCli, CsvHoldsThePlottedSeriesWithNamedColumns) {
  const TempDir dir;
  const std::string lens = kLensDir + "dgauss-50mm.dat";
  {
    const std::string csvFile = (dir / "ri.csv").string(), svgFile = (dir / "ri.svg").string();
    const RunResult r = runLensrt({"lens", "plot", lens, "--what", "relative-illumination", "--fstop", "4",
                                   "--sensor", "36x24", "-o", svgFile, "--csv", csvFile});
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(std::filesystem::exists(svgFile));
    const std::string text = readFile(csvFile);
    const Csv csv = parseCsv(text);
    EXPECT_EQ(csv.columns,
              (std::vector<std::string>{"film_radius_mm", "relative_illumination", "vignetting", "cos4"}));
    ASSERT_GE(csv.rows.size(), 20u);
    EXPECT_EQ(csv.rows.front()[0], 0.0);
    EXPECT_EQ(csv.rows.front()[1], 1.0);
    EXPECT_NEAR(csv.rows.back()[0], std::hypot(36.0, 24.0) / 2, 1e-6);
    for (std::size_t i = 1; i < csv.rows.size(); ++i) {
      EXPECT_GT(csv.rows[i][0], csv.rows[i - 1][0]) << "radii ascend";
      EXPECT_LT(csv.rows[i][3], csv.rows[i - 1][3]) << "cos^4 falls off axis";
    }
    EXPECT_LT(csv.rows.back()[1], csv.rows.back()[3]) << "vignetting takes more than cos^4 at the corner";
    // The same data on standard output, and no SVG without -o.
    const RunResult out = runLensrt({"lens", "plot", lens, "--what", "relative-illumination", "--fstop", "4",
                                     "--sensor", "36x24", "--csv", "-"});
    ASSERT_EQ(out.status, 0) << out.err;
    EXPECT_EQ(out.out, text);
  }
  {
    const RunResult r = runLensrt({"lens", "plot", lens, "--what", "distortion", "--csv", "-"});
    ASSERT_EQ(r.status, 0) << r.err;
    const Csv csv = parseCsv(r.out);
    EXPECT_EQ(csv.columns, (std::vector<std::string>{"field_angle_deg", "real_height_mm",
                                                     "paraxial_height_mm", "distortion_percent"}));
    ASSERT_GE(csv.rows.size(), 20u);
    for (const auto& row : csv.rows) {
      if (row[0] == 0.0) continue;
      const double efl = row[2] / std::tan(row[0] * M_PI / 180);
      EXPECT_NEAR(efl, 50.0, 1.0) << "paraxial height / tan(angle) at " << row[0] << " deg";
      EXPECT_NEAR(row[3], 100 * (row[1] - row[2]) / row[2], 1e-6);
    }
  }
  {
    const RunResult r = runLensrt({"lens", "plot", lens, "--what", "spot", "--fstop", "8", "--csv", "-"});
    ASSERT_EQ(r.status, 0) << r.err;
    const Csv csv = parseCsv(r.out);
    EXPECT_EQ(csv.columns,
              (std::vector<std::string>{"field_angle_deg", "image_height_mm", "dx_um", "dy_um"}));
    std::map<double, std::vector<double>> fields;  // angle -> sum dx, sum dy, count
    for (const auto& row : csv.rows) {
      auto& f = fields[row[0]];
      f.resize(3);
      f[0] += row[2];
      f[1] += row[3];
      f[2] += 1;
    }
    ASSERT_EQ(fields.size(), 3u) << "three fields";
    EXPECT_EQ(fields.begin()->first, 0.0);
    for (const auto& [angle, f] : fields) {
      EXPECT_GT(f[2], 100) << "rays at " << angle << " deg";
      EXPECT_NEAR(f[0] / f[2], 0.0, 1e-6) << "mean dx (um) at " << angle << " deg";
      EXPECT_NEAR(f[1] / f[2], 0.0, 1e-6) << "mean dy (um) at " << angle << " deg";
    }
  }
  for (const auto& entry : std::filesystem::directory_iterator(dir.path()))
    EXPECT_TRUE(entry.path().filename() == "ri.csv" || entry.path().filename() == "ri.svg")
        << "no temporary left behind: " << entry.path();
}

// --what chromatic: the focal shift is zero at the d line and rises to the
// red (the double Gauss is undercorrected); lateral colour is zero on the
// axis and reaches `lens info`'s lateral_color_um at the half diagonal.
TEST(LensPlotCli, ChromaticCsvAgreesWithLensInfo) {
  const std::string lens = kLensDir + "dgauss-100mm.lens";
  const RunResult r = runLensrt({"lens", "plot", lens, "--what", "chromatic", "--csv", "-"});
  ASSERT_EQ(r.status, 0) << r.err;
  const Csv csv = parseCsv(r.out);
  EXPECT_EQ(csv.columns, (std::vector<std::string>{"wavelength_nm", "focal_shift_mm", "image_height_mm",
                                                   "lateral_color_um"}));
  ASSERT_EQ(csv.rows.size(), 41u);
  EXPECT_EQ(csv.rows.front()[0], 400.0);
  EXPECT_EQ(csv.rows.back()[0], 700.0);
  for (std::size_t i = 1; i < csv.rows.size(); ++i) {
    EXPECT_GT(csv.rows[i][1], csv.rows[i - 1][1]) << "the focus recedes toward the red";
    if (csv.rows[i - 1][0] < 587.5618 && csv.rows[i][0] >= 587.5618) {
      EXPECT_LT(csv.rows[i - 1][1], 0.0);
      EXPECT_GE(csv.rows[i][1], 0.0);
    }
  }
  EXPECT_EQ(csv.rows.front()[3], 0.0);
  const RunResult info = runLensrt({"lens", "info", lens, "--json"});
  ASSERT_EQ(info.status, 0) << info.err;
  const std::size_t at = info.out.find("\"lateral_color_um\": ");
  ASSERT_NE(at, std::string::npos);
  const double lateral = std::stod(info.out.substr(at + 20));
  EXPECT_NEAR(csv.rows.back()[2], std::hypot(36.0, 24.0) / 2, 1e-6);
  EXPECT_NEAR(csv.rows.back()[3], lateral, 1e-6);
  EXPECT_GT(lateral, 1.0);
}

TEST(LensPlotCli, BadArgumentsFailWithOneLineAndLeaveTheOutputAlone) {
  const TempDir dir;
  const std::string out = (dir / "keep.svg").string();
  cli::writeFile(out, "precious");
  const struct {
    std::vector<std::string> args;
    int status;
  } cases[] = {
      {{"lens", "plot", "dgauss-50mm", "--what", "mtf", "-o", out}, 2},
      {{"lens", "plot", "dgauss-50mm", "--what", "spot", "--fstop", "abc", "-o", out}, 2},
      {{"lens", "plot", "dgauss-50mm", "--what", "spot", "--fstop", "-2", "-o", out}, 2},
      {{"lens", "diagram", "dgauss-50mm", "--sensor", "36by24", "-o", out}, 2},
      {{"lens", "diagram", "dgauss-50mm", "--focus", "near", "-o", out}, 2},
      {{"lens", "diagram", "dgauss-50mm", "-o", (dir / "x.png").string()}, 2},
      {{"lens", "diagram", "no-such-lens", "-o", out}, 1},
      {{"lens", "diagram", "dgauss-50mm", "--focus", "0.01", "-o", out}, 1},
      // A folder under a file cannot be made.
      {{"lens", "plot", "dgauss-50mm", "--what", "distortion", "-o", (dir / "keep.svg" / "d.svg").string()},
       1},
      {{"lens", "plot", "dgauss-50mm", "--what", "distortion"}, 2},  // neither -o nor --csv
      {{"lens", "plot", "dgauss-50mm", "--what", "spot", "--csv", (dir / "keep.svg" / "s.csv").string()}, 1},
      {{"lens", "plot", "dgauss-50mm", "--what", "spot", "--csv", (dir / "s.csv").string(), "-o",
        out + ".png"},
       2},
  };
  for (const auto& c : cases) {
    const RunResult r = runLensrt(c.args);
    std::string joined;
    for (const auto& a : c.args) joined += a + " ";
    EXPECT_EQ(r.status, c.status) << joined << "\n" << r.err;
    EXPECT_EQ(r.err.rfind("lensrt: error: ", 0), 0u) << joined << "\n" << r.err;
    EXPECT_EQ(cli::lines(r.err).size(), 1u) << joined << "\n" << r.err;
  }
  EXPECT_EQ(readFile(out), "precious");
  for (const auto& entry : std::filesystem::directory_iterator(dir.path()))
    EXPECT_EQ(entry.path().filename(), "keep.svg") << "no temporary left behind";
}

// lens plot and lens diagram word lens errors as lensrt render does: naming
// the lens as typed (a diverging lens used to be blamed on its internal name).
TEST(LensPlotCli, LensErrorsNameTheLensAsTyped) {
  const TempDir dir;
  const std::string diverging = (dir / "diverging.lens").string();
  cli::writeFile(diverging, "radius thick n_d V_d ap\n-50 3 1.5 60 20\n50 10 1 0 20\nstop 10 15\n");
  RunResult r = runLensrt({"lens", "plot", diverging, "--what", "spot", "--csv", "-"});
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err,
            "lensrt: error: " + diverging +
                ": a diverging lens (focal length -49.5 mm) forms no real image, so no film can be focused "
                "behind it\n");
  r = runLensrt({"lens", "diagram", dir.path().string(), "-o", (dir / "d.svg").string()});
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "lensrt: error: " + dir.path().string() + ": is a directory, not a lens file\n");
}

}  // namespace
}  // namespace lensrt
