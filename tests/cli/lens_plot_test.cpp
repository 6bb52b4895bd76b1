// `lensrt lens diagram` and `lensrt lens plot` end to end: well-formed SVG
// with the expected elements, rays that end on the film, and one-line
// errors with the right exit status that leave an existing output untouched.
#include <gtest/gtest.h>

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
      {"spot", {"id=\"spot-0\"", "id=\"spot-1\"", "id=\"spot-2\"", "RMS radius", "(\u00b5m)"}}};
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
      {{"lens", "plot", "dgauss-50mm", "--what", "distortion", "-o", (dir / "missing" / "d.svg").string()},
       1},
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

}  // namespace
}  // namespace lensrt
