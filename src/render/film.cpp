#include "render/film.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

namespace lensrt {

std::string AovSelection::unsavedAovs() const {
  std::string names;
  for (const auto& [on, name] :
       {std::pair{cryptoObject, "crypto_object"}, std::pair{cryptoMaterial, "crypto_material"},
        std::pair{objectId, "object_id"}, std::pair{flow, "flow"}})
    if (on) names += (names.empty() ? "" : ", ") + std::string(name);
  return names;
}

std::vector<std::string> filmChannels(const AovSelection& aovs) {
  std::vector<std::string> c{"R", "G", "B", "A"};
  if (aovs.depth) c.push_back("depth.Z");
  if (aovs.z) c.push_back("Z");
  if (aovs.normal) c.insert(c.end(), {"normal.X", "normal.Y", "normal.Z"});
  if (aovs.albedo) c.insert(c.end(), {"albedo.R", "albedo.G", "albedo.B"});
  if (aovs.variance) c.insert(c.end(), {"variance.R", "variance.G", "variance.B"});
  if (aovs.spp) c.push_back("spp");
  for (const auto& [on, layer] : {std::pair{aovs.cryptoObject, kCryptoObjectLayer},
                                  std::pair{aovs.cryptoMaterial, kCryptoMaterialLayer}})
    if (on)
      for (const char* rank : {"00", "01", "02"})
        for (const char* k : {".R", ".G", ".B", ".A"}) c.push_back(std::string(layer) + rank + k);
  // One token before the dot, one after: the layout Blender's EXR reader
  // takes as a pass (a bare "object_id" it drops), as its own IndexOB.X.
  if (aovs.objectId) c.push_back("object_id.X");
  if (aovs.position) c.insert(c.end(), {"position.X", "position.Y", "position.Z"});
  if (aovs.uv) c.insert(c.end(), {"uv.U", "uv.V"});
  if (aovs.objectCoords) c.insert(c.end(), {"object_coords.X", "object_coords.Y", "object_coords.Z"});
  if (aovs.flow)
    c.insert(c.end(), {"flow.forward.X", "flow.forward.Y", "flow.backward.X", "flow.backward.Y"});
  return c;
}

bool PixelAccumulator::add(const PathSample& s, float weight, bool lensReflected) {
  const Rgb l = s.radiance * weight;
  if (!isFinite(l)) {
    ++dropped_;
    return false;
  }
  ++count_;
  ++reached_;
  if (!lensReflected) {
    ++seen_;
    covered_ += s.hit;
  }
  for (int k = 0; k < 3; ++k) {
    sum_[k] += l[k];
    sumSq_[k] += double(l[k]) * l[k];
  }
  if (s.hit) {
    ++hits_;
    distance_ += s.distance;
    planarZ_ += s.planarZ;
    if (isFinite(s.normal)) normal_ += s.normal;
    for (int k = 0; k < 3; ++k) albedo_[k] += s.albedo[k];
  }
  return true;
}

void PixelAccumulator::addBlocked() {
  ++count_;
}

namespace {
// Unbiased sample variance over n (the variance of the mean), clamped
// against cancellation; 0 below 2 samples.
double varianceOfMean(double sum, double sumSq, double n) {
  if (n <= 1) return 0.0;
  const double mean = sum / n;
  return std::max(0.0, (sumSq - n * mean * mean) / (n - 1)) / n;
}
}  // namespace

PixelAccumulator::MeanAndError PixelAccumulator::meanAndError() const {
  MeanAndError m;
  const double n = double(count_);
  for (int k = 0; k < 3; ++k) {
    m.mean[k] = n > 0 ? sum_[k] / n : 0.0;
    m.standardError[k] = std::sqrt(varianceOfMean(sum_[k], sumSq_[k], n));
  }
  return m;
}

void PixelAccumulator::write(const AovSelection& aovs, float* out) const {
  const double n = double(count_);
  double mean[3] = {0, 0, 0};
  for (int k = 0; k < 3; ++k) mean[k] = n > 0 ? sum_[k] / n : 0.0;
  int c = 0;
  for (int k = 0; k < 3; ++k) out[c++] = float(mean[k]);
  out[c++] = seen_ > 0      ? float(double(covered_) / double(seen_))
             : reached_ > 0 ? float(double(hits_) / double(reached_))
                            : 0.0f;
  if (aovs.depth) out[c++] = hits_ > 0 ? float(distance_ / double(hits_)) : 0.0f;
  if (aovs.z) out[c++] = hits_ > 0 ? float(planarZ_ / double(hits_)) : 0.0f;
  if (aovs.normal) {
    const float len = length(normal_);
    const Vec3f nn = len > 0 ? normal_ / len : Vec3f{0, 0, 0};
    out[c++] = nn.x;
    out[c++] = nn.y;
    out[c++] = nn.z;
  }
  if (aovs.albedo)
    for (int k = 0; k < 3; ++k) out[c++] = n > 0 ? float(albedo_[k] / n) : 0.0f;
  if (aovs.variance)
    for (int k = 0; k < 3; ++k) out[c++] = float(varianceOfMean(sum_[k], sumSq_[k], n));
  if (aovs.spp) out[c++] = float(samplesTaken());
}

namespace {
template <class T>
void put(std::byte*& p, const T& v) {
  std::memcpy(p, &v, sizeof v);
  p += sizeof v;
}
template <class T>
void get(const std::byte*& p, T& v) {
  std::memcpy(&v, p, sizeof v);
  p += sizeof v;
}
}  // namespace

void PixelAccumulator::saveState(std::byte* out) const {
  for (double v : sum_) put(out, v);
  for (double v : sumSq_) put(out, v);
  put(out, count_);
  put(out, hits_);
  put(out, reached_);
  put(out, seen_);
  put(out, covered_);
  put(out, dropped_);
  put(out, distance_);
  put(out, planarZ_);
  for (double v : albedo_) put(out, v);
  put(out, normal_.x);
  put(out, normal_.y);
  put(out, normal_.z);
}

void PixelAccumulator::loadState(const std::byte* in) {
  for (double& v : sum_) get(in, v);
  for (double& v : sumSq_) get(in, v);
  get(in, count_);
  get(in, hits_);
  get(in, reached_);
  get(in, seen_);
  get(in, covered_);
  get(in, dropped_);
  get(in, distance_);
  get(in, planarZ_);
  for (double& v : albedo_) get(in, v);
  get(in, normal_.x);
  get(in, normal_.y);
  get(in, normal_.z);
}

void CoordinateSums::add(const PathSample& s) {
  if (!s.hit) return;
  ++hits_;
  for (int k = 0; k < 3; ++k) {
    position_[k] += s.position[k];
    object_[k] += s.objectPosition[k];
  }
  uv_[0] += s.uv.x;
  uv_[1] += s.uv.y;
}

void CoordinateSums::write(const AovSelection& aovs, float* out) const {
  // No hit: 0, as depth.Z (alpha says which pixels saw nothing).
  const double n = double(hits_);
  const auto mean = [n](double sum) { return n > 0 ? float(sum / n) : 0.0f; };
  int c = 0;
  if (aovs.position)
    for (double v : position_) out[c++] = mean(v);
  if (aovs.uv)
    for (double v : uv_) out[c++] = mean(v);
  if (aovs.objectCoords)
    for (double v : object_) out[c++] = mean(v);
}

void CoordinateSums::saveState(std::byte* out) const {
  put(out, hits_);
  for (double v : position_) put(out, v);
  for (double v : uv_) put(out, v);
  for (double v : object_) put(out, v);
}

void CoordinateSums::loadState(const std::byte* in) {
  get(in, hits_);
  for (double& v : position_) get(in, v);
  for (double& v : uv_) get(in, v);
  for (double& v : object_) get(in, v);
}

}  // namespace lensrt
