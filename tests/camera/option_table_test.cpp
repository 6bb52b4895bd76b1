// The option table (api/option_table.h): every row well formed, the render's
// identity walks it (a row that changes the image is part of it, one that
// does not leaves the pixels alone), settings that do nothing are named, and
// Python's messages name keywords.
#include "api/option_table.h"

#include <gtest/gtest.h>

#include <cctype>
#include <set>

#include "api/render_request.h"
#include "core/error.h"

namespace lensrt {
namespace {

TEST(OptionTable, EveryRowIsWellFormed) {
  std::set<std::string> flags, keywords;
  const RenderSpec defaults;
  for (const Option& o : optionTable()) {
    SCOPED_TRACE(o.flag);
    EXPECT_TRUE(flags.insert(o.flag).second) << "twice";
    if (!o.keyword.empty()) {
      EXPECT_TRUE(keywords.insert(o.keyword).second) << "twice";
      std::string fromFlag = o.flag.substr(2);
      for (char& c : fromFlag)
        if (c == '-') c = '_';
      EXPECT_EQ(o.keyword, fromFlag) << "a keyword is its flag's name";
    }
    EXPECT_FALSE(o.help.empty());
    EXPECT_FALSE(o.group.empty());
    EXPECT_TRUE(o.set && o.show);
    EXPECT_EQ(bool(o.applies), !o.usedBy.empty()) << "a row that may do nothing says what would use it";
    // The example is a value the row takes, other than the default.
    RenderSpec spec;
    EXPECT_NO_THROW(o.set(spec, o.example));
    EXPECT_NE(o.show(spec), o.show(defaults)) << "the example " << o.example << " is the default";
    // A bad value is refused, naming the flag.
    if (o.python != PyValue::Text && o.python != PyValue::Path && !o.isFlag && o.keyword != "camera_node" &&
        o.keyword != "animation") {
      try {
        o.set(spec, "not-a-value");
        ADD_FAILURE() << "took 'not-a-value'";
      } catch (const UsageError& e) {
        EXPECT_EQ(e.option(), o.flag);
      }
    }
  }
}

// Each row set to its example changes the identity exactly where the row
// says it is part of it. The pixels of the rows that say they never change
// the image are checked below.
TEST(OptionTable, IdentityWalksTheTable) {
  const std::string base = optionsIdentity(RenderSpec{});
  EXPECT_EQ(base, "");
  for (const Option& o : optionTable()) {
    SCOPED_TRACE(o.flag + " " + o.example);
    RenderSpec spec;
    o.set(spec, o.example);
    const std::string id = optionsIdentity(spec);
    if (o.identity == Identity::Image)
      EXPECT_NE(id.find((o.keyword.empty() ? o.flag.substr(2) : o.keyword) + "="), std::string::npos) << id;
    else
      EXPECT_EQ(id, base);
  }
}

// The rows outside the identity that could touch a render (Identity::None)
// leave its pixels bit for bit alone: a row that does change them must be
// marked Image, or two different renders would be joined.
TEST(OptionTable, RowsOutsideTheIdentityLeaveThePixelsAlone) {
  const auto renderWith = [](const Option* row) {
    RenderRequest request;
    RenderSpec& spec = request.spec;
    spec.scene.file = std::string(LENSRT_SOURCE_DIR) + "/scenes/dof_row.gltf";
    spec.resolution = Resolution{24, 14};
    spec.sampling.spp = 2;
    spec.sampling.threads = 1;
    if (row) row->set(spec, row->example);
    Warnings warnings;
    return render(nullptr, request, warnings).image.pixels;
  };
  const std::vector<float> reference = renderWith(nullptr);
  int checked = 0;
  for (const Option& o : optionTable()) {
    if (o.identity != Identity::None) continue;
    SCOPED_TRACE(o.flag + " " + o.example);
    EXPECT_EQ(renderWith(&o), reference);
    ++checked;
  }
  EXPECT_GE(checked, 4);  // threads, tile size, the scene's limits, fps
}

TEST(OptionTable, SettingsThatDoNothingAreNamed) {
  RenderSpec spec;
  std::vector<const Option*> given;
  for (const char* flag : {"--lens", "--fstop"}) {
    given.push_back(findOption(flag));
    given.back()->set(spec, given.back()->example);
  }
  const std::vector<std::string> pinhole = unusedSettings(spec, given);
  ASSERT_EQ(pinhole.size(), 2u);
  EXPECT_EQ(pinhole[1].rfind("--fstop does nothing with the pinhole's radiance film", 0), 0u) << pinhole[1];
  EXPECT_NE(pinhole[0].find("--camera lens"), std::string::npos) << pinhole[0];
  findOption("--camera")->set(spec, "lens");
  EXPECT_TRUE(unusedSettings(spec, given).empty());
  // compare renders every model: nothing there is unused.
  findOption("--camera")->set(spec, "pinhole");
  EXPECT_TRUE(unusedSettings(spec, given, kCompareCommand).empty());
}

TEST(OptionTable, PythonMessagesNameKeywords) {
  EXPECT_EQ(inKeywords("--min-spp: 4 is above --spp 1 (the most)"), "min_spp: 4 is above spp=1 (the most)");
  EXPECT_EQ(inKeywords("--flare: it needs --camera lens"), "flare: it needs camera='lens'");
  EXPECT_EQ(inKeywords("--fstop and --lens do not apply"), "fstop and lens do not apply");
  EXPECT_EQ(inKeywords("needs --noise-threshold (adaptive sampling)"),
            "needs noise_threshold (adaptive sampling)");
  EXPECT_EQ(inKeywords("--unknown-flag stays"), "--unknown-flag stays");
}

}  // namespace
}  // namespace lensrt
