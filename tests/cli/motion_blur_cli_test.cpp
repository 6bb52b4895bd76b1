// Motion blur and the rolling shutter against their closed forms, seen
// through an orthographic camera (100 pixels per metre, so a distance on the
// film is a distance in the scene): an emitter moving at constant speed v
// during a shutter T smears into a streak v T long with a flat top; a bar
// moving sideways under a rolling shutter of readout R slants by v R over
// the frame's height; a tiny shutter gives the still frame; and the bits do
// not depend on threads or tiles.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli/cli_util.h"
#include "core/constants.h"
#include "image/image_io.h"

namespace lensrt {
namespace {

using cli::runLensrt;
using cli::RunResult;
using cli::TempDir;
using nlohmann::json;

constexpr int kSize = 200;               // pixels, square
constexpr double kPixelsPerMetre = 100;  // orthographic xmag = ymag = 1 m over 100 px

// An emissive rectangle (width x height metres) seen from +z by an
// orthographic camera over [-1, 1]^2, animated by one LINEAR channel of
// node 0 (`path`: translation or rotation; `values` 3 or 4 per keyframe).
// With a `radius` node 0 is a pivot at the origin and the rectangle sits
// that far out along its x axis, so a rotation spins it in a circle.
std::string animatedRectangle(double width, double height, const std::string& path,
                              const std::vector<float>& times, const std::vector<float>& values,
                              double radius = 0, int animatedNode = 0) {
  const float w = float(width / 2), h = float(height / 2);
  const float positions[] = {-w, -h, 0, w, -h, 0, w, h, 0, -w, h, 0};
  const unsigned short indices[] = {0, 1, 2, 0, 2, 3, 0, 0};
  std::string data(reinterpret_cast<const char*>(positions), sizeof positions);
  data.append(reinterpret_cast<const char*>(indices), sizeof indices);
  const std::size_t timesAt = data.size();
  data.append(reinterpret_cast<const char*>(times.data()), times.size() * sizeof(float));
  const std::size_t valuesAt = data.size();
  data.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(float));
  const std::size_t components = values.size() / times.size();
  const json camera = {{"camera", 0}, {"translation", {0, 0, 5}}};
  const json nodes = radius > 0
                         ? json{{{"children", {2}}}, camera, {{"mesh", 0}, {"translation", {radius, 0, 0}}}}
                         : json{{{"mesh", 0}}, camera};
  json doc = {
      {"asset", {{"version", "2.0"}}},
      {"scene", 0},
      {"scenes", {{{"nodes", {0, 1}}}}},
      {"nodes", nodes},
      {"cameras",
       {{{"type", "orthographic"},
         {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 100}}}}}},
      {"materials",
       {{{"emissiveFactor", {1, 1, 1}}, {"pbrMetallicRoughness", {{"baseColorFactor", {0, 0, 0, 1}}}}}}},
      {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}, {"material", 0}}}}}}},
      {"accessors",
       {{{"bufferView", 0},
         {"componentType", 5126},
         {"count", 4},
         {"type", "VEC3"},
         {"min", {-w, -h, 0}},
         {"max", {w, h, 0}}},
        {{"bufferView", 1}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}},
        {{"bufferView", 2},
         {"componentType", 5126},
         {"count", times.size()},
         {"type", "SCALAR"},
         {"min", {times.front()}},
         {"max", {times.back()}}},
        {{"bufferView", 3},
         {"componentType", 5126},
         {"count", times.size()},
         {"type", components == 4 ? "VEC4" : "VEC3"}}}},
      {"bufferViews",
       {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 48}},
        {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 12}},
        {{"buffer", 0}, {"byteOffset", timesAt}, {"byteLength", times.size() * sizeof(float)}},
        {{"buffer", 0}, {"byteOffset", valuesAt}, {"byteLength", values.size() * sizeof(float)}}}},
      {"buffers",
       {{{"byteLength", data.size()}, {"uri", "data:application/octet-stream;base64," + cli::base64(data)}}}},
      {"animations",
       {{{"name", "move"},
         {"channels", {{{"sampler", 0}, {"target", {{"node", animatedNode}, {"path", path}}}}}},
         {"samplers", {{{"input", 2}, {"output", 3}, {"interpolation", "LINEAR"}}}}}}},
  };
  return doc.dump();
}

// A white diffuse floor (z = 0, 2 x 2 m) under the orthographic camera, lit
// only by a light moving along +x at 1 m/s from x = -1 at t = 0, 0.4 m up:
// a 1 W/sr point light (`emitter` false) or a 0.1 m emissive square facing
// down (true).
std::string floorUnderMovingLight(bool emitter) {
  const float floor[] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
  const float lamp[] = {-0.05f, -0.05f, 0, -0.05f, 0.05f, 0, 0.05f, 0.05f, 0, 0.05f, -0.05f, 0};  // faces -z
  const unsigned short indices[] = {0, 1, 2, 0, 2, 3, 0, 0};
  const float times[] = {0, 10};
  const float translations[] = {-1, 0, 0.4f, 9, 0, 0.4f};
  std::string data(reinterpret_cast<const char*>(floor), sizeof floor);
  data.append(reinterpret_cast<const char*>(lamp), sizeof lamp);
  data.append(reinterpret_cast<const char*>(indices), sizeof indices);
  data.append(reinterpret_cast<const char*>(times), sizeof times);
  data.append(reinterpret_cast<const char*>(translations), sizeof translations);
  json light = {{"translation", {-1, 0, 0.4}}};
  if (emitter)
    light["mesh"] = 1;
  else
    light["extensions"] = {{"KHR_lights_punctual", {{"light", 0}}}};
  json doc = {
      {"asset", {{"version", "2.0"}}},
      {"scene", 0},
      {"scenes", {{{"nodes", {0, 1, 2}}}}},
      {"nodes", {{{"mesh", 0}}, light, {{"camera", 0}, {"translation", {0, 0, 5}}}}},
      {"cameras",
       {{{"type", "orthographic"},
         {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 100}}}}}},
      {"materials",
       {{{"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, 1}}, {"metallicFactor", 0}}}},
        {{"emissiveFactor", {1, 1, 1}},
         {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 100}}}}},
         {"pbrMetallicRoughness", {{"baseColorFactor", {0, 0, 0, 1}}}}}}},
      {"meshes",
       {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 2}, {"material", 0}}}}},
        {{"primitives", {{{"attributes", {{"POSITION", 1}}}, {"indices", 2}, {"material", 1}}}}}}},
      {"accessors",
       {{{"bufferView", 0},
         {"componentType", 5126},
         {"count", 4},
         {"type", "VEC3"},
         {"min", {-1, -1, 0}},
         {"max", {1, 1, 0}}},
        {{"bufferView", 1},
         {"componentType", 5126},
         {"count", 4},
         {"type", "VEC3"},
         {"min", {-0.05, -0.05, 0}},
         {"max", {0.05, 0.05, 0}}},
        {{"bufferView", 2}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}},
        {{"bufferView", 3},
         {"componentType", 5126},
         {"count", 2},
         {"type", "SCALAR"},
         {"min", {0}},
         {"max", {10}}},
        {{"bufferView", 4}, {"componentType", 5126}, {"count", 2}, {"type", "VEC3"}}}},
      {"bufferViews",
       {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 48}},
        {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 48}},
        {{"buffer", 0}, {"byteOffset", 96}, {"byteLength", 12}},
        {{"buffer", 0}, {"byteOffset", 112}, {"byteLength", 8}},
        {{"buffer", 0}, {"byteOffset", 120}, {"byteLength", 24}}}},
      {"buffers",
       {{{"byteLength", data.size()}, {"uri", "data:application/octet-stream;base64," + cli::base64(data)}}}},
      {"animations",
       {{{"name", "carry"},
         {"channels", {{{"sampler", 0}, {"target", {{"node", 1}, {"path", "translation"}}}}}},
         {"samplers", {{{"input", 3}, {"output", 4}, {"interpolation", "LINEAR"}}}}}}},
  };
  if (emitter) {
    doc["extensionsUsed"] = {"KHR_materials_emissive_strength"};
  } else {
    doc["extensionsUsed"] = {"KHR_lights_punctual"};
    doc["extensions"] = {{"KHR_lights_punctual", {{"lights", {{{"type", "point"}, {"intensity", 683}}}}}}};
  }
  return doc.dump();
}

// The rectangle moving along +x at `speed` m/s from x = -1 at t = 0.
std::string movingRectangle(double width, double height, double speed) {
  return animatedRectangle(width, height, "translation", {0, 10}, {-1, 0, 0, float(-1 + 10 * speed), 0, 0});
}

// The rectangle still at the origin, and the camera (node 1, 5 m up the z
// axis) moving along +x at `speed` m/s from x = -1 at t = 0.
std::string movingCamera(double width, double height, double speed) {
  return animatedRectangle(width, height, "translation", {0, 10}, {-1, 0, 5, float(-1 + 10 * speed), 0, 5}, 0,
                           1);
}

// The rectangle at `radius` turning about the z axis at 90 degrees a second
// (keyframes a quarter turn apart: slerp takes the short way between them).
std::string spinningRectangle(double size, double radius) {
  std::vector<float> times, rotations;
  for (int k = 0; k <= 4; ++k) {
    const double half = 0.25 * kPi * k;  // half the angle, 90 degrees a keyframe
    times.push_back(float(k));
    rotations.insert(rotations.end(), {0, 0, float(std::sin(half)), float(std::cos(half))});
  }
  return animatedRectangle(size, size, "rotation", times, rotations, radius);
}

Image render(const TempDir& dir, const std::string& scene, const std::string& out,
             const std::vector<std::string>& extra, int spp = 64) {
  std::vector<std::string> args{"render",
                                (dir / scene).string(),
                                "--env",
                                "none",
                                "--res",
                                std::to_string(kSize) + "x" + std::to_string(kSize),
                                "--spp",
                                std::to_string(spp),
                                "-q",
                                "-o",
                                (dir / out).string()};
  args.insert(args.end(), extra.begin(), extra.end());
  const RunResult r = runLensrt(args);
  EXPECT_EQ(r.status, 0) << r.err;
  return readImage(dir / out);
}

// Mean red of a row band [y0, y1) at each column.
std::vector<double> columnProfile(const Image& image, int y0, int y1) {
  std::vector<double> profile(static_cast<std::size_t>(image.width), 0.0);
  for (int y = y0; y < y1; ++y)
    for (int x = 0; x < image.width; ++x)
      profile[static_cast<std::size_t>(x)] += image.at(x, y, 0) / (y1 - y0);
  return profile;
}

// The width at half the plateau, in pixels, from linear interpolation at
// both edges of a single bump.
double widthAtHalf(const std::vector<double>& profile, double plateau) {
  const double half = plateau / 2;
  std::size_t first = 0, last = profile.size() - 1;
  while (first < profile.size() && profile[first] < half) ++first;
  while (last > 0 && profile[last] < half) --last;
  if (first == 0 || last + 1 >= profile.size() || first > last) return -1;
  const double left = double(first) - (profile[first] - half) / (profile[first] - profile[first - 1]);
  const double right = double(last) + (profile[last] - half) / (profile[last] - profile[last + 1]);
  return right - left;
}

// An emitter 0.1 m wide moving at 1 m/s during 0.4 s: a streak 40 px long at
// half height (the box blur of a 10 px box by a 40 px one), flat over the
// 30 px where the whole shutter sees it. Shown to fail with the shutter's
// share of the time scaled by 0.95 (a streak of 38.3 px) and the readout's
// by 0.97 (slants of 29.1 px in the rolling shutter's test).
TEST(MotionBlurCli, AnEmitterMovingAtConstantSpeedMakesAStreakVTLong) {
  const TempDir dir;
  cli::writeFile(dir / "slide.gltf", movingRectangle(0.1, 0.4, 1.0));
  const Image still = render(dir, "slide.gltf", "still.exr", {"--time", "1", "--shutter", "0"});
  const Image blur = render(dir, "slide.gltf", "blur.exr", {"--time", "0.8", "--shutter", "0.4"});
  const std::vector<double> stillProfile = columnProfile(still, 90, 110);
  const std::vector<double> blurProfile = columnProfile(blur, 90, 110);
  EXPECT_NEAR(widthAtHalf(stillProfile, 1.0), 0.1 * kPixelsPerMetre, 1.0);
  // Centred where the emitter is at mid-shutter (t = 1: x = 0, the frame's centre).
  const double streak = widthAtHalf(blurProfile, 0.1 / 0.4);
  EXPECT_NEAR(streak, 1.0 * 0.4 * kPixelsPerMetre, 1.0) << "v T = 40 px";
  // The plateau [x = 100 - 15, 100 + 15) px: the emitter covers each of its
  // points for 0.1 s of the 0.4 s, a quarter of its radiance.
  double lo = 1e9, hi = 0, sum = 0;
  for (int x = 100 - 13; x < 100 + 13; ++x) {
    lo = std::min(lo, blurProfile[static_cast<std::size_t>(x)]);
    hi = std::max(hi, blurProfile[static_cast<std::size_t>(x)]);
    sum += blurProfile[static_cast<std::size_t>(x)];
  }
  EXPECT_NEAR(sum / 26, 0.25, 0.01);
  EXPECT_LT(hi - lo, 0.03) << "a flat top: from " << lo << " to " << hi;
  // Light is moved, not made: the streak holds the still frame's energy.
  double stillSum = 0, blurSum = 0;
  for (std::size_t x = 0; x < stillProfile.size(); ++x)
    stillSum += stillProfile[x], blurSum += blurProfile[x];
  EXPECT_NEAR(blurSum / stillSum, 1.0, 0.01);
}

// The camera's node moving at 1 m/s past a still emitter during 0.4 s: the
// same 40 px streak, the camera's rays moved with it to their time. (A
// camera left at its opening pose shows the emitter 10 px wide.)
TEST(MotionBlurCli, ACameraMovingPastAnEmitterStreaksIt) {
  const TempDir dir;
  cli::writeFile(dir / "pan.gltf", movingCamera(0.1, 0.4, 1.0));
  const Image blur = render(dir, "pan.gltf", "pan.exr", {"--time", "0.8", "--shutter", "0.4"});
  EXPECT_NEAR(widthAtHalf(columnProfile(blur, 90, 110), 0.1 / 0.4), 0.4 * kPixelsPerMetre, 1.0);
}

// Moving lights light the scene from where they are at each ray's time: a
// floor lit by a light crossing it during the shutter is the mean of the
// still frames over the shutter (8 instants, each midway in its eighth),
// in each quarter of the frame across the motion within 3%. Shown to fail
// with the lights left where they were when the shutter opened (the point
// light's quarters at 2.38, 1.26, 0.40 and 0.33 of the mean).
TEST(MotionBlurCli, MovingLightsLightFromWhereTheyAreAtEachRaysTime) {
  const TempDir dir;
  for (const bool emitter : {false, true}) {
    const std::string name = emitter ? "emitter.gltf" : "lamp.gltf";
    cli::writeFile(dir / name, floorUnderMovingLight(emitter));
    const auto quarters = [&](const Image& image) {
      std::vector<double> q(4, 0.0);
      for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) q[std::size_t(4 * x / image.width)] += image.at(x, y, 0);
      return q;
    };
    const std::vector<double> blurred =
        quarters(render(dir, name, "blur.exr", {"--time", "0.6", "--shutter", "0.8"}, 128));
    std::vector<double> mean(4, 0.0);
    for (int k = 0; k < 8; ++k) {
      const std::string at = std::to_string(0.6 + 0.8 * (k + 0.5) / 8);
      const std::vector<double> q =
          quarters(render(dir, name, "still.exr", {"--time", at, "--shutter", "0"}, 16));
      for (int i = 0; i < 4; ++i) mean[std::size_t(i)] += q[std::size_t(i)] / 8;
    }
    for (int i = 0; i < 4; ++i)
      EXPECT_NEAR(blurred[std::size_t(i)] / mean[std::size_t(i)], 1.0, 0.03)
          << (emitter ? "emissive square" : "point light") << ", quarter " << i;
  }
}

// A trapezoid shutter opening over a quarter of the interval and closing
// over another: the blur kernel is the trapezoid, so the streak's ends ramp
// and its width at half height is (1 - F) v T.
TEST(MotionBlurCli, ATrapezoidShutterRampsTheStreaksEnds) {
  const TempDir dir;
  cli::writeFile(dir / "slide.gltf", movingRectangle(0.02, 0.4, 1.0));
  const Image blur = render(dir, "slide.gltf", "trap.exr",
                            {"--time", "0.8", "--shutter", "0.4", "--shutter-curve", "trapezoid:0.25"});
  const std::vector<double> profile = columnProfile(blur, 90, 110);
  // The kernel's height: the 2 px emitter over 40 px at a transmission of
  // 1 / (1 - F) of the box's mean.
  const double plateau = 0.02 / 0.4 / (1 - 0.25);
  EXPECT_NEAR(widthAtHalf(profile, plateau), (1 - 0.25) * 0.4 * kPixelsPerMetre, 1.0);
  // Over each 10 px ramp the kernel rises (falls) linearly: pixels 81-88
  // (centres 1.5 to 8.5 px past the emitter's centre at the opening, x = 80
  // px) average half the plateau, as do 111-118 at the closing. A box
  // shutter gives 0.8 and more there.
  double rising = 0, falling = 0;
  for (int k = 0; k < 8; ++k) {
    rising += profile[static_cast<std::size_t>(81 + k)] / plateau / 8;
    falling += profile[static_cast<std::size_t>(111 + k)] / plateau / 8;
  }
  EXPECT_NEAR(rising, 0.5, 0.05);
  EXPECT_NEAR(falling, 0.5, 0.05);
}

// A bar 0.05 m wide spanning the frame's height, moving at 1 m/s, under a
// rolling shutter read out top-down in 0.3 s: each row sees it later, so its
// centre moves 30 px to the right from the top row to the bottom one; read
// bottom-up it slants the other way.
TEST(MotionBlurCli, ARollingShutterSlantsAMovingBarByVTimesTheReadout) {
  const TempDir dir;
  cli::writeFile(dir / "bar.gltf", movingRectangle(0.05, 3.0, 1.0));
  const auto slant = [&](const std::string& readout) {
    const Image image =
        render(dir, "bar.gltf", readout + ".exr",
               {"--time", "0.85", "--shutter", "0", "--rolling-shutter", "0.3", "--readout", readout}, 16);
    // Centroid of each row; the least-squares slope over the rows, times the height.
    double sy = 0, sx = 0, syy = 0, sxy = 0;
    const int n = image.height;
    for (int y = 0; y < n; ++y) {
      double mass = 0, moment = 0;
      for (int x = 0; x < image.width; ++x) {
        mass += image.at(x, y, 0);
        moment += image.at(x, y, 0) * (x + 0.5);
      }
      const double cx = moment / mass, yc = y + 0.5;
      sy += yc, sx += cx, syy += yc * yc, sxy += yc * cx;
    }
    const double slope = (n * sxy - sy * sx) / (n * syy - sy * sy);
    return slope * n;
  };
  const double expected = 1.0 * 0.3 * kPixelsPerMetre;
  EXPECT_NEAR(slant("top-down"), expected, 0.02 * expected);
  EXPECT_NEAR(slant("bottom-up"), -expected, 0.02 * expected);
}

// A square 0.8 m from the axis, spinning 90 degrees during the shutter
// (45 to 135 degrees): its blur is a circular arc, whose middle (at 90
// degrees, the top of the frame's centre column) stays 80 px above the
// centre. Linear steps are chords: two time steps would put the middle at
// 0.8 cos 45 = 0.57 m (57 px), ten (9 degrees each) within 0.1 px. Shown
// to fail (56.6 px) with steps of 90 degrees and no check for curved paths.
TEST(MotionBlurCli, ASpinningSquareBlursIntoACircularArc) {
  const TempDir dir;
  cli::writeFile(dir / "spin.gltf", spinningRectangle(0.04, 0.8));
  const Image blur = render(dir, "spin.gltf", "spin.exr", {"--time", "0.5", "--shutter", "1"});
  // The centroid of the columns 98-101 along y, and of the arc's row at 45 degrees.
  double mass = 0, moment = 0;
  for (int y = 0; y < kSize / 2; ++y)
    for (int x = 98; x < 102; ++x) {
      mass += blur.at(x, y, 0);
      moment += blur.at(x, y, 0) * (y + 0.5);
    }
  ASSERT_GT(mass, 0);
  EXPECT_NEAR(kSize / 2 - moment / mass, 0.8 * kPixelsPerMetre, 1.0);
  // Along the diagonal at 112.5 degrees (between the middle and the end) too.
  const double a = 112.5 * kPi / 180;
  double along = 0, weight = 0;
  for (double r = 0.5; r < 1.0; r += 0.0025) {
    const int x = int(std::floor(kSize / 2 + r * std::cos(a) * kPixelsPerMetre));
    const int y = int(std::floor(kSize / 2 - r * std::sin(a) * kPixelsPerMetre));
    along += blur.at(x, y, 0) * r;
    weight += blur.at(x, y, 0);
  }
  ASSERT_GT(weight, 0);
  EXPECT_NEAR(along / weight * kPixelsPerMetre, 0.8 * kPixelsPerMetre, 1.0);
}

// A shutter of a microsecond is the still frame at its opening within noise
// (the same samples, the emitter moved by a micrometre).
TEST(MotionBlurCli, ATinyShutterIsTheStillFrame) {
  const TempDir dir;
  cli::writeFile(dir / "slide.gltf", movingRectangle(0.1, 0.4, 1.0));
  const Image still = render(dir, "slide.gltf", "still.exr", {"--time", "1", "--shutter", "0"}, 16);
  const Image tiny = render(dir, "slide.gltf", "tiny.exr", {"--time", "1", "--shutter", "1e-6"}, 16);
  double differ = 0, total = 0;
  for (std::size_t i = 0; i < still.pixels.size(); ++i) {
    differ += std::abs(still.pixels[i] - tiny.pixels[i]);
    total += std::abs(still.pixels[i]);
  }
  EXPECT_LT(differ / total, 1e-3);
  // And a real shutter is not.
  const Image blur = render(dir, "slide.gltf", "blur.exr", {"--time", "1", "--shutter", "0.2"}, 16);
  double blurDiffer = 0;
  for (std::size_t i = 0; i < still.pixels.size(); ++i)
    blurDiffer += std::abs(still.pixels[i] - blur.pixels[i]);
  EXPECT_GT(blurDiffer / total, 0.1);
}

TEST(MotionBlurCli, MotionBlurIsTheSameBitsOnAnyThreadsAndTiles) {
  const TempDir dir;
  cli::writeFile(dir / "slide.gltf", movingRectangle(0.1, 0.4, 1.0));
  const std::vector<std::string> blur{"--time", "0.9", "--shutter", "0.2", "--rolling-shutter", "0.1"};
  const auto with = [&](std::vector<std::string> extra) {
    extra.insert(extra.begin(), blur.begin(), blur.end());
    return extra;
  };
  const Image one = render(dir, "slide.gltf", "t1.exr", with({"--threads", "1"}), 4);
  EXPECT_EQ(one.pixels, render(dir, "slide.gltf", "t2.exr", with({"--threads", "2"}), 4).pixels);
  render(dir, "slide.gltf", "p0.exr", with({"--tile", "0/2"}), 4);
  render(dir, "slide.gltf", "p1.exr", with({"--tile", "1/2"}), 4);
  const RunResult m = runLensrt(
      {"merge", (dir / "p0.exr").string(), (dir / "p1.exr").string(), "-o", (dir / "m.exr").string()});
  ASSERT_EQ(m.status, 0) << m.err;
  EXPECT_EQ(one.pixels, readImage(dir / "m.exr").pixels);
}

// --frames renders each frame of the range to its own file, bit for bit the
// render of that --frame; a name without a frame number is refused before
// any work.
TEST(MotionBlurCli, FramesRenderEachFrameAsFrameDoes) {
  const TempDir dir;
  cli::writeFile(dir / "slide.gltf", movingRectangle(0.1, 0.4, 1.0));
  const std::vector<std::string> common{"--fps", "4", "--shutter", "0.05"};
  const auto with = [&](std::vector<std::string> extra) {
    extra.insert(extra.end(), common.begin(), common.end());
    return extra;
  };
  std::vector<std::string> sequence{
      "render", (dir / "slide.gltf").string(), "--env", "none", "--res", "200x200", "--spp", "2", "-q",
      "-o",     (dir / "f.##.exr").string()};
  for (const std::string& a : with({"--frames", "2:6:2"})) sequence.push_back(a);
  const RunResult r = runLensrt(sequence);
  ASSERT_EQ(r.status, 0) << r.err;
  for (const int f : {2, 4, 6}) {
    const Image one = render(dir, "slide.gltf", "one.exr", with({"--frame", std::to_string(f)}), 2);
    EXPECT_EQ(readImage(dir / fmt::format("f.{:02d}.exr", f)).pixels, one.pixels) << f;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "f.03.exr"));
  const RunResult plain = runLensrt(
      {"render", (dir / "slide.gltf").string(), "--frames", "0:2", "-o", (dir / "plain.exr").string()});
  EXPECT_EQ(plain.status, 2);
  EXPECT_NE(plain.err.find("# marks or %04d"), std::string::npos) << plain.err;
  const RunResult both = runLensrt({"render", (dir / "slide.gltf").string(), "--frames", "0:2", "--time", "1",
                                    "-o", (dir / "f%03d.exr").string()});
  EXPECT_EQ(both.status, 2);
  EXPECT_NE(both.err.find("not both"), std::string::npos) << both.err;
  const RunResult backwards = runLensrt(
      {"render", (dir / "slide.gltf").string(), "--frames", "5:2", "-o", (dir / "f%03d.exr").string()});
  EXPECT_EQ(backwards.status, 2);
  EXPECT_NE(backwards.err.find("A <= B"), std::string::npos) << backwards.err;
}

// --frames with --focus auto focuses once, on what the centre sees at the
// first frame, and holds it: a wall 5 m before a thin lens at t = 0 that
// comes to 3 m at t = 1 s stays focused at 5 m in both frames (refocusing
// each frame would breathe), while --frame 1 alone focuses at 3 m.
TEST(MotionBlurCli, FramesHoldTheFirstFramesAutoFocus) {
  const TempDir dir;
  json doc = json::parse(animatedRectangle(20, 20, "translation", {0, 1}, {0, 0, 0, 0, 0, 2}));
  doc["cameras"][0] = {{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}};
  cli::writeFile(dir / "approach.gltf", doc.dump());
  const std::vector<std::string> common{"render",
                                        (dir / "approach.gltf").string(),
                                        "--camera",
                                        "thin",
                                        "--focal-length",
                                        "50",
                                        "--fstop",
                                        "4",
                                        "--env",
                                        "none",
                                        "--res",
                                        "16x16",
                                        "--spp",
                                        "1",
                                        "--shutter",
                                        "0",
                                        "--fps",
                                        "1",
                                        "-q"};
  const auto focusOf = [&](const std::filesystem::path& file) {
    ImageMetadata meta;
    readImage(file, &meta);
    return std::stod(meta.at("lensrt:focus_m"));
  };
  std::vector<std::string> sequence = common;
  sequence.insert(sequence.end(), {"--frames", "0:1", "-o", (dir / "f.#.exr").string()});
  const RunResult r = runLensrt(sequence);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NEAR(focusOf(dir / "f.0.exr"), 5.0, 1e-3);
  EXPECT_NEAR(focusOf(dir / "f.1.exr"), 5.0, 1e-3);
  std::vector<std::string> alone = common;
  alone.insert(alone.end(), {"--frame", "1", "-o", (dir / "alone.exr").string()});
  const RunResult one = runLensrt(alone);
  ASSERT_EQ(one.status, 0) << one.err;
  EXPECT_NEAR(focusOf(dir / "alone.exr"), 3.0, 1e-3);
}

// A moment or a rolling shutter asked of a scene that does not move: one
// notice each, and the image of the scene at rest.
TEST(MotionBlurCli, TimeOnAStillSceneGivesANotice) {
  const TempDir dir;
  const std::string cornell = std::string(LENSRT_SOURCE_DIR) + "/scenes/cornell.gltf";
  const RunResult r = runLensrt({"render", cornell, "--time", "2", "--rolling-shutter", "0.01", "--res",
                                 "16x16", "--spp", "1", "-o", (dir / "a.exr").string()});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("at 2 s: the file has no animation"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("the rolling shutter and shutter curve change nothing"), std::string::npos) << r.err;
  const RunResult still =
      runLensrt({"render", cornell, "--res", "16x16", "--spp", "1", "-q", "-o", (dir / "b.exr").string()});
  EXPECT_EQ(readImage(dir / "a.exr").pixels, readImage(dir / "b.exr").pixels);
}

TEST(MotionBlurCli, BadShutterFlagsAreOneLineUsageErrors) {
  const TempDir dir;
  cli::writeFile(dir / "slide.gltf", movingRectangle(0.1, 0.4, 1.0));
  for (const auto& [flag, value, says] : {std::tuple{"--shutter", "-1", "--shutter"},
                                          std::tuple{"--rolling-shutter", "soon", "--rolling-shutter"},
                                          std::tuple{"--shutter-curve", "trapezoid:0.7", "0 < F <= 0.5"},
                                          std::tuple{"--readout", "diagonal", "--readout"}}) {
    const RunResult r =
        runLensrt({"render", (dir / "slide.gltf").string(), flag, value, "-o", (dir / "x.exr").string()});
    EXPECT_EQ(r.status, 2) << flag;
    EXPECT_NE(r.err.find(says), std::string::npos) << r.err;
    EXPECT_EQ(cli::lines(r.err).size(), 1u) << r.err;
  }
  const RunResult physical =
      runLensrt({"render", (dir / "slide.gltf").string(), "--shutter", "0", "--exposure", "physical",
                 "--film", "irradiance", "-o", (dir / "x.exr").string()});
  EXPECT_EQ(physical.status, 2);
  EXPECT_NE(physical.err.find("records no light"), std::string::npos) << physical.err;
}

}  // namespace
}  // namespace lensrt
