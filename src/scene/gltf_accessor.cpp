#include "scene/gltf_accessor.h"

#include <algorithm>
#include <cstring>
#include <string>

namespace lensrt::gltf {
namespace {

// Accessors without a bufferView are zero-filled; cap them so a hostile count
// cannot allocate unbounded memory.
constexpr std::size_t kMaxUnbackedElements = std::size_t{1} << 26;

int componentSize(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    case TINYGLTF_COMPONENT_TYPE_INT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return 4;
    default:
      return 0;
  }
}

template <class T>
T load(const unsigned char* p) {
  T v;
  std::memcpy(&v, p, sizeof(T));
  return v;
}

// glTF 2.0, "Animation/Accessor data": normalized signed values clamp at -1.
float toFloat(const unsigned char* p, int type, bool normalized) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return load<float>(p);
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const float v = load<std::int8_t>(p);
      return normalized ? std::max(v / 127.0f, -1.0f) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
      const float v = load<std::uint8_t>(p);
      return normalized ? v / 255.0f : v;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      const float v = load<std::int16_t>(p);
      return normalized ? std::max(v / 32767.0f, -1.0f) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      const float v = load<std::uint16_t>(p);
      return normalized ? v / 65535.0f : v;
    }
    case TINYGLTF_COMPONENT_TYPE_INT:
      return static_cast<float>(load<std::int32_t>(p));
    default:
      return static_cast<float>(load<std::uint32_t>(p));
  }
}

std::uint32_t toUint(const unsigned char* p, int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return load<std::uint8_t>(p);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return load<std::uint16_t>(p);
    default:
      return load<std::uint32_t>(p);
  }
}

bool isUnsignedIndexType(int type) {
  return type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE || type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
         type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
}

const tinygltf::Accessor& accessorAt(const Context& ctx, int index, const char* what) {
  if (index < 0 || static_cast<std::size_t>(index) >= ctx.model.accessors.size())
    ctx.fail(std::string(what) + ": accessor " + std::to_string(index) + " does not exist");
  return ctx.model.accessors[static_cast<std::size_t>(index)];
}

// Start of `count` elements of `elemSize` bytes, `stride` apart (0: packed), at
// `offset` into bufferView `viewIndex`, after checking that all of them lie in
// the view and the view lies in its buffer.
const unsigned char* viewData(const Context& ctx, int viewIndex, long long offset, std::size_t count,
                              std::size_t elemSize, std::size_t stride, const std::string& what) {
  const auto& views = ctx.model.bufferViews;
  if (viewIndex < 0 || static_cast<std::size_t>(viewIndex) >= views.size())
    ctx.fail(what + ": bufferView " + std::to_string(viewIndex) + " does not exist");
  const tinygltf::BufferView& view = views[static_cast<std::size_t>(viewIndex)];
  if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= ctx.model.buffers.size())
    ctx.fail("bufferView " + std::to_string(viewIndex) + ": buffer " + std::to_string(view.buffer) +
             " does not exist");
  const std::vector<unsigned char>& data = ctx.model.buffers[static_cast<std::size_t>(view.buffer)].data;
  if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
    ctx.fail("bufferView " + std::to_string(viewIndex) + " (bytes " + std::to_string(view.byteOffset) + ".." +
             std::to_string(view.byteOffset + view.byteLength) + ") exceeds buffer " +
             std::to_string(view.buffer) + " of " + std::to_string(data.size()) + " bytes");
  if (stride == 0) stride = elemSize;
  if (stride < elemSize)
    ctx.fail(what + ": byteStride " + std::to_string(stride) + " is smaller than an element (" +
             std::to_string(elemSize) + " bytes)");
  if (offset < 0) ctx.fail(what + ": negative byteOffset");
  const auto start = static_cast<std::size_t>(offset);
  if (count > 0) {
    const bool fits = start <= view.byteLength && elemSize <= view.byteLength - start &&
                      count - 1 <= (view.byteLength - start - elemSize) / stride;
    if (!fits)
      ctx.fail(what + ": accessor reads beyond the end of bufferView " + std::to_string(viewIndex) + " (" +
               std::to_string(count) + " elements of " + std::to_string(elemSize) + " bytes from offset " +
               std::to_string(start) + ", view is " + std::to_string(view.byteLength) + " bytes)");
  }
  return data.data() + view.byteOffset + start;
}

template <class Out, class Convert>
std::vector<Out> decode(const Context& ctx, int index, int components, const char* what, Convert convert) {
  const tinygltf::Accessor& acc = accessorAt(ctx, index, what);
  const std::string label = std::string(what) + " (accessor " + std::to_string(index) + ")";
  const int actual = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(acc.type));
  if (actual != components)
    ctx.fail(label + ": has " + std::to_string(actual) + " components per element, expected " +
             std::to_string(components));
  const int csize = componentSize(acc.componentType);
  if (csize == 0) ctx.fail(label + ": unknown componentType " + std::to_string(acc.componentType));
  const std::size_t elemSize = static_cast<std::size_t>(csize) * static_cast<std::size_t>(components);
  const std::size_t count = acc.count;

  const unsigned char* base = nullptr;
  std::size_t stride = elemSize;
  if (acc.bufferView >= 0) {
    const std::size_t declared =
        static_cast<std::size_t>(acc.bufferView) < ctx.model.bufferViews.size()
            ? ctx.model.bufferViews[static_cast<std::size_t>(acc.bufferView)].byteStride
            : 0;
    base = viewData(ctx, acc.bufferView,
                    static_cast<long long>(std::min<std::size_t>(acc.byteOffset, 1ull << 62)), count,
                    elemSize, declared, label);
    if (declared != 0) stride = declared;
  } else if (count > kMaxUnbackedElements) {
    ctx.fail(label + ": " + std::to_string(count) + " elements without a bufferView");
  }

  std::vector<Out> out(count * static_cast<std::size_t>(components), Out{});
  if (base)
    for (std::size_t i = 0; i < count; ++i)
      for (int c = 0; c < components; ++c)
        out[i * components + c] = convert(base + i * stride + static_cast<std::size_t>(c * csize), acc);

  if (acc.sparse.isSparse) {
    const auto& sp = acc.sparse;
    if (sp.count < 0 || static_cast<std::size_t>(sp.count) > count)
      ctx.fail(label + ": sparse count " + std::to_string(sp.count) + " exceeds the accessor count");
    if (!isUnsignedIndexType(sp.indices.componentType))
      ctx.fail(label + ": sparse indices must be unsigned integers");
    const auto n = static_cast<std::size_t>(sp.count);
    const auto isize = static_cast<std::size_t>(componentSize(sp.indices.componentType));
    const unsigned char* ip =
        viewData(ctx, sp.indices.bufferView, sp.indices.byteOffset, n, isize, 0, label + " sparse indices");
    const unsigned char* vp =
        viewData(ctx, sp.values.bufferView, sp.values.byteOffset, n, elemSize, 0, label + " sparse values");
    for (std::size_t k = 0; k < n; ++k) {
      const std::uint32_t target = toUint(ip + k * isize, sp.indices.componentType);
      if (target >= count)
        ctx.fail(label + ": sparse index " + std::to_string(target) + " beyond the accessor count " +
                 std::to_string(count));
      for (int c = 0; c < components; ++c)
        out[target * components + c] = convert(vp + k * elemSize + static_cast<std::size_t>(c * csize), acc);
    }
  }
  return out;
}

}  // namespace

std::vector<float> readFloats(const Context& ctx, int index, int components, const char* what) {
  return decode<float>(ctx, index, components, what, [](const unsigned char* p, const tinygltf::Accessor& a) {
    return toFloat(p, a.componentType, a.normalized);
  });
}

std::vector<std::uint32_t> readIndices(const Context& ctx, int index, const char* what) {
  const tinygltf::Accessor& acc = accessorAt(ctx, index, what);
  if (!isUnsignedIndexType(acc.componentType))
    ctx.fail(std::string(what) + " (accessor " + std::to_string(index) +
             "): indices must be unsigned byte, short or int");
  return decode<std::uint32_t>(ctx, index, 1, what, [](const unsigned char* p, const tinygltf::Accessor& a) {
    return toUint(p, a.componentType);
  });
}

std::size_t accessorCount(const Context& ctx, int index, const char* what) {
  return accessorAt(ctx, index, what).count;
}

}  // namespace lensrt::gltf
