#include "cli/cli_util.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

extern char** environ;

namespace lensrt::cli {

namespace {
std::atomic<int> counter{0};
}

RunResult runLensrt(const std::vector<std::string>& args) {
  return runProgram(LENSRT_BINARY, args);
}

RunResult runProgram(const std::string& program, const std::vector<std::string>& args) {
  const TempDir io;
  const std::string outPath = (io / "stdout").string(), errPath = (io / "stderr").string();
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<std::string> argvStrings{program};
  argvStrings.insert(argvStrings.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& s : argvStrings) argv.push_back(s.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int rc = posix_spawnp(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw std::runtime_error("cannot run " + program + ": " + std::strerror(rc));
  int wstatus = 0;
  waitpid(pid, &wstatus, 0);
  RunResult r;
  r.status = WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : 128 + WTERMSIG(wstatus);
  r.out = readFile(outPath);
  r.err = readFile(errPath);
  return r;
}

TempDir::TempDir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string name = info ? std::string(info->test_suite_name()) + "." + info->name() : "lensrt";
  path_ = std::filesystem::temp_directory_path() /
          ("lensrt_cli_" + name + "_" + std::to_string(getpid()) + "_" + std::to_string(counter++));
  std::filesystem::remove_all(path_);
  std::filesystem::create_directories(path_);
}

TempDir::~TempDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

std::string readFile(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void writeFile(const std::filesystem::path& file, const std::string& contents) {
  std::ofstream out(file, std::ios::binary);
  out << contents;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> result;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) result.push_back(line);
  return result;
}

std::string base64(const std::string& bytes) {
  static const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const unsigned b0 = static_cast<unsigned char>(bytes[i]);
    const unsigned b1 = i + 1 < bytes.size() ? static_cast<unsigned char>(bytes[i + 1]) : 0;
    const unsigned b2 = i + 2 < bytes.size() ? static_cast<unsigned char>(bytes[i + 2]) : 0;
    const unsigned v = (b0 << 16) | (b1 << 8) | b2;
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? kAlphabet[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kAlphabet[v & 63] : '=';
  }
  return out;
}

std::string triangleGltf(const float (&positions)[9], const unsigned short (&indices)[3], int bufferBytes) {
  std::string data(44, '\0');
  std::memcpy(data.data(), positions, 36);
  std::memcpy(data.data() + 36, indices, 6);
  data.resize(std::size_t(bufferBytes));
  return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
         R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],)"
         R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
         R"("min":[-1,-1,-1],"max":[1,1,1]},{"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"}],)"
         R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":6}],)"
         R"("buffers":[{"byteLength":)" +
         std::to_string(bufferBytes) + R"(,"uri":"data:application/octet-stream;base64,)" + base64(data) +
         R"("}]})";
}

std::string quadsGltf(const QuadScene& scene) {
  const std::vector<Quad>& quads = scene.quads;
  std::string data, meshes, accessors, views, nodes, sceneNodes;
  for (std::size_t q = 0; q < quads.size(); ++q) {
    const std::size_t offset = data.size();
    float lo[3] = {1e30f, 1e30f, 1e30f}, hi[3] = {-1e30f, -1e30f, -1e30f};
    for (const auto& c : quads[q].corners)
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], c[k]), hi[k] = std::max(hi[k], c[k]);
    data.append(reinterpret_cast<const char*>(quads[q].corners), sizeof quads[q].corners);
    const unsigned short indices[6] = {0, 1, 2, 0, 2, 3};
    data.append(reinterpret_cast<const char*>(indices), sizeof indices);
    data.append(4, '\0');  // keep the next quad's floats 4-byte aligned
    const std::string i = std::to_string(q);
    const auto sep = [&](std::string& s) { s += s.empty() ? "" : ","; };
    sep(views);
    views += R"({"buffer":0,"byteOffset":)" + std::to_string(offset) + R"(,"byteLength":48},)" +
             R"({"buffer":0,"byteOffset":)" + std::to_string(offset + 48) + R"(,"byteLength":12})";
    sep(accessors);
    accessors += R"({"bufferView":)" + std::to_string(2 * q) +
                 R"(,"componentType":5126,"count":4,"type":"VEC3",)" + R"("min":[)" + std::to_string(lo[0]) +
                 "," + std::to_string(lo[1]) + "," + std::to_string(lo[2]) + R"(],"max":[)" +
                 std::to_string(hi[0]) + "," + std::to_string(hi[1]) + "," + std::to_string(hi[2]) +
                 R"(]},)" + R"({"bufferView":)" + std::to_string(2 * q + 1) +
                 R"(,"componentType":5123,"count":6,"type":"SCALAR"})";
    sep(meshes);
    meshes += R"({"primitives":[{"attributes":{"POSITION":)" + std::to_string(2 * q) + R"(},"indices":)" +
              std::to_string(2 * q + 1) + R"(,"material":)" + std::to_string(quads[q].material) + "}]}";
    sep(nodes);
    nodes += R"({"mesh":)" + i + "}";
    sep(sceneNodes);
    sceneNodes += i;
  }
  nodes += R"(,{"camera":0,)";
  nodes += scene.cameraPlacement;
  nodes += "}";
  sceneNodes += ",";
  sceneNodes += std::to_string(quads.size());
  std::string extensions;
  if (!scene.light.empty()) {
    nodes += ",{" + scene.lightPlacement + R"(,"extensions":{"KHR_lights_punctual":{"light":0}}})";
    sceneNodes += ",";
    sceneNodes += std::to_string(quads.size() + 1);
    extensions =
        R"("extensionsUsed":["KHR_lights_punctual"],"extensions":{"KHR_lights_punctual":{"lights":[)" +
        scene.light + "]}},";
  }
  return R"({"asset":{"version":"2.0"},)" + extensions + R"("scene":0,"scenes":[{"nodes":[)" + sceneNodes +
         R"(]}],"cameras":[{"type":"perspective","perspective":{"yfov":)" + std::to_string(scene.yfov) +
         R"(,"znear":0.001}}],"nodes":[)" + nodes + R"(],"meshes":[)" + meshes + R"(],"materials":[)" +
         scene.materials + R"(],"accessors":[)" + accessors + R"(],"bufferViews":[)" + views +
         R"(],"buffers":[{"byteLength":)" + std::to_string(data.size()) +
         R"(,"uri":"data:application/octet-stream;base64,)" + base64(data) + R"("}]})";
}

}  // namespace lensrt::cli
