#include "render_test_util.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cmath>
#include <cstring>
#include <stdexcept>

#include "render/integrator.h"
#include "render/lights.h"
#include "render/material_eval.h"
#include "render/renderer.h"
#include "scene/render_scene.h"

extern char** environ;

namespace lensrt::test {

SceneDesc rectangleScene(float x0, float x1, float y0, float y1, float distance, float emission) {
  SceneDesc s;
  s.sourceFile = "camera render test (in code)";
  Mesh m;
  m.name = "rectangle";
  const float z = -distance;
  m.positions = {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}};
  m.indices = {0, 1, 2, 0, 2, 3};  // counter-clockwise seen from +Z (the camera)
  m.material = 0;
  s.meshes.push_back(std::move(m));
  Material mat;
  mat.baseColor = {0, 0, 0, 1};
  mat.metallic = 0;
  mat.emissive = {emission, emission, emission};
  mat.doubleSided = true;
  s.materials.push_back(mat);
  s.instances.push_back({0, Transform()});
  return s;
}

SceneDesc squareScene(float distance, float size, float emission) {
  const float h = size / 2;
  return rectangleScene(-h, h, -h, h, distance, emission);
}

RenderedImage renderScene(SceneDesc desc, const Camera& camera, const Environment& env, int spp,
                          bool variance) {
  const RenderScene scene(std::move(desc));
  const MaterialTable materials(scene.desc());
  const LightSet lights(materials, env, scene.bounds());
  IntegratorSettings is;
  is.maxDepth = 1;
  const Integrator integrator(scene, materials, lights, env, is);
  RenderSettings rs;
  rs.samplesPerPixel = spp;
  rs.seed = 3;
  rs.aovs.variance = variance;
  RenderedImage out{renderImage(camera, integrator, rs).image};
  out.red = out.image.channelIndex("R");
  if (variance) out.varianceR = out.image.channelIndex("variance.R");
  return out;
}

Centroid centroid(const Image& img, const char* channel) {
  const int c = img.channelIndex(channel);
  double sum = 0, sx = 0, sy = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const double v = img.at(x, y, c);
      sum += v;
      sx += v * (img.originX + x + 0.5);
      sy += v * (img.originY + y + 0.5);
    }
  return {sx / sum, sy / sum};
}

std::vector<double> columnProfile(const RenderedImage& img) {
  const int w = img.image.width, h = img.image.height;
  std::vector<double> profile(w, 0.0);
  for (int x = 0; x < w; ++x) {
    for (int y = 0; y < h; ++y) profile[x] += img.image.at(x, y, img.red);
    profile[x] /= h;
  }
  return profile;
}

double riseWidth(const std::vector<double>& p, double lo, double hi) {
  const int n = static_cast<int>(p.size());
  // Pixel i's centre is at i + 0.5.
  double xLo = 0.0, xHi = n;
  for (int i = 0; i + 1 < n; ++i)
    if (p[i] < lo && p[i + 1] >= lo) {
      xLo = i + 0.5 + (lo - p[i]) / (p[i + 1] - p[i]);
      break;
    }
  for (int i = n - 2; i >= 0; --i)
    if (p[i] < hi && p[i + 1] >= hi) {
      xHi = i + 0.5 + (hi - p[i]) / (p[i + 1] - p[i]);
      break;
    }
  return xHi - xLo;
}

double diskEdgeSpread(double u) {
  if (u <= -1.0) return 0.0;
  if (u >= 1.0) return 1.0;
  return 0.5 + (u * std::sqrt(1.0 - u * u) + std::asin(u)) / M_PI;
}

int runLensrt(const std::vector<std::string>& args, const std::string& log) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  std::vector<std::string> argvStrings{LENSRT_BINARY};
  argvStrings.insert(argvStrings.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& s : argvStrings) argv.push_back(s.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, LENSRT_BINARY, &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw std::runtime_error(std::string("cannot run lensrt: ") + std::strerror(rc));
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace lensrt::test
