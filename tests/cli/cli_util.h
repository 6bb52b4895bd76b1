// Runs the built `lensrt` binary as a child process and captures its output.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace lensrt::cli {

struct RunResult {
  int status = -1;  // exit status, or 128 + signal number
  std::string out;
  std::string err;
};

RunResult runLensrt(const std::vector<std::string>& args);
// Any program, found on the PATH (dcraw, raw-identify).
RunResult runProgram(const std::string& program, const std::vector<std::string>& args);

// A fresh empty directory for the current test, removed by the destructor.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

std::string readFile(const std::filesystem::path& file);
void writeFile(const std::filesystem::path& file, const std::string& contents);
std::vector<std::string> lines(const std::string& text);

// Standard base64 with padding, for data: URIs.
std::string base64(const std::string& bytes);

// A glTF of quads (two triangles each, one mesh per quad) with a data: URI
// buffer, one perspective camera and, optionally, one KHR_lights_punctual
// light (1 m above the origin unless placed elsewhere).
struct Quad {
  float corners[4][3];  // counterclockwise seen from the front
  int material;         // index into the materials
};
struct QuadScene {
  std::vector<Quad> quads;
  std::string materials;  // glTF material objects, comma-separated
  std::string light;      // a KHR_lights_punctual light object, or none
  // The light node's placement (a spot shines down its local -Z).
  std::string lightPlacement = R"("translation":[0,1,0])";
  // The camera node's placement: 2 m above the origin looking straight down.
  std::string cameraPlacement = R"("translation":[0,2,0],"rotation":[-0.707106781,0,0,0.707106781])";
  double yfov = 0.5;  // radians
};
std::string quadsGltf(const QuadScene& scene);

// A one-triangle glTF with its buffer as a data URI. `bufferBytes` < 44 cuts
// the buffer short.
std::string triangleGltf(const float (&positions)[9], const unsigned short (&indices)[3],
                         int bufferBytes = 44);

// A camera (yfov 0.7 rad) at the origin and nothing else: under a constant
// sky, a flat field.
inline constexpr const char* kSkyOnlyGltf =
    R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],)"
    R"("cameras":[{"type":"perspective","perspective":{"yfov":0.7,"znear":0.1}}],)"
    R"("nodes":[{"name":"flat field","camera":0}]})";

}  // namespace lensrt::cli
