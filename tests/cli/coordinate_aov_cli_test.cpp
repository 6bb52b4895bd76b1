// The coordinate AOVs against the scene's closed form. A pinhole at the
// origin looks down -Z at a wall at z = -4 (its node unmoved, no TEXCOORD_0,
// ending at x = 1 so the frame's right edge sees the sky) and, in front of
// it, a 1 m square placed by a node turned 30 degrees about +Y and moved to
// (0.4, 0.1, -2.5), with uv = its local (x, y) + 0.5. For each pixel the ray
// through its centre meets the plane it sees at p (the wall's or the
// square's, solved by hand): position is p, object_coords is p in the node's
// frame (R^T (p - t) for the square, p for the wall), uv is the square's
// local (x + 0.5, y + 0.5) or (0, 0) on the wall, and the sky gives 0.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "cli/cli_util.h"
#include "image/image_io.h"

namespace lensrt {
namespace {

using cli::runLensrt;
using cli::TempDir;

constexpr int kWidth = 48, kHeight = 32;
constexpr double kYfov = 0.5;
constexpr double kTurn = 30.0 * 3.14159265358979323846 / 180.0;  // about +Y
constexpr std::array<double, 3> kSquareAt{0.4, 0.1, -2.5};

std::string twoQuadsGltf() {
  // The wall (no uv) then the square (positions, uv), each a quad 0 1 2, 0 2 3.
  const float wall[12] = {-50, -50, -4, 1, -50, -4, 1, 50, -4, -50, 50, -4};
  const float square[12] = {-0.5f, -0.5f, 0, 0.5f, -0.5f, 0, 0.5f, 0.5f, 0, -0.5f, 0.5f, 0};
  const float uv[8] = {0, 0, 1, 0, 1, 1, 0, 1};
  const unsigned short indices[6] = {0, 1, 2, 0, 2, 3};
  std::string data;
  data.append(reinterpret_cast<const char*>(wall), sizeof wall);        // 0: 48 bytes
  data.append(reinterpret_cast<const char*>(square), sizeof square);    // 48: 48 bytes
  data.append(reinterpret_cast<const char*>(uv), sizeof uv);            // 96: 32 bytes
  data.append(reinterpret_cast<const char*>(indices), sizeof indices);  // 128: 12 bytes
  const double s = std::sin(kTurn / 2), c = std::cos(kTurn / 2);
  return std::string(R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0,1,2]}],)") +
         R"("cameras":[{"type":"perspective","perspective":{"yfov":0.5,"znear":0.001}}],)" +
         R"("nodes":[{"mesh":0},{"mesh":1,"translation":[0.4,0.1,-2.5],"rotation":[0,)" + std::to_string(s) +
         ",0," + std::to_string(c) + R"(]},{"camera":0}],)" +
         R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":3}]},)" +
         R"({"primitives":[{"attributes":{"POSITION":1,"TEXCOORD_0":2},"indices":3}]}],)" +
         R"("accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3","min":[-50,-50,-4],"max":[1,50,-4]},)" +
         R"({"bufferView":1,"componentType":5126,"count":4,"type":"VEC3","min":[-0.5,-0.5,0],"max":[0.5,0.5,0]},)" +
         R"({"bufferView":2,"componentType":5126,"count":4,"type":"VEC2"},)" +
         R"({"bufferView":3,"componentType":5123,"count":6,"type":"SCALAR"}],)" +
         R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":48},)" +
         R"({"buffer":0,"byteOffset":96,"byteLength":32},{"buffer":0,"byteOffset":128,"byteLength":12}],)" +
         R"("buffers":[{"byteLength":)" + std::to_string(data.size()) +
         R"(,"uri":"data:application/octet-stream;base64,)" + cli::base64(data) + R"("}]})";
}

struct Seen {
  enum What { Sky, Wall, Square } what = Sky;
  std::array<double, 3> world{0, 0, 0}, object{0, 0, 0};
};

// What the ray through film point (fx, fy) (pixels, from the top left) meets.
Seen trace(double fx, double fy) {
  const double tanY = std::tan(kYfov / 2), tanX = tanY * kWidth / kHeight;
  const std::array<double, 3> d{(2 * fx / kWidth - 1) * tanX, (1 - 2 * fy / kHeight) * tanY, -1.0};
  const double cs = std::cos(kTurn), sn = std::sin(kTurn);
  // The square's plane: normal R (0, 0, 1) = (sin, 0, cos) through kSquareAt.
  const double n[3] = {sn, 0, cs};
  const double s = (n[0] * kSquareAt[0] + n[1] * kSquareAt[1] + n[2] * kSquareAt[2]) /
                   (n[0] * d[0] + n[1] * d[1] + n[2] * d[2]);
  const std::array<double, 3> p{s * d[0], s * d[1], s * d[2]};
  const double r[3] = {p[0] - kSquareAt[0], p[1] - kSquareAt[1], p[2] - kSquareAt[2]};
  // R^T for R = [[c, 0, s], [0, 1, 0], [-s, 0, c]].
  const std::array<double, 3> local{cs * r[0] - sn * r[2], r[1], sn * r[0] + cs * r[2]};
  if (s > 0 && std::abs(local[0]) < 0.5 && std::abs(local[1]) < 0.5) return {Seen::Square, p, local};
  const std::array<double, 3> w{4 * d[0], 4 * d[1], -4.0};
  if (w[0] < 1) return {Seen::Wall, w, w};
  return {};
}

TEST(CoordinateAovCli, PositionUvAndObjectCoordinatesMatchTheLayout) {
  const TempDir dir;
  cli::writeFile(dir / "scene.gltf", twoQuadsGltf());
  const std::string out = (dir / "out.exr").string();
  const cli::RunResult r =
      runLensrt({"render", (dir / "scene.gltf").string(), "--camera", "pinhole", "--res",
                 std::to_string(kWidth) + "x" + std::to_string(kHeight), "--spp", "64", "--env", "constant:1",
                 "--aov", "position,uv,object_coords", "-q", "-o", out});
  ASSERT_EQ(r.status, 0) << r.err;
  const Image image = readImage(out);
  ASSERT_EQ(image.width, kWidth);
  const int a = image.channelIndex("A");
  int position[3], object[3], uv[2];
  for (int k = 0; k < 3; ++k) {
    position[k] = image.channelIndex(std::string("position.") + "XYZ"[k]);
    object[k] = image.channelIndex(std::string("object_coords.") + "XYZ"[k]);
    ASSERT_GE(position[k], 0);
    ASSERT_GE(object[k], 0);
  }
  uv[0] = image.channelIndex("uv.U");
  uv[1] = image.channelIndex("uv.V");
  ASSERT_GE(uv[0], 0);
  ASSERT_GE(uv[1], 0);

  int counted[3] = {0, 0, 0}, wrong = 0;
  double worst = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      // Only pixels that see one thing across their whole area (and a margin
      // for the pixel filter): the centre's value is then the mean's.
      const Seen centre = trace(x + 0.5, y + 0.5);
      bool uniform = true;
      for (double dx : {-0.5, 0.5, 1.5})
        for (double dy : {-0.5, 0.5, 1.5}) uniform = uniform && trace(x + dx, y + dy).what == centre.what;
      if (!uniform) continue;
      ++counted[centre.what];
      const auto off = [&](int channel, double expected, double tolerance) {
        const double e = std::abs(image.at(x, y, channel) - expected);
        worst = std::max(worst, e / tolerance);
        return e > tolerance;
      };
      bool bad = false;
      // The sky: 0 in every coordinate channel (and alpha 0).
      if (centre.what == Seen::Sky) {
        bad = off(a, 0, 0);
        for (int k = 0; k < 3; ++k) bad = off(position[k], 0, 0) || off(object[k], 0, 0) || bad;
        for (int k = 0; k < 2; ++k) bad = off(uv[k], 0, 0) || bad;
      } else {
        // A pixel is 4-6 cm wide at 2.5-4 m: 1 mm is 2% of it.
        for (int k = 0; k < 3; ++k)
          bad = off(position[k], centre.world[k], 1e-3) || off(object[k], centre.object[k], 1e-3) || bad;
        const double u = centre.what == Seen::Square ? centre.object[0] + 0.5 : 0.0;
        const double v = centre.what == Seen::Square ? centre.object[1] + 0.5 : 0.0;
        bad = off(uv[0], u, 1e-3) || off(uv[1], v, 1e-3) || bad;
      }
      if (bad && wrong++ < 5)
        ADD_FAILURE() << "pixel (" << x << ", " << y << ") sees " << int(centre.what) << ": position "
                      << image.at(x, y, position[0]) << " " << image.at(x, y, position[1]) << " "
                      << image.at(x, y, position[2]) << ", expected " << centre.world[0] << " "
                      << centre.world[1] << " " << centre.world[2] << "; object " << image.at(x, y, object[0])
                      << " " << image.at(x, y, object[1]) << " " << image.at(x, y, object[2]) << ", expected "
                      << centre.object[0] << " " << centre.object[1] << " " << centre.object[2] << "; uv "
                      << image.at(x, y, uv[0]) << " " << image.at(x, y, uv[1]);
    }
  EXPECT_EQ(wrong, 0);
  // The layout puts each kind in many pixels.
  EXPECT_GT(counted[Seen::Sky], 40);
  EXPECT_GT(counted[Seen::Wall], 300);
  EXPECT_GT(counted[Seen::Square], 150);
  std::printf("worst error / tolerance: %.3f; sky %d, wall %d, square %d pixels\n", worst, counted[0],
              counted[1], counted[2]);
}

}  // namespace
}  // namespace lensrt
