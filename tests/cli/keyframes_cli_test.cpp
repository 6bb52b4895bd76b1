// --focus keyframes (SECONDS:METRES,...): read at --time, linear between
// keyframes and held outside them, so a keyframed render is bit for bit the
// render at the focus the keyframes give then.
#include <gtest/gtest.h>

#include "cli/cli_util.h"
#include "image/image_io.h"

namespace lensrt {
namespace {

using cli::runLensrt;
using cli::RunResult;
using cli::TempDir;

const std::string kDofRow = std::string(LENSRT_SOURCE_DIR) + "/scenes/dof_row.gltf";

Image renderFocus(const TempDir& dir, const std::string& name, const std::string& focus,
                  const std::string& time, ImageMetadata& meta, const std::string& fstop = "2") {
  std::vector<std::string> args{"render",
                                kDofRow,
                                "--camera",
                                "lens",
                                "--lens",
                                "dgauss-50mm",
                                "--fstop",
                                fstop,
                                "--focus",
                                focus,
                                "--res",
                                "48x27",
                                "--spp",
                                "2",
                                "-q",
                                "-o",
                                (dir / name).string()};
  if (!time.empty()) args.insert(args.end(), {"--time", time});
  const RunResult r = runLensrt(args);
  EXPECT_EQ(r.status, 0) << r.err;
  return readImage(dir / name, &meta);
}

TEST(KeyframesCli, AKeyframedFocusIsTheFocusAtThatTime) {
  const TempDir dir;
  for (const auto& [time, metres] :
       {std::pair{"1", "2"}, std::pair{"-5", "1"}, std::pair{"0.5", "1.5"}, std::pair{"9", "3"}}) {
    ImageMetadata keyed, plain;
    const Image a = renderFocus(dir, "a.exr", "0:1,2:3", time, keyed);
    const Image b = renderFocus(dir, "b.exr", metres, "", plain);
    EXPECT_EQ(keyed["lensrt:focus_m"], metres) << time;
    EXPECT_EQ(a.pixels, b.pixels) << "at " << time << " s the focus is " << metres << " m";
  }
}

TEST(KeyframesCli, AKeyframedFStopIsTheFStopAtThatTime) {
  const TempDir dir;
  for (const auto& [time, fstop] : {std::pair{"1", "4"}, std::pair{"3", "6"}}) {
    ImageMetadata keyed, plain;
    const Image a = renderFocus(dir, "a.exr", "2", time, keyed, "0:2,2:6");
    const Image b = renderFocus(dir, "b.exr", "2", "", plain, fstop);
    EXPECT_EQ(keyed["lensrt:f_number"], fstop) << time;
    EXPECT_EQ(a.pixels, b.pixels) << "at " << time << " s the f-number is " << fstop;
  }
}

}  // namespace
}  // namespace lensrt
