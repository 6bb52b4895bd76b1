// RAII ownership of Embree handles: unique_ptr with deleters that release.
#pragma once

#include <embree3/rtcore.h>

#include <memory>

namespace lensrt {

struct EmbreeDeviceDeleter {
  void operator()(RTCDeviceTy* d) const { rtcReleaseDevice(d); }
};
struct EmbreeSceneDeleter {
  void operator()(RTCSceneTy* s) const { rtcReleaseScene(s); }
};
struct EmbreeGeometryDeleter {
  void operator()(RTCGeometryTy* g) const { rtcReleaseGeometry(g); }
};

using EmbreeDevice = std::unique_ptr<RTCDeviceTy, EmbreeDeviceDeleter>;
using EmbreeScene = std::unique_ptr<RTCSceneTy, EmbreeSceneDeleter>;
// Only held until the geometry is attached to a scene (which then keeps it alive).
using EmbreeGeometry = std::unique_ptr<RTCGeometryTy, EmbreeGeometryDeleter>;

}  // namespace lensrt
