#include "scene/gltf_loader.h"

#include <fmt/core.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "core/ascii_lower.h"
#include "core/error.h"
#include "scene/gltf_accessor.h"
#include "scene/gltf_animation.h"
#include "scene/gltf_context.h"
#include "scene/gltf_lights.h"
#include "scene/gltf_materials.h"
#include "scene/gltf_mesh.h"
#include "scene/gltf_values.h"
#include "scene/scene_file_access.h"
#include "scene/scene_motion.h"
#include "scene/selection_error.h"

namespace lensrt {
namespace {

using gltf::Context;

// tinygltf reports several lines; our errors are one line.
std::string oneLine(const std::string& text) {
  std::string out;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.pop_back();
    if (line.empty()) continue;
    if (!out.empty()) out += "; ";
    out += line;
  }
  return out;
}

std::uint32_t littleEndian32(const unsigned char* b) {
  return b[0] | (b[1] << 8) | (b[2] << 16) | (std::uint32_t{b[3]} << 24);
}

// The .glb layout (12-byte header, JSON chunk, optional BIN chunk), checked
// here because tinygltf says only "Invalid glTF binary." and lets a BIN chunk
// header run 8 bytes past the declared length.
void checkGlbLayout(const std::filesystem::path& file, const std::string& name, std::uint64_t fileSize) {
  std::ifstream in(file, std::ios::binary);
  std::array<unsigned char, 28> b{};
  in.read(reinterpret_cast<char*>(b.data()), b.size());
  const auto got = static_cast<std::size_t>(in.gcount());
  const std::string size = std::to_string(fileSize) + " byte" + (fileSize == 1 ? "" : "s");
  if (got < 20)
    throw InputError(name, "truncated .glb: the file has " + size +
                               ", less than the 12-byte header and the JSON chunk header");
  const std::uint64_t declared = littleEndian32(&b[8]);
  const std::uint64_t jsonLength = littleEndian32(&b[12]);
  const std::uint64_t jsonEnd = 20 + jsonLength;
  if (declared > fileSize)
    throw InputError(name, "truncated .glb: the header declares " + std::to_string(declared) +
                               " bytes but the file has " + size);
  if (littleEndian32(&b[16]) != 0x4E4F534Au)
    throw InputError(name, "broken .glb: the first chunk is not the JSON chunk");
  if (jsonLength == 0) throw InputError(name, "broken .glb: the JSON chunk is empty");
  if (jsonEnd > declared)
    throw InputError(name, "broken .glb: the JSON chunk (" + std::to_string(jsonLength) +
                               " bytes) runs past the declared length of " + std::to_string(declared) +
                               " bytes");
  if (jsonEnd == declared) return;  // no BIN chunk
  if (jsonEnd + 8 > declared)
    throw InputError(name, "broken .glb: " + std::to_string(declared - jsonEnd) +
                               " stray bytes after the JSON chunk (too few for a chunk header)");
  std::array<unsigned char, 8> chunk{};
  in.seekg(static_cast<std::streamoff>(jsonEnd));
  in.read(reinterpret_cast<char*>(chunk.data()), chunk.size());
  if (in.gcount() != 8) throw InputError(name, "truncated .glb: the BIN chunk header is cut off");
  const std::uint64_t binLength = littleEndian32(&chunk[0]);
  if (littleEndian32(&chunk[4]) != 0x004E4942u)
    throw InputError(name, "broken .glb: the chunk after the JSON chunk is not a BIN chunk");
  if (jsonEnd + 8 + binLength > declared)
    throw InputError(name, "truncated .glb: the BIN chunk declares " + std::to_string(binLength) +
                               " bytes but only " + std::to_string(declared - jsonEnd - 8) +
                               " follow it within the declared length");
}

// tinygltf's file access for buffer and image URIs. tinygltf joins the
// decoded URI to the folder we give it, then tries the working directory:
// SceneFileAccess decides what may be read, and the working directory never
// is. A refusal is kept and thrown once tinygltf returns, since tinygltf would
// only say "File not found" (and goes on after an image).
class UriReader {
 public:
  UriReader(const SceneFileAccess& access, Warnings& warnings)
      : access_(access), warnings_(warnings), prefix_(access.folder().string()) {
    if (!prefix_.ends_with('/')) prefix_ += '/';
  }

  const std::string& folder() const { return prefix_; }
  const std::optional<InputError>& refusal() const { return refusal_; }

  tinygltf::FsCallbacks callbacks() {
    return {&UriReader::exists, &UriReader::expand, &UriReader::read, &tinygltf::WriteWholeFile, this};
  }

 private:
  static std::string expand(const std::string& path, void*) { return path; }  // no ~ or $VAR

  static bool exists(const std::string& path, void* self) {
    auto& r = *static_cast<UriReader*>(self);
    if (!path.starts_with(r.prefix_)) return false;  // tinygltf's second try, in the working directory
    const std::string uri = path.substr(r.prefix_.size());
    // A data: URI tinygltf cannot decode (another media type) names no file.
    if (uri.starts_with("data:")) return false;
    try {
      const std::optional<SceneFile> file = r.access_.resolveDecoded(uri);
      if (file) r.checked_.insert_or_assign(path, *file);
      return file.has_value();
    } catch (const InputError& e) {
      if (!r.refusal_) r.refusal_ = e;
      return false;
    }
  }

  static bool read(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* self) {
    auto& r = *static_cast<UriReader*>(self);
    const auto it = r.checked_.find(path);
    if (it == r.checked_.end()) {
      if (err) *err += "not checked\n";
      return false;
    }
    if (it->second.external)
      r.warnings_.warn("reading " + it->second.resolved.string() +
                       ", outside the scene's folder (--allow-external-files)");
    try {
      *out = r.access_.read(it->second);
      return true;
    } catch (const InputError& e) {
      if (err) *err += e.message() + "\n";
      return false;
    }
  }

  const SceneFileAccess& access_;
  Warnings& warnings_;
  std::string prefix_;  // the scene's folder and '/', as tinygltf joins URIs to it
  std::map<std::string, SceneFile> checked_;
  std::optional<InputError> refusal_;
};

std::vector<unsigned char> readSceneFile(const std::filesystem::path& file, const std::string& name,
                                         std::uint64_t fileSize) {
  // tinygltf takes the length as an unsigned int.
  if (fileSize > std::numeric_limits<unsigned int>::max())
    throw InputError(name, "the file is larger than 4 GiB");
  std::vector<unsigned char> bytes(static_cast<std::size_t>(fileSize));
  std::ifstream in(file, std::ios::binary);
  in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (static_cast<std::uint64_t>(in.gcount()) != fileSize) throw InputError(name, "cannot read the file");
  return bytes;
}

// Each data: URI decoded, against the limit. tinygltf has decoded them by now,
// but the text they came from was as large, so the memory is bounded by the
// scene file's size.
void checkDataUris(const tinygltf::Model& model, const std::string& name, const SceneReadLimits& limits) {
  const auto check = [&](const std::string& what, std::size_t bytes) {
    if (bytes > limits.maxDataUriBytes)
      throw InputError(name, what + ": its data: URI decodes to " + std::to_string(bytes) +
                                 " bytes, more than the " + std::to_string(limits.maxDataUriBytes) +
                                 " a data: URI may hold");
  };
  for (std::size_t i = 0; i < model.buffers.size(); ++i)
    if (model.buffers[i].uri.starts_with("data:"))
      check("buffer " + std::to_string(i), model.buffers[i].data.size());
  // deferImageDecoding keeps the bytes of URI images; only external ones keep
  // their URI, and data: URIs of media types tinygltf does not decode
  // (image/webp), which the material loader decodes: their size from the text.
  for (std::size_t i = 0; i < model.images.size(); ++i) {
    const tinygltf::Image& image = model.images[i];
    if (image.as_is && image.uri.empty()) check("image " + std::to_string(i), image.image.size());
    if (!image.as_is && image.uri.starts_with("data:"))
      check("image " + std::to_string(i), (image.uri.size() - image.uri.find(',') - 1) / 4 * 3);
  }
}

// A .gltf is JSON: an object. Anything else (an image, a binary blob, a
// renamed file) gets this line rather than nlohmann's "invalid literal".
void checkLooksLikeJson(const std::filesystem::path& file, const std::string& name) {
  std::ifstream in(file, std::ios::binary);
  std::string head(64, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  std::size_t i = head.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0;  // UTF-8 byte order mark
  while (i < head.size() && std::isspace(static_cast<unsigned char>(head[i]))) ++i;
  if (i < head.size() && head[i] != '{')
    throw InputError(name,
                     "not a glTF file: neither JSON (a .gltf starts with '{') nor binary glTF (a .glb "
                     "starts with 'glTF')");
}

bool isGlb(const std::filesystem::path& file, const std::string& name, std::uint64_t fileSize) {
  std::ifstream in(file, std::ios::binary);
  std::array<unsigned char, 12> header{};
  in.read(reinterpret_cast<char*>(header.data()), header.size());
  const auto got = static_cast<std::size_t>(in.gcount());
  const bool magic = got >= 4 && header[0] == 'g' && header[1] == 'l' && header[2] == 'T' && header[3] == 'F';
  const std::string ext = lowerExtension(file);
  if (!magic) {
    if (ext == ".glb") throw InputError(name, "not a binary glTF: the header does not start with 'glTF'");
    return false;
  }
  if (got < 12) throw InputError(name, "truncated .glb header");
  const std::uint32_t version = littleEndian32(&header[4]);
  if (version != 2)
    throw InputError(name, "unsupported .glb version " + std::to_string(version) + " (expected 2)");
  checkGlbLayout(file, name, fileSize);
  return true;
}

// nlohmann's parse errors read "[json.exception.parse_error.101] parse error at
// line 3, column 7: what"; keep the line for InputError and the rest as text.
[[noreturn]] void throwParseError(const std::string& name, const std::string& fullErr) {
  // nlohmann quotes the last token read, which in a truncated file can be a
  // whole data URI: keep the message short. Parsed by hand: libstdc++'s
  // std::regex recurses per character and overflowed the stack (fuzz_gltf).
  const std::string err = fullErr.size() > 300 ? fullErr.substr(0, 300) + "..." : fullErr;
  const std::string lineKey = "parse error at line ", columnKey = ", column ";
  const std::size_t l = err.find(lineKey);
  if (err.rfind("[json.exception.", 0) == 0 && l != std::string::npos) {
    std::size_t i = l + lineKey.size();
    std::string lineText, columnText;
    while (i < err.size() && std::isdigit(static_cast<unsigned char>(err[i]))) lineText += err[i++];
    if (!lineText.empty() && err.compare(i, columnKey.size(), columnKey) == 0) {
      i += columnKey.size();
      while (i < err.size() && std::isdigit(static_cast<unsigned char>(err[i]))) columnText += err[i++];
      if (!columnText.empty() && err.compare(i, 2, ": ") == 0) {
        const int line = lineText.size() < 9 ? std::stoi(lineText) : 0;
        throw InputError(name, "JSON syntax error at column " + columnText + ": " + err.substr(i + 2), line);
      }
    }
  }
  throw InputError(name, err);
}

tinygltf::Model parse(const std::filesystem::path& file, const std::string& name, Warnings& warnings,
                      const SceneReadLimits& limits) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) throw InputError(name, "file not found");
  if (!std::filesystem::is_regular_file(file, ec)) throw InputError(name, "not a regular file");
  const std::uint64_t fileSize = std::filesystem::file_size(file, ec);
  if (ec) throw InputError(name, "cannot read: " + ec.message());
  if (fileSize == 0) throw InputError(name, "file is empty");
  const bool binary = isGlb(file, name, fileSize);
  if (!binary) checkLooksLikeJson(file, name);
  const SceneFileAccess access(file, limits.allowExternalFiles);
  UriReader uris(access, warnings);
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(gltf::deferImageDecoding, nullptr);
  loader.SetFsCallbacks(uris.callbacks());
  const std::vector<unsigned char> bytes = readSceneFile(file, name, fileSize);
  const auto size = static_cast<unsigned int>(bytes.size());
  tinygltf::Model model;
  std::string err, warn;
  const bool ok =
      binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), size, uris.folder())
             : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
                                          size, uris.folder());
  if (uris.refusal()) throw *uris.refusal();
  // Image problems are reported once, in our words, when a material uses the
  // image (gltf_materials.cpp); drop tinygltf's own lines about them.
  const auto aboutImage = [&](const std::string& line) {
    if (line.find("for image[") != std::string::npos) return true;
    const std::string notFound = "File not found : ";
    if (line.rfind(notFound, 0) != 0) return false;
    // A data: URI of a media type tinygltf does not decode (image/webp),
    // which it took for a file name; the material loader decodes it.
    if (line.compare(notFound.size(), 5, "data:") == 0) return true;
    return std::any_of(model.images.begin(), model.images.end(),
                       [&](const tinygltf::Image& im) { return !im.uri.empty() && line.ends_with(im.uri); });
  };
  std::istringstream lines(warn);
  for (std::string line; std::getline(lines, line);)
    if (!oneLine(line).empty() && !aboutImage(line)) warnings.warn(oneLine(line));
  if (!ok) throwParseError(name, err.empty() ? "cannot parse the glTF file" : oneLine(err));
  checkDataUris(model, name, limits);
  return model;
}

// "major.minor" as the glTF spec writes versions; nullopt for anything else.
std::optional<std::pair<int, int>> parseVersion(const std::string& text) {
  const std::size_t dot = text.find('.');
  if (dot == 0 || dot == std::string::npos || dot + 1 == text.size() || dot > 4 || text.size() - dot > 5)
    return std::nullopt;
  const auto digits = [](std::string_view d) {
    return std::all_of(d.begin(), d.end(),
                       [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
  };
  if (!digits(std::string_view(text).substr(0, dot)) || !digits(std::string_view(text).substr(dot + 1)))
    return std::nullopt;
  return std::pair{std::stoi(text.substr(0, dot)), std::stoi(text.substr(dot + 1))};
}

// glTF 2.0: asset.version must be 2.x, unless asset.minVersion says the file
// needs no more than 2.0 (a later 2.x or 3.x file readable as 2.0).
void checkVersion(const Context& ctx) {
  const tinygltf::Asset& asset = ctx.model.asset;
  if (!asset.minVersion.empty()) {
    const auto min = parseVersion(asset.minVersion);
    if (!min) ctx.fail("asset.minVersion '" + asset.minVersion + "' is not a glTF version (major.minor)");
    if (*min > std::pair{2, 0})
      ctx.fail("glTF minVersion " + asset.minVersion + " is not supported (lensrt reads glTF 2.0)");
    return;
  }
  if (asset.version.empty()) {
    ctx.warnings.warn("asset.version is missing; reading the file as glTF 2.0");
    return;
  }
  const auto version = parseVersion(asset.version);
  if (!version) ctx.fail("asset.version '" + asset.version + "' is not a glTF version (major.minor)");
  if (version->first != 2)
    ctx.fail("glTF version " + asset.version + " is not supported (lensrt reads glTF 2.x)");
}

void checkExtensions(const Context& ctx) {
  for (const std::string& ext : ctx.model.extensionsRequired)
    if (!gltf::isSupportedExtension(ext)) ctx.fail("required extension " + ext + " is not supported");
  for (const std::string& ext : ctx.model.extensionsUsed)
    if (!gltf::isSupportedExtension(ext)) ctx.warnUnsupportedExtension(ext);
}

Transform trs(const Context& ctx, const std::string& label, const std::vector<double>& t,
              const std::vector<double>& r, const std::vector<double>& s) {
  if ((!t.empty() && t.size() != 3) || (!r.empty() && r.size() != 4) || (!s.empty() && s.size() != 3))
    ctx.fail(label + ": translation/rotation/scale have the wrong number of values");
  Transform x;
  if (!t.empty()) x = Transform::translate({t[0], t[1], t[2]});
  if (!r.empty()) x = x * Transform::rotateQuaternion(r[0], r[1], r[2], r[3]);
  if (!s.empty()) x = x * Transform::scale({s[0], s[1], s[2]});
  return x;
}

bool finite(const Transform& t) {
  for (const auto& row : t.matrix())
    for (const double v : row)
      if (!std::isfinite(v)) return false;
  return true;
}

// The node's own transform, or with the animation's values in place of its
// translation, rotation and scale where it sets them.
Transform localTransform(const Context& ctx, int index, const tinygltf::Node& node,
                         const gltf::AnimatedTrs* animated) {
  const std::string label = "node " + std::to_string(index);
  Transform local;
  if (animated && (animated->translation || animated->rotation || animated->scale)) {
    std::vector<double> t = node.translation, r = node.rotation, sc = node.scale;
    if (animated->translation) t.assign(animated->translation->begin(), animated->translation->end());
    if (animated->rotation) r.assign(animated->rotation->begin(), animated->rotation->end());
    if (animated->scale) sc.assign(animated->scale->begin(), animated->scale->end());
    local = trs(ctx, label, t, r, sc);
  } else if (!node.matrix.empty()) {
    if (node.matrix.size() != 16) ctx.fail(label + ": matrix needs 16 values");
    // glTF node matrices are affine (decomposable into T * R * S): a
    // projective last row has no meaning here and no usable inverse.
    const std::vector<double>& m = node.matrix;
    if (m[3] != 0.0 || m[7] != 0.0 || m[11] != 0.0 || m[15] != 1.0)
      ctx.fail(label + ": matrix is not affine (its last row must be 0 0 0 1)");
    local = Transform::fromColumnMajor(node.matrix.data());
  } else {
    local = trs(ctx, label, node.translation, node.rotation, node.scale);
  }
  if (!finite(local)) ctx.fail(label + ": transform is not finite");
  return local;
}

// The camera's rigid frame: glTF cameras look down local -Z with +Y up; scale
// in the node transform would only distort the renderer's rays, so drop it.
Transform cameraFrame(const Transform& world) {
  const Vec3d eye = world.point(Vec3d(0, 0, 0));
  const Vec3d forward = world.vector(Vec3d(0, 0, -1));
  const Vec3d up = world.vector(Vec3d(0, 1, 0));
  if (!(length(forward) > 0) || !(length(up) > 0)) return Transform::translate(eye);
  return Transform::lookAt(eye, eye + normalize(forward), normalize(up));
}

class Traversal {
 public:
  Traversal(const Context& ctx, SceneDesc& desc, const std::map<int, gltf::AnimatedTrs>& animated)
      : ctx_(ctx), desc_(desc), animated_(animated) {}

  enum class Visit { All, WorldsOnly };
  void run(const std::vector<int>& roots, Visit mode = Visit::All) {
    struct Item {
      int node;
      Transform parent;
    };
    std::vector<Item> stack;
    // Reverse so that the depth-first order (and the camera order) follows the file.
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back({*it, Transform()});
    std::vector<bool> visited(ctx_.model.nodes.size(), false);
    std::vector<int> order;
    while (!stack.empty()) {
      const Item item = std::move(stack.back());
      stack.pop_back();
      if (item.node < 0 || static_cast<std::size_t>(item.node) >= ctx_.model.nodes.size())
        ctx_.fail("node " + std::to_string(item.node) + " does not exist");
      if (visited[static_cast<std::size_t>(item.node)])
        ctx_.fail("node " + std::to_string(item.node) +
                  " is reached twice (a cycle or a shared child; glTF nodes must form trees)");
      visited[static_cast<std::size_t>(item.node)] = true;
      const tinygltf::Node& node = ctx_.model.nodes[static_cast<std::size_t>(item.node)];
      const auto pose = animated_.find(item.node);
      const Transform world = item.parent * localTransform(ctx_, item.node, node,
                                                           pose == animated_.end() ? nullptr : &pose->second);
      if (!finite(world)) ctx_.fail("node " + std::to_string(item.node) + ": world transform is not finite");
      order.push_back(item.node);
      worlds_.emplace(item.node, world);
      for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) stack.push_back({*it, world});
    }
    if (mode == Visit::WorldsOnly) return;
    desc_.nodeNames.clear();
    for (std::size_t i = 0; i < ctx_.model.nodes.size(); ++i)
      desc_.nodeNames.push_back(ctx_.model.nodes[i].name.empty() ? "node" + std::to_string(i)
                                                                 : ctx_.model.nodes[i].name);
    // Every node's world transform first: a skin needs its joints' wherever
    // they sit in the tree.
    for (const int index : order)
      visit(index, ctx_.model.nodes[static_cast<std::size_t>(index)], worlds_.at(index));
  }

  const gltf::MeshStats& stats() const { return stats_; }
  // Every node's world transform, posed.
  const std::map<int, Transform>& worlds() const { return worlds_; }

 private:
  void visit(int index, const tinygltf::Node& node, const Transform& world) {
    for (const auto& [name, value] : node.extensions)
      if (!gltf::isSupportedExtension(name)) ctx_.warnUnsupportedExtension(name);
    if (node.mesh >= 0) placeMesh(index, node, world);
    if (node.camera >= 0) addCamera(index, node, world);
    if (const tinygltf::Value* ext = gltf::extension(node.extensions, "KHR_lights_punctual")) {
      const std::optional<double> light = gltf::numberMember(*ext, "light");
      if (!light) ctx_.fail("node " + std::to_string(index) + ": KHR_lights_punctual without a light index");
      if (!gltf::isIndex(*light))
        ctx_.fail("node " + std::to_string(index) + ": KHR_lights_punctual light " +
                  gltf::numberText(*light) + " is not an index");
      if (auto l = gltf::convertLight(ctx_, static_cast<int>(*light), world)) desc_.lights.push_back(*l);
    }
  }

  void placeMesh(int index, const tinygltf::Node& node, const Transform& world) {
    // A mesh is converted once per set of morph weights its nodes give it
    // (the animation's at this time, the node's, or the mesh's own).
    const auto pose = animated_.find(index);
    std::vector<double> weights = pose != animated_.end() && pose->second.weights
                                      ? *pose->second.weights
                                      : gltf::morphWeights(ctx_, node, node.mesh);
    if (std::all_of(weights.begin(), weights.end(), [](double w) { return w == 0.0; })) weights.clear();
    if (node.skin >= 0) {
      // Skinned vertices are blended into world space by the joints; the
      // node's own transform does not apply (glTF 2.0 3.7.3).
      const std::vector<Transform::Matrix> joints = jointMatrices(index, node.skin);
      for (const int mesh : gltf::convertMesh(ctx_, node.mesh, desc_.meshes, stats_, weights, &joints))
        desc_.instances.push_back({.mesh = mesh, .worldFromObject = Transform(), .node = index});
      return;
    }
    auto [it, inserted] = meshes_.try_emplace(std::pair{node.mesh, weights});
    if (inserted) it->second = gltf::convertMesh(ctx_, node.mesh, desc_.meshes, stats_, weights);
    std::vector<Transform> placements;
    if (const tinygltf::Value* ext = gltf::extension(node.extensions, "EXT_mesh_gpu_instancing"))
      placements = gpuInstances(index, *ext, world);
    else
      placements.push_back(world);
    for (const Transform& xf : placements)
      for (const int mesh : it->second)
        desc_.instances.push_back({.mesh = mesh, .worldFromObject = xf, .node = index});
  }

  // Each joint's world transform times its inverse bind matrix.
  std::vector<Transform::Matrix> jointMatrices(int index, int skinIndex) {
    const std::string label = "node " + std::to_string(index) + " skin " + std::to_string(skinIndex);
    if (static_cast<std::size_t>(skinIndex) >= ctx_.model.skins.size()) ctx_.fail(label + " does not exist");
    const tinygltf::Skin& skin = ctx_.model.skins[static_cast<std::size_t>(skinIndex)];
    std::vector<float> inverseBind;
    if (skin.inverseBindMatrices >= 0) {
      inverseBind =
          gltf::readFloats(ctx_, skin.inverseBindMatrices, 16, (label + " inverseBindMatrices").c_str());
      if (inverseBind.size() != 16 * skin.joints.size())
        ctx_.fail(label + ": inverseBindMatrices has " + std::to_string(inverseBind.size() / 16) +
                  " matrices for " + std::to_string(skin.joints.size()) + " joints");
    }
    std::vector<Transform::Matrix> joints;
    for (std::size_t j = 0; j < skin.joints.size(); ++j) {
      const auto world = worlds_.find(skin.joints[j]);
      if (world == worlds_.end())
        ctx_.fail(label + ": joint " + std::to_string(skin.joints[j]) + " is not a node of the scene");
      Transform bind;
      if (!inverseBind.empty()) {
        std::array<double, 16> m{};
        for (std::size_t k = 0; k < 16; ++k) m[k] = inverseBind[16 * j + k];
        bind = Transform::fromColumnMajor(m.data());
      }
      const Transform joint = world->second * bind;
      if (!finite(joint)) ctx_.fail(label + ": joint " + std::to_string(j) + "'s matrix is not finite");
      joints.push_back(joint.matrix());
    }
    return joints;
  }

  // EXT_mesh_gpu_instancing: each instance is world * T * R * S from its attributes.
  std::vector<Transform> gpuInstances(int index, const tinygltf::Value& ext, const Transform& world) {
    const std::string label = "node " + std::to_string(index) + " EXT_mesh_gpu_instancing";
    const tinygltf::Value* attributes = gltf::member(ext, "attributes");
    if (!attributes || !attributes->IsObject()) ctx_.fail(label + ": no attributes");
    const auto read = [&](const char* name, int components) -> std::vector<float> {
      const std::optional<double> accessor = gltf::numberMember(*attributes, name);
      if (!accessor) return {};
      if (!gltf::isIndex(*accessor))
        ctx_.fail(label + " " + name + ": accessor " + gltf::numberText(*accessor) + " is not an index");
      return gltf::readFloats(ctx_, static_cast<int>(*accessor), components, (label + " " + name).c_str());
    };
    const std::vector<float> t = read("TRANSLATION", 3), r = read("ROTATION", 4), s = read("SCALE", 3);
    std::size_t count = 0;
    for (const auto& [v, n] : {std::pair{&t, 3}, std::pair{&r, 4}, std::pair{&s, 3}}) {
      if (v->empty()) continue;
      const std::size_t c = v->size() / static_cast<std::size_t>(n);
      if (count != 0 && c != count) ctx_.fail(label + ": attributes have different counts");
      count = c;
    }
    if (count == 0) ctx_.warnings.warn(label + ": no instances");
    std::vector<Transform> out;
    out.reserve(count);
    for (std::size_t k = 0; k < count; ++k) {
      const auto slice = [&](const std::vector<float>& v, int n) {
        return v.empty() ? std::vector<double>{}
                         : std::vector<double>(v.begin() + static_cast<long>(k * n),
                                               v.begin() + static_cast<long>((k + 1) * n));
      };
      const Transform xf = world * trs(ctx_, label, slice(t, 3), slice(r, 4), slice(s, 3));
      if (!finite(xf)) ctx_.fail(label + ": instance transform is not finite");
      out.push_back(xf);
    }
    return out;
  }

  void addCamera(int index, const tinygltf::Node& node, const Transform& world) {
    if (static_cast<std::size_t>(node.camera) >= ctx_.model.cameras.size())
      ctx_.fail("node " + std::to_string(index) + ": camera " + std::to_string(node.camera) +
                " does not exist");
    const tinygltf::Camera& gc = ctx_.model.cameras[static_cast<std::size_t>(node.camera)];
    CameraDesc cam;
    cam.cameraName = gc.name;
    cam.name =
        !node.name.empty() ? node.name : (!gc.name.empty() ? gc.name : "node " + std::to_string(index));
    cam.node = index;
    cam.worldFromCamera = cameraFrame(world);
    // Embree takes no ray starting beyond 1.8e18; the geometry's own limit applies.
    const Vec3d eye = cam.worldFromCamera.point(Vec3d(0, 0, 0));
    if (!(std::abs(eye.x) <= gltf::kMaxCoordinate && std::abs(eye.y) <= gltf::kMaxCoordinate &&
          std::abs(eye.z) <= gltf::kMaxCoordinate))
      ctx_.fail("camera '" + cam.name + "' (node " + std::to_string(index) +
                ") is placed beyond 1e15 (check the node transforms)");
    if (gc.type == "orthographic") {
      const tinygltf::OrthographicCamera& o = gc.orthographic;
      // glTF: xmag and ymag must not be zero (a negative one mirrors nothing
      // here); both and their ratio must be usable floats.
      const float xmag = static_cast<float>(std::abs(o.xmag)), ymag = static_cast<float>(std::abs(o.ymag));
      const float aspect = xmag / ymag;
      if (xmag > 0 && ymag > 0 && xmag < gltf::kMaxCoordinate && ymag < gltf::kMaxCoordinate && aspect > 0 &&
          std::isfinite(aspect)) {
        cam.orthographic = true;
        cam.xmag = xmag;
        cam.ymag = ymag;
        cam.aspectRatio = aspect;
      } else {
        ctx_.warnings.warn("camera '" + cam.name +
                           "': orthographic xmag and ymag must be non-zero; rendering it as a perspective "
                           "camera (yfov 39.6 degrees)");
      }
    } else {
      const tinygltf::PerspectiveCamera& p = gc.perspective;
      if (p.yfov > 0 && p.yfov < kPi)
        cam.yfov = static_cast<float>(p.yfov);
      else
        ctx_.warnings.warn("camera '" + cam.name + "': yfov out of range, using 39.6 degrees");
      if (p.aspectRatio > 0 && std::isfinite(p.aspectRatio))
        cam.aspectRatio = static_cast<float>(p.aspectRatio);
      if (p.znear > 0 && std::isfinite(p.znear)) cam.znear = static_cast<float>(p.znear);
    }
    desc_.cameras.push_back(std::move(cam));
  }

  const Context& ctx_;
  SceneDesc& desc_;
  const std::map<int, gltf::AnimatedTrs>& animated_;
  std::map<int, Transform> worlds_;  // every node of the scene, posed
  std::map<std::pair<int, std::vector<double>>, std::vector<int>>
      meshes_;  // glTF mesh -> desc meshes (one per primitive)
  gltf::MeshStats stats_;
};

std::vector<int> sceneRoots(const Context& ctx, int sceneIndex) {
  const auto& scenes = ctx.model.scenes;
  if (sceneIndex >= 0 && static_cast<std::size_t>(sceneIndex) >= scenes.size())
    throw SelectionError(ctx.file, "scene index " + std::to_string(sceneIndex) +
                                       " out of range (the file has " + std::to_string(scenes.size()) +
                                       " scene" + (scenes.size() == 1 ? "" : "s") + ")");
  if (sceneIndex < 0) {
    if (ctx.model.defaultScene >= 0 && static_cast<std::size_t>(ctx.model.defaultScene) < scenes.size())
      sceneIndex = ctx.model.defaultScene;
    else if (!scenes.empty())
      sceneIndex = 0;
  }
  if (sceneIndex >= 0) return scenes[static_cast<std::size_t>(sceneIndex)].nodes;
  // No scenes at all: render every node that is nobody's child.
  ctx.warnings.warn("the file defines no scene: rendering all root nodes");
  std::vector<bool> isChild(ctx.model.nodes.size(), false);
  for (const tinygltf::Node& n : ctx.model.nodes)
    for (const int c : n.children)
      if (c >= 0 && static_cast<std::size_t>(c) < isChild.size()) isChild[static_cast<std::size_t>(c)] = true;
  std::vector<int> roots;
  for (std::size_t i = 0; i < isChild.size(); ++i)
    if (!isChild[i]) roots.push_back(static_cast<int>(i));
  return roots;
}

void checkRenderable(const Context& ctx, const SceneDesc& desc, const gltf::MeshStats& stats) {
  if (stats.degenerateTriangles > 0)
    ctx.warnings.warn(std::to_string(stats.degenerateTriangles) +
                      " degenerate (zero-area) triangles dropped");
  // A camera looking at nothing but the environment is a flat-field test of
  // the lens (vignetting): render it.
  if (desc.instances.empty() && !desc.cameras.empty()) {
    ctx.warnings.warn("the scene has no meshes: rendering the environment only");
    return;
  }
  if (ctx.model.meshes.empty()) ctx.fail("nothing to render: the file has no meshes");
  if (desc.instances.empty()) {
    if (stats.degenerateTriangles > 0 && stats.triangles == 0)
      ctx.fail("nothing to render: all triangles are degenerate");
    ctx.fail("nothing to render: the scene places no triangle meshes");
  }
  const Bounds3f b = desc.worldBounds();
  for (int a = 0; a < 3; ++a)
    if (!std::isfinite(b.lo[a]) || !std::isfinite(b.hi[a]) || std::abs(b.lo[a]) > gltf::kMaxCoordinate ||
        std::abs(b.hi[a]) > gltf::kMaxCoordinate)
      ctx.fail("world-space coordinates beyond 1e15 (check the node transforms)");
}

// The scene's meshes, instances, lights and cameras posed at `time` (no
// materials).
SceneDesc poseAt(const Context& ctx, const std::vector<int>& roots, const AnimationTime& time) {
  SceneDesc desc;
  const std::map<int, gltf::AnimatedTrs> animated = gltf::animatedNodes(ctx, time);
  Traversal traversal(ctx, desc, animated);
  traversal.run(roots);
  return desc;
}

// Every node's world transform at `time`, nothing converted.
std::map<int, Transform> worldsAt(const Context& ctx, const std::vector<int>& roots,
                                  const AnimationTime& time) {
  SceneDesc unused;
  const std::map<int, gltf::AnimatedTrs> animated = gltf::animatedNodes(ctx, time);
  Traversal traversal(ctx, unused, animated);
  traversal.run(roots, Traversal::Visit::WorldsOnly);
  return traversal.worlds();
}

// Motion blur over time.spanSeconds: probe the node worlds at evenly spaced
// moments for how many time steps the span needs, then pose the scene at
// them. `opening`: the worlds at the span's start, which the caller has.
void addAnimationMotion(const Context& ctx, const std::vector<int>& roots, const AnimationTime& time,
                        std::map<int, Transform> opening, SceneDesc& desc) {
  constexpr int kProbeIntervals = 8;
  const auto at = [&](int step, int steps) {
    AnimationTime t = time;
    t.seconds = time.seconds + time.spanSeconds * double(step) / double(steps - 1);
    t.spanSeconds = 0;
    return t;
  };
  std::vector<std::map<int, Transform>> probeWorlds{std::move(opening)};
  for (int k = 1; k <= kProbeIntervals; ++k)
    probeWorlds.push_back(worldsAt(ctx, roots, at(k, kProbeIntervals + 1)));
  const int steps = motionStepCount(probeWorlds);
  std::vector<SceneDesc> poses;
  for (int k = 1; k < steps; ++k) poses.push_back(poseAt(ctx, roots, at(k, steps)));
  addMotion(desc, poses, ctx.warnings);
}

}  // namespace

struct GltfLoader::Impl {
  std::string name;
  SceneReadLimits limits;
  Warnings& warnings;
  tinygltf::Model model;
  Context ctx;
  std::vector<int> roots;
  bool stillNoticed = false;  // the notice of a moment asked of a file without animation, once

  Impl(const std::filesystem::path& file, int sceneIndex, Warnings& w, const SceneReadLimits& readLimits)
      : name(file.string()),
        limits(readLimits),
        warnings(w),
        model(parse(file, name, w, limits)),
        ctx{model, name, w, limits} {
    checkVersion(ctx);
    checkExtensions(ctx);
    roots = sceneRoots(ctx, sceneIndex);
  }
};

GltfLoader::GltfLoader(const std::filesystem::path& file, int sceneIndex, Warnings& warnings,
                       const SceneReadLimits& limits)
    : impl_(std::make_unique<Impl>(file, sceneIndex, warnings, limits)) {}

GltfLoader::~GltfLoader() = default;

SceneDesc GltfLoader::load(const AnimationTime& time, SceneDesc* previous) {
  const Context& ctx = impl_->ctx;
  const tinygltf::Model& model = impl_->model;
  SceneDesc desc;
  desc.sourceFile = impl_->name;
  if (previous) {
    desc.materials = std::move(previous->materials);
    desc.textures = std::move(previous->textures);
  } else {
    gltf::loadMaterials(ctx, desc);
  }
  const std::map<int, gltf::AnimatedTrs> animated = gltf::animatedNodes(ctx, time);
  if (model.animations.empty() && time.seconds != 0 && !impl_->stillNoticed) {
    impl_->stillNoticed = true;
    impl_->warnings.warn(
        fmt::format("at {:g} s: the file has no animation, so it renders as it is at rest, at every moment",
                    time.seconds));
  }
  if (!model.animations.empty())
    desc.pose =
        fmt::format("time={:g} animation={}{}", time.seconds, time.animation.empty() ? "all" : time.animation,
                    time.spanSeconds > 0 ? fmt::format(" span={:g}", time.spanSeconds) : "");
  Traversal traversal(ctx, desc, animated);
  traversal.run(impl_->roots);
  checkRenderable(ctx, desc, traversal.stats());
  if (time.spanSeconds > 0 && !model.animations.empty())
    addAnimationMotion(ctx, impl_->roots, time, traversal.worlds(), desc);
  return desc;
}

SceneDesc loadGltf(const std::filesystem::path& file, int sceneIndex, Warnings& warnings,
                   const SceneReadLimits& limits, const AnimationTime& time) {
  return GltfLoader(file, sceneIndex, warnings, limits).load(time);
}

}  // namespace lensrt
