#include "scene/gltf_materials.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <utility>
#include <variant>
#include <vector>

#include "core/constants.h"
#include "image/png_allocation.h"
#include "scene/data_uri.h"
#include "scene/gltf_values.h"
#include "image/texture_decoding.h"

namespace lensrt::gltf {
namespace {

// Textures are held as 4 floats per texel: 128 Mtexels is 2 GiB, beyond any
// real asset. A 1 MB PNG of zeros declaring 16000x16000 took 5 GB.
constexpr int kMaxMegatexels = 128;
constexpr double kMaxTexels = kMaxMegatexels * 1048576.0;

// Textures are held as 4 floats a texel.
std::uint64_t texelBytes(std::uint64_t width, std::uint64_t height) {
  return width * height * sizeof(Vec4f);
}

std::string bytesText(std::uint64_t bytes) {
  constexpr std::uint64_t kMiB = 1 << 20;
  if (bytes < kMiB) return std::to_string(bytes) + " bytes";
  return std::to_string((bytes + kMiB - 1) / kMiB) + " MiB";
}

// "#3": an unnamed material or image. Appended, not "#" + std::string:
// GCC 12 warns falsely about that once inlined (bug 105329).
std::string indexName(std::size_t index) {
  std::string name = "#";
  name += std::to_string(index);
  return name;
}

class TextureLoader {
 public:
  TextureLoader(const Context& ctx, SceneDesc& desc) : ctx_(ctx), desc_(desc) {}

  // TextureRef for a material slot (a glTF textureInfo: index, texCoord and
  // its extensions), or none (with a warning) when unusable.
  TextureRef ref(int textureIndex, int texCoord, const tinygltf::ExtensionMap& extensions, bool srgb,
                 const std::string& material, const char* slot) {
    if (textureIndex < 0) return {};
    const std::string where = "material '" + material + "' " + slot;
    TextureRef out;
    out.texCoord = texCoord;
    if (const tinygltf::Value* ext = extension(extensions, "KHR_texture_transform"))
      out.transform = textureTransform(*ext, where, out.texCoord);
    if (out.texCoord < 0 || out.texCoord > 1) {
      ctx_.warnings.warn(where + ": texCoord " + std::to_string(out.texCoord) +
                         " is not supported (only TEXCOORD_0 and TEXCOORD_1); using the factor only");
      return {};
    }
    const auto key = std::make_pair(textureIndex, srgb);
    auto it = cache_.find(key);
    if (it == cache_.end()) {
      std::optional<Texture> tex = load(textureIndex, srgb, material);
      const int index = tex ? static_cast<int>(desc_.textures.size()) : -1;
      if (tex) desc_.textures.push_back(std::move(*tex));
      it = cache_.emplace(key, index).first;
    }
    if (it->second < 0) return {};
    out.texture = it->second;
    return out;
  }

 private:
  std::optional<Texture> load(int textureIndex, bool srgb, const std::string& material) {
    const auto& textures = ctx_.model.textures;
    const std::string where = "material '" + material + "'";
    if (static_cast<std::size_t>(textureIndex) >= textures.size()) {
      ctx_.warnings.warn(where + ": texture " + std::to_string(textureIndex) +
                         " does not exist; using the factor only");
      return std::nullopt;
    }
    const tinygltf::Texture& gt = textures[static_cast<std::size_t>(textureIndex)];
    for (const auto& [name, value] : gt.extensions)
      if (name != "EXT_texture_webp") ctx_.warnUnsupportedExtension(name);
    // EXT_texture_webp: its WebP image first, then `source`, the fallback
    // for viewers without WebP.
    std::vector<int> sources;
    if (const std::optional<int> webp = webpSource(gt, textureIndex)) sources.push_back(*webp);
    if (gt.source >= 0 && static_cast<std::size_t>(gt.source) < ctx_.model.images.size() &&
        (sources.empty() || sources.front() != gt.source))
      sources.push_back(gt.source);
    if (sources.empty()) {
      ctx_.warnings.warn(where + ": texture " + std::to_string(textureIndex) +
                         " has no usable image; using the factor only");
      return std::nullopt;
    }
    for (std::size_t i = 0; i < sources.size(); ++i) {
      const int source = sources[i];
      const std::string imageName = nameOf(source);
      std::variant<Texture, TextureDecodeFailure> decoded = decode(imageName, source, srgb);
      if (Texture* tex = std::get_if<Texture>(&decoded)) {
        textureBytes_ += texelBytes(tex->width, tex->height);
        tex->name = imageName;
        applySampler(gt.sampler, *tex);
        return std::move(*tex);
      }
      const TextureDecodeFailure& failure = std::get<TextureDecodeFailure>(decoded);
      const bool fallback = i + 1 < sources.size();
      if (!failure.pluginProblem.empty()) {
        // An installation problem, not the file's: an error unless the file
        // gives another image.
        const std::string needs = "texture image '" + imageName + "' (" + failure.pluginLabel +
                                  ") needs lensrt's OpenImageIO plugin: " + failure.pluginProblem;
        if (!fallback) ctx_.fail(needs);
        ctx_.warnings.warn(needs + "; using its fallback '" + nameOf(sources[i + 1]) + "'");
      } else if (fallback) {
        ctx_.warnings.warn("texture image '" + imageName + "' " + failure.why + "; using its fallback '" +
                           nameOf(sources[i + 1]) + "'");
      } else {
        ctx_.warnings.warn("texture image '" + imageName + "' " + failure.why +
                           "; using the material factor only");
      }
    }
    return std::nullopt;
  }

  // The image EXT_texture_webp names, if the texture has the extension and
  // it names an image (else a warning).
  std::optional<int> webpSource(const tinygltf::Texture& gt, int textureIndex) const {
    const tinygltf::Value* ext = extension(gt.extensions, "EXT_texture_webp");
    if (!ext) return std::nullopt;
    const std::optional<double> source = ext->IsObject() ? numberMember(*ext, "source") : std::nullopt;
    if (source && isIndex(*source) && *source < double(ctx_.model.images.size())) return int(*source);
    ctx_.warnings.warn("texture " + std::to_string(textureIndex) +
                       ": EXT_texture_webp has no valid image source; ignored");
    return std::nullopt;
  }

  // An image's name for messages: its URI, else its name, else its index.
  std::string nameOf(int source) const {
    const tinygltf::Image& image = ctx_.model.images[static_cast<std::size_t>(source)];
    if (!image.uri.empty() && image.uri.rfind("data:", 0) != 0) return image.uri;
    return image.name.empty() ? indexName(std::size_t(source)) : image.name;
  }

  // The texture limits, before decoding allocates for what the header
  // declares (and again after, for formats whose header is not read here):
  // a small untrusted file can declare a huge image.
  void checkLimits(const std::string& imageName, std::uint32_t width, std::uint32_t height,
                   const char* declares) const {
    if (double(width) * double(height) > kMaxTexels)
      ctx_.fail("texture image '" + imageName + "' " + declares + " " + std::to_string(width) + "x" +
                std::to_string(height) + " texels, more than the " + std::to_string(kMaxMegatexels) +
                " Mtexels a texture may have");
    const std::uint64_t total = textureBytes_ + texelBytes(width, height);
    if (total > ctx_.limits.maxTextureBytes)
      ctx_.fail("texture image '" + imageName + "' (" + std::to_string(width) + "x" + std::to_string(height) +
                ") brings the textures to " + bytesText(total) + ", more than the " +
                bytesText(ctx_.limits.maxTextureBytes) + " --max-texture-memory allows");
  }

  std::variant<Texture, TextureDecodeFailure> decode(const std::string& imageName, int source,
                                                     bool srgb) const {
    const tinygltf::Image& image = ctx_.model.images[static_cast<std::size_t>(source)];
    const unsigned char* bytes = nullptr;
    std::size_t size = 0;
    std::optional<std::string> dataUriBytes;
    if (image.as_is && !image.image.empty()) {
      bytes = image.image.data();
      size = image.image.size();
    } else if (image.uri.starts_with("data:")) {
      // A media type tinygltf does not decode (image/webp, image/tiff): the
      // loader checked its size against the data: URI limit.
      dataUriBytes = decodeBase64DataUri(image.uri);
      if (!dataUriBytes) return TextureDecodeFailure{"is a data: URI without base64 data", "", ""};
      bytes = reinterpret_cast<const unsigned char*>(dataUriBytes->data());
      size = dataUriBytes->size();
    } else if (image.bufferView >= 0) {
      const auto& views = ctx_.model.bufferViews;
      if (static_cast<std::size_t>(image.bufferView) >= views.size())
        return TextureDecodeFailure{"refers to a missing bufferView", "", ""};
      const tinygltf::BufferView& view = views[static_cast<std::size_t>(image.bufferView)];
      if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= ctx_.model.buffers.size())
        return TextureDecodeFailure{"refers to a missing buffer", "", ""};
      const auto& data = ctx_.model.buffers[static_cast<std::size_t>(view.buffer)].data;
      if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
        return TextureDecodeFailure{"lies outside its buffer", "", ""};
      bytes = data.data() + view.byteOffset;
      size = view.byteLength;
    } else {
      return TextureDecodeFailure{"could not be read", "", ""};
    }
    if (size == 0 || size > static_cast<std::size_t>(std::numeric_limits<int>::max()))
      return TextureDecodeFailure{"is empty or too large", "", ""};
    if (const std::optional<std::pair<std::uint32_t, std::uint32_t>> dims = declaredTextureSize(bytes, size))
      checkLimits(imageName, dims->first, dims->second, "declares");
    if (const std::optional<std::string> bomb = pngAllocationProblem(bytes, size))
      ctx_.fail("texture image '" + imageName + "': " + *bomb);
    return decodeTextureImage(bytes, size, srgb, [&](std::uint32_t width, std::uint32_t height) {
      checkLimits(imageName, width, height, "has");
    });
  }

  // KHR_texture_transform: offset, rotation (radians, counter-clockwise in
  // the image), scale, and a texCoord that overrides the textureInfo's. A
  // malformed member is ignored with a warning; the rest still applies.
  UvTransform textureTransform(const tinygltf::Value& ext, const std::string& where, int& texCoord) const {
    const auto pair = [&](const char* key, Vec2f fallback) {
      const tinygltf::Value* v = member(ext, key);
      if (!v) return fallback;
      if (v->IsArray() && v->ArrayLen() == 2 && v->Get(0).IsNumber() && v->Get(1).IsNumber()) {
        const double x = v->Get(0).GetNumberAsDouble(), y = v->Get(1).GetNumberAsDouble();
        if (std::abs(x) <= 1e30 && std::abs(y) <= 1e30) return Vec2f{float(x), float(y)};
      }
      ctx_.warnings.warn(where + ": KHR_texture_transform " + key + " is not two numbers; ignored");
      return fallback;
    };
    const Vec2f offset = pair("offset", {0, 0});
    const Vec2f scale = pair("scale", {1, 1});
    float rotation = 0;
    if (const tinygltf::Value* r = member(ext, "rotation")) {
      if (r->IsNumber() && std::abs(r->GetNumberAsDouble()) <= 1e6)
        rotation = float(std::remainder(r->GetNumberAsDouble(), 2 * 3.14159265358979323846));
      else
        ctx_.warnings.warn(where + ": KHR_texture_transform rotation is not a number of radians; ignored");
    }
    if (const tinygltf::Value* t = member(ext, "texCoord")) {
      if (t->IsNumber() && isIndex(t->GetNumberAsDouble()))
        texCoord = static_cast<int>(t->GetNumberAsDouble());
      else
        ctx_.warnings.warn(where + ": KHR_texture_transform texCoord is not an index; ignored");
    }
    return UvTransform::fromOffsetRotationScale(offset, rotation, scale);
  }

  // glTF sampler: wrapS/wrapT per axis; magFilter picks nearest or bilinear.
  // Without ray differentials the renderer cannot tell magnification from
  // minification: the many samples per pixel average the texels under a pixel
  // instead of mipmaps, and minFilter only decides when magFilter is absent.
  void applySampler(int samplerIndex, Texture& tex) const {
    if (samplerIndex < 0) return;  // glTF default: repeat, linear
    if (static_cast<std::size_t>(samplerIndex) >= ctx_.model.samplers.size()) {
      ctx_.warnings.warn("texture sampler " + std::to_string(samplerIndex) +
                         " does not exist; using defaults");
      return;
    }
    const tinygltf::Sampler& s = ctx_.model.samplers[static_cast<std::size_t>(samplerIndex)];
    const std::string where = "texture sampler " + std::to_string(samplerIndex) + ": ";
    const auto wrap = [&](int mode, const char* axis, bool& repeat, bool& mirror) {
      if (mode != TINYGLTF_TEXTURE_WRAP_REPEAT && mode != TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE &&
          mode != TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) {
        ctx_.warnings.warn(where + axis + " " + std::to_string(mode) +
                           " is not a glTF wrap mode; using REPEAT");
        mode = TINYGLTF_TEXTURE_WRAP_REPEAT;
      }
      repeat = mode != TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
      mirror = mode == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT;
    };
    wrap(s.wrapS, "wrapS", tex.wrapRepeatS, tex.mirrorS);
    wrap(s.wrapT, "wrapT", tex.wrapRepeatT, tex.mirrorT);
    const bool magValid = s.magFilter == -1 || s.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST ||
                          s.magFilter == TINYGLTF_TEXTURE_FILTER_LINEAR;
    const bool minValid = s.minFilter == -1 || s.minFilter == TINYGLTF_TEXTURE_FILTER_NEAREST ||
                          s.minFilter == TINYGLTF_TEXTURE_FILTER_LINEAR ||
                          (s.minFilter >= TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST &&
                           s.minFilter <= TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR);
    if (!magValid)
      ctx_.warnings.warn(where + "magFilter " + std::to_string(s.magFilter) +
                         " is not a glTF filter; using LINEAR");
    if (!minValid)
      ctx_.warnings.warn(where + "minFilter " + std::to_string(s.minFilter) +
                         " is not a glTF filter; ignored");
    if (magValid && s.magFilter != -1) {
      tex.nearest = s.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST;
    } else if (minValid) {
      tex.nearest = s.minFilter == TINYGLTF_TEXTURE_FILTER_NEAREST ||
                    s.minFilter == TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST ||
                    s.minFilter == TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR;
    }
  }

  const Context& ctx_;
  SceneDesc& desc_;
  std::uint64_t textureBytes_ = 0;             // held by the textures loaded so far
  std::map<std::pair<int, bool>, int> cache_;  // (glTF texture, sRGB) -> desc texture or -1
};

float finiteOr(double v, float fallback) {
  return std::isfinite(v) ? static_cast<float>(v) : fallback;
}

void warnTextureInfoExtensions(const Context& ctx, const tinygltf::ExtensionMap& extensions) {
  for (const auto& [name, value] : extensions)
    if (name != "KHR_texture_transform") ctx.warnUnsupportedExtension(name);
}

// Members of a material extension, checked as they are read: a value out of
// its range is ignored with a warning naming material, extension and member.
class ExtensionReader {
 public:
  ExtensionReader(const Context& ctx, TextureLoader& textures, const tinygltf::Value& ext,
                  std::string material, std::string name)
      : ctx_(ctx), textures_(textures), ext_(ext), material_(std::move(material)), name_(std::move(name)) {}

  float number(const char* key, float fallback, float lo, float hi) const {
    const tinygltf::Value* v = member(ext_, key);
    if (!v) return fallback;
    if (v->IsNumber()) {
      const double x = v->GetNumberAsDouble();
      if (x >= lo && x <= hi) return float(x);
    }
    warn(std::string(key) + " is not a number in [" + numberText(lo) + ", " + numberText(hi) + "]");
    return fallback;
  }
  Vec3f colour(const char* key, Vec3f fallback) const {
    const tinygltf::Value* v = member(ext_, key);
    if (!v) return fallback;
    if (v->IsArray() && v->ArrayLen() == 3) {
      Vec3f c;
      bool ok = true;
      for (int i = 0; i < 3; ++i) {
        const tinygltf::Value& e = v->Get(i);
        ok = ok && e.IsNumber() && e.GetNumberAsDouble() >= 0 && e.GetNumberAsDouble() <= 1e6;
        if (ok) c[std::size_t(i)] = float(e.GetNumberAsDouble());
      }
      if (ok) return c;
    }
    warn(std::string(key) + " is not three non-negative numbers");
    return fallback;
  }
  // A textureInfo member (index, texCoord, its own extensions; `scale` for
  // normal textures).
  TextureRef texture(const char* key, bool srgb, float* scale = nullptr) const {
    const tinygltf::Value* info = member(ext_, key);
    if (!info) return {};
    const std::optional<double> index = info->IsObject() ? numberMember(*info, "index") : std::nullopt;
    if (!index || !isIndex(*index)) {
      warn(std::string(key) + " has no valid texture index");
      return {};
    }
    int texCoord = 0;
    if (const std::optional<double> t = numberMember(*info, "texCoord")) {
      if (isIndex(*t) && *t <= 1e6)
        texCoord = int(*t);
      else
        warn(std::string(key) + ".texCoord is not an index");
    }
    if (scale)
      if (const std::optional<double> sc = numberMember(*info, "scale"); sc && std::isfinite(*sc))
        *scale = float(*sc);
    tinygltf::ExtensionMap extensions;
    if (const tinygltf::Value* e = member(*info, "extensions"); e && e->IsObject())
      for (const std::string& k : e->Keys()) extensions[k] = e->Get(k);
    warnTextureInfoExtensions(ctx_, extensions);
    const std::string slot = name_ + " " + key;
    return textures_.ref(int(*index), texCoord, extensions, srgb, material_, slot.c_str());
  }

 private:
  void warn(const std::string& what) const {
    ctx_.warnings.warn("material '" + material_ + "': " + name_ + " " + what + "; ignored");
  }
  const Context& ctx_;
  TextureLoader& textures_;
  const tinygltf::Value& ext_;
  std::string material_, name_;
};

// The material extensions on top of glTF's metallic-roughness (the renderer's
// BSDF says how they combine: render/gltf_bsdf.h).
void readMaterialExtensions(const Context& ctx, TextureLoader& textures,
                            const tinygltf::ExtensionMap& extensions, Material& m) {
  constexpr float kBig = 1e30f;
  const auto reader = [&](const char* name) -> std::optional<ExtensionReader> {
    const tinygltf::Value* ext = extension(extensions, name);
    if (!ext) return std::nullopt;
    return std::optional<ExtensionReader>(std::in_place, ctx, textures, *ext, m.name, name);
  };
  if (const auto r = reader("KHR_materials_ior")) m.ior = r->number("ior", 1.5f, 1.0f, 10.0f);
  if (const auto r = reader("KHR_materials_specular")) {
    m.specular = r->number("specularFactor", 1, 0, 1);
    m.specularTexture = r->texture("specularTexture", false);
    m.specularColor = r->colour("specularColorFactor", {1, 1, 1});
    m.specularColorTexture = r->texture("specularColorTexture", true);
  }
  if (const auto r = reader("KHR_materials_transmission")) {
    m.transmission = r->number("transmissionFactor", 0, 0, 1);
    m.transmissionTexture = r->texture("transmissionTexture", false);
  }
  if (const auto r = reader("KHR_materials_volume")) {
    // The thickness texture serves rasterisers; a path tracer has the geometry.
    m.thickness = r->number("thicknessFactor", 0, 0, kBig);
    m.attenuationDistance = r->number("attenuationDistance", kInfinityF, 1e-30f, kInfinityF);
    m.attenuationColor = r->colour("attenuationColor", {1, 1, 1});
  }
  if (const auto r = reader("KHR_materials_dispersion")) m.dispersion = r->number("dispersion", 0, 0, kBig);
  if (const auto r = reader("KHR_materials_clearcoat")) {
    m.clearcoat = r->number("clearcoatFactor", 0, 0, 1);
    m.clearcoatTexture = r->texture("clearcoatTexture", false);
    m.clearcoatRoughness = r->number("clearcoatRoughnessFactor", 0, 0, 1);
    m.clearcoatRoughnessTexture = r->texture("clearcoatRoughnessTexture", false);
    m.clearcoatNormalTexture = r->texture("clearcoatNormalTexture", false, &m.clearcoatNormalScale);
  }
  if (const auto r = reader("KHR_materials_sheen")) {
    m.sheenColor = r->colour("sheenColorFactor", {0, 0, 0});
    m.sheenColorTexture = r->texture("sheenColorTexture", true);
    m.sheenRoughness = r->number("sheenRoughnessFactor", 0, 0, 1);
    m.sheenRoughnessTexture = r->texture("sheenRoughnessTexture", false);
  }
}

}  // namespace

bool deferImageDecoding(tinygltf::Image* image, int, std::string*, std::string*, int, int,
                        const unsigned char* bytes, int size, void*) {
  if (image->bufferView < 0 && bytes && size > 0) {
    image->image.assign(bytes, bytes + size);
    image->as_is = true;
  }
  return true;
}

void loadMaterials(const Context& ctx, SceneDesc& desc) {
  TextureLoader textures(ctx, desc);
  for (std::size_t i = 0; i < ctx.model.materials.size(); ++i) {
    const tinygltf::Material& gm = ctx.model.materials[i];
    const tinygltf::PbrMetallicRoughness& pbr = gm.pbrMetallicRoughness;
    Material m;
    m.name = gm.name.empty() ? indexName(i) : gm.name;
    if (pbr.baseColorFactor.size() == 4)
      m.baseColor = {finiteOr(pbr.baseColorFactor[0], 1), finiteOr(pbr.baseColorFactor[1], 1),
                     finiteOr(pbr.baseColorFactor[2], 1), finiteOr(pbr.baseColorFactor[3], 1)};
    const auto slot = [&](const auto& info, bool srgb, const char* name) {
      return textures.ref(info.index, info.texCoord, info.extensions, srgb, m.name, name);
    };
    m.baseColorTexture = slot(pbr.baseColorTexture, true, "baseColorTexture");
    m.metallic = finiteOr(pbr.metallicFactor, 1);
    m.roughness = finiteOr(pbr.roughnessFactor, 1);
    m.metallicRoughnessTexture = slot(pbr.metallicRoughnessTexture, false, "metallicRoughnessTexture");
    m.normalTexture = slot(gm.normalTexture, false, "normalTexture");
    m.normalScale = finiteOr(gm.normalTexture.scale, 1);
    float strength = 1;
    if (const tinygltf::Value* ext = extension(gm.extensions, "KHR_materials_emissive_strength"))
      strength = std::max(0.0f, finiteOr(numberMember(*ext, "emissiveStrength").value_or(1.0), 1));
    if (gm.emissiveFactor.size() == 3)
      m.emissive = Vec3f{finiteOr(gm.emissiveFactor[0], 0), finiteOr(gm.emissiveFactor[1], 0),
                         finiteOr(gm.emissiveFactor[2], 0)} *
                   strength;
    m.emissiveTexture = slot(gm.emissiveTexture, true, "emissiveTexture");
    if (gm.occlusionTexture.index >= 0)
      ctx.warnings.warn("occlusion textures are ignored (the path tracer computes occlusion itself)");
    if (gm.alphaMode == "MASK") {
      m.alphaMode = AlphaMode::Mask;
    } else if (gm.alphaMode == "BLEND") {
      m.alphaMode = AlphaMode::Blend;
    } else if (gm.alphaMode != "OPAQUE") {
      ctx.warnings.warn("material '" + m.name + "': unknown alphaMode '" + gm.alphaMode + "', using OPAQUE");
    }
    m.alphaCutoff = finiteOr(gm.alphaCutoff, 0.5f);
    m.doubleSided = gm.doubleSided;
    readMaterialExtensions(ctx, textures, gm.extensions, m);
    for (const auto& [name, value] : gm.extensions)
      if (!isSupportedExtension(name)) ctx.warnUnsupportedExtension(name);
    for (const tinygltf::ExtensionMap* e :
         {&pbr.baseColorTexture.extensions, &pbr.metallicRoughnessTexture.extensions,
          &gm.normalTexture.extensions, &gm.emissiveTexture.extensions})
      warnTextureInfoExtensions(ctx, *e);
    desc.materials.push_back(std::move(m));
  }
}

}  // namespace lensrt::gltf
