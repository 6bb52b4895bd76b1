#include "render/id_coverage.h"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <map>

#include "core/murmur_hash.h"
#include "render/film.h"
#include "scene/scene_desc.h"

namespace lensrt {

namespace {
std::string nodeIdName(const SceneDesc& desc, int node) {
  return node >= 0 && std::size_t(node) < desc.nodeNames.size() ? desc.nodeNames[std::size_t(node)]
                                                                : "node" + std::to_string(node);
}
std::uint32_t idBits(const std::string& name) {
  return cryptomatteIdBits(murmurHash3X86_32(name));
}

// JSON string escaping for the manifest (names are UTF-8 from glTF).
std::string jsonString(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\')
      out += {'\\', c};
    else if (static_cast<unsigned char>(c) < 0x20)
      out += fmt::format("\\u{:04x}", int(static_cast<unsigned char>(c)));
    else
      out += c;
  }
  return out + '"';
}

void addLayer(ImageMetadata& m, const std::string& layer, const std::map<std::string, std::uint32_t>& ids) {
  const std::string key = fmt::format("{:08x}", murmurHash3X86_32(layer)).substr(0, 7);
  std::string manifest = "{";
  for (const auto& [name, bits] : ids) {
    // No operator+ on a const char* conditional (GCC 12's -Wrestrict false alarm).
    if (manifest.size() > 1) manifest += ',';
    manifest += jsonString(name);
    manifest += fmt::format(":\"{:08x}\"", bits);
  }
  manifest += "}";
  const std::string prefix = "cryptomatte/" + key + "/";
  m[prefix + "name"] = layer;
  m[prefix + "hash"] = "MurmurHash3_32";
  m[prefix + "conversion"] = "uint32_to_float32";
  m[prefix + "manifest"] = manifest;
}
}  // namespace

std::string materialIdName(const SceneDesc& desc, int material) {
  if (material < 0 || std::size_t(material) >= desc.materials.size()) return "default";
  const std::string& name = desc.materials[std::size_t(material)].name;
  return name.empty() ? "material" + std::to_string(material) : name;
}

SceneIds::SceneIds(const SceneDesc& desc) {
  for (const MeshInstance& inst : desc.instances) {
    instanceBits.push_back(idBits(nodeIdName(desc, inst.node)));
    instanceNode.push_back(inst.node);
  }
  for (int m = -1; m < int(desc.materials.size()); ++m)
    materialBits.push_back(idBits(materialIdName(desc, m)));
}

ImageMetadata cryptomatteMetadata(const SceneDesc& desc, const AovSelection& aovs) {
  ImageMetadata m;
  if (aovs.cryptoObject) {
    std::map<std::string, std::uint32_t> ids;
    for (const MeshInstance& inst : desc.instances) {
      const std::string name = nodeIdName(desc, inst.node);
      ids[name] = idBits(name);
    }
    addLayer(m, kCryptoObjectLayer, ids);
  }
  if (aovs.cryptoMaterial) {
    std::map<std::string, std::uint32_t> ids;
    for (int k = -1; k < int(desc.materials.size()); ++k) {
      const std::string name = materialIdName(desc, k);
      ids[name] = idBits(name);
    }
    addLayer(m, kCryptoMaterialLayer, ids);
  }
  return m;
}

void IdCoverage::bump(std::vector<IdCount>& list, std::uint32_t bits, std::int32_t index) {
  // A pixel sees few ids: a linear search beats a map.
  for (IdCount& e : list)
    if (e.idBits == bits && e.index == index) {
      ++e.count;
      return;
    }
  list.push_back({bits, index, 1});
}

void IdCoverage::add(std::uint32_t objectBits, std::int32_t node, std::uint32_t materialBits,
                     std::int32_t material) {
  ++samples_;
  bump(objects_, objectBits, node);
  bump(materials_, materialBits, material);
}

std::vector<IdCount> IdCoverage::ranked(const std::vector<IdCount>& list) {
  std::vector<IdCount> r = list;
  std::sort(r.begin(), r.end(), [](const IdCount& a, const IdCount& b) {
    return a.count != b.count     ? a.count > b.count
           : a.idBits != b.idBits ? a.idBits < b.idBits
                                  : a.index < b.index;
  });
  return r;
}

void IdCoverage::writeRanks(bool material, float* out) const {
  std::fill(out, out + 2 * kCryptoRanks, 0.0f);
  if (samples_ == 0) return;
  const std::vector<IdCount> r = ranked(material ? materials_ : objects_);
  // Two instances of one name share an id: their counts add up (Cryptomatte
  // mattes by name). The list is short, so merge after ranking.
  std::vector<IdCount> byId;
  for (const IdCount& e : r) {
    auto it = std::find_if(byId.begin(), byId.end(), [&](const IdCount& b) { return b.idBits == e.idBits; });
    if (it == byId.end())
      byId.push_back(e);
    else
      it->count += e.count;
  }
  std::stable_sort(byId.begin(), byId.end(),
                   [](const IdCount& a, const IdCount& b) { return a.count > b.count; });
  const std::size_t n = std::min<std::size_t>(byId.size(), kCryptoRanks);
  for (std::size_t i = 0; i < n; ++i) {
    out[2 * i] = std::bit_cast<float>(byId[i].idBits);
    out[2 * i + 1] = float(double(byId[i].count) / double(samples_));
  }
}

std::int32_t IdCoverage::topNode() const {
  if (samples_ == 0) return -1;
  return ranked(objects_).front().index;
}

}  // namespace lensrt
