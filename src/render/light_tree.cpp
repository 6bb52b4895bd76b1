#include "render/light_tree.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace lensrt {
namespace {

constexpr int kBuckets = 12;
// Below this depth every split halves its lights (sorted along the widest
// axis), so that a trail of 64 bits holds any leaf's path for up to 2^32 lights.
constexpr int kBalancedFromDepth = 30;
// Nodes of more lights than this try only their widest axis for a cut.
constexpr std::size_t kAllAxesUpTo = 1024;
constexpr double kOneMinusEpsilon = 1.0 - 0x1p-53;

float surfaceArea(const Bounds3f& b) {
  const Vec3f d = b.diagonal();
  return 2 * (d.x * d.y + d.y * d.z + d.z * d.x);
}

Bounds3f padded(Bounds3f b, float pad) {
  b.lo -= Vec3f{pad, pad, pad};
  b.hi += Vec3f{pad, pad, pad};
  return b;
}

float maxComponent(const Vec3f& v) {
  return std::max({v.x, v.y, v.z});
}

}  // namespace

LightTree::LightTree(const std::vector<LightBounds>& lights, const std::vector<std::int32_t>& emitter)
    : slot_(lights.size(), 0), trail_(lights.size(), 0), depth_(lights.size(), kNotInTree) {
  std::vector<Entry> entries;
  Bounds3f all;
  for (std::size_t i = 0; i < lights.size(); ++i) {
    const LightBounds& b = lights[i];
    if (!(b.phi > 0) || !std::isfinite(b.phi) || b.bounds.empty()) continue;
    entries.push_back({i, b, emitter.size() == lights.size() ? emitter[i] : -1});
    all.extend(b.bounds);
  }
  if (entries.empty()) return;
  smallRadius_ = kSmallEmitter * 0.5f * length(all.diagonal());
  nodes_.reserve(2 * entries.size() - 1);
  leafLights_.reserve(entries.size());
  leafPhi_.reserve(entries.size());
  leafPhiTotal_.reserve(entries.size());
  leafCdf_.reserve(entries.size());
  build(entries, 0, entries.size(), 0, 0);
}

void LightTree::build(std::vector<Entry>& entries, std::size_t begin, std::size_t end, std::uint64_t trail,
                      int depth) {
  LightBounds all;
  Bounds3f centroids;
  for (std::size_t k = begin; k < end; ++k) {
    all = unite(all, entries[k].bounds);
    centroids.extend(entries[k].bounds.bounds.center());
  }
  if (end - begin == 1 || flatPatch(entries, begin, end, all) || smallEmitter(entries, begin, end, all)) {
    const std::uint32_t first = std::uint32_t(leafLights_.size());
    float total = 0;
    double cdf = 0;
    for (std::size_t k = begin; k < end; ++k) {
      const Entry& e = entries[k];
      slot_[e.light] = std::uint32_t(leafLights_.size());
      leafLights_.push_back(std::uint32_t(e.light));
      leafPhi_.push_back(e.bounds.phi);
      total += e.bounds.phi;
      cdf += double(e.bounds.phi);
      leafCdf_.push_back(cdf);
      trail_[e.light] = trail;
      depth_[e.light] = std::uint8_t(depth);
    }
    leafPhiTotal_.insert(leafPhiTotal_.end(), end - begin, total);
    nodes_.push_back({ImportanceBounds(all), first, std::uint32_t(end - begin), {}});
    return;
  }
  const Vec3f extent = all.bounds.diagonal();
  const float maxExtent = maxComponent(extent);
  const auto bucketOf = [&](const Entry& e, int dim) {
    const float lo = centroids.lo[dim], hi = centroids.hi[dim];
    const int b = int(float(kBuckets) * ((e.bounds.bounds.center()[dim] - lo) / (hi - lo)));
    return std::clamp(b, 0, kBuckets - 1);
  };
  // The cost of one side of a split (Conty Estevez and Kulla): power times
  // the orientation measure times the box's area, the area of boxes padded
  // so that point lights, whose boxes have none, still split by position;
  // K_r favours cuts across the node's long axis.
  const float pad = 1e-3f * maxExtent;
  const auto cost = [&](const LightBounds& b, float kr) {
    if (!(b.phi > 0)) return 0.0f;
    return b.phi * orientationMeasure(b.cosThetaO, b.cosThetaE) * kr * surfaceArea(padded(b.bounds, pad));
  };

  float bestCost = std::numeric_limits<float>::infinity();
  int bestDim = -1, bestBucket = -1;
  // Large nodes try their widest axis alone (uniting cones costs the build
  // most of its time; a large node's best cut is nearly always across it).
  const Vec3f spread = centroids.diagonal();
  const int widest = spread.x >= spread.y && spread.x >= spread.z ? 0 : (spread.y >= spread.z ? 1 : 2);
  for (int dim = 0; dim < 3 && depth < kBalancedFromDepth; ++dim) {
    if (!(centroids.hi[dim] > centroids.lo[dim])) continue;
    if (end - begin > kAllAxesUpTo && dim != widest) continue;
    std::array<LightBounds, kBuckets> buckets{};
    for (std::size_t k = begin; k < end; ++k) {
      LightBounds& b = buckets[std::size_t(bucketOf(entries[k], dim))];
      b = unite(b, entries[k].bounds);
    }
    std::array<LightBounds, kBuckets> above{};  // above[s]: buckets s.. together
    above[kBuckets - 1] = buckets[kBuckets - 1];
    for (int s = kBuckets - 2; s >= 0; --s) above[s] = unite(buckets[s], above[s + 1]);
    const float kr = maxExtent / extent[dim];
    LightBounds below;
    for (int s = 0; s < kBuckets - 1; ++s) {
      below = unite(below, buckets[s]);
      if (!(below.phi > 0) || !(above[s + 1].phi > 0)) continue;
      const float c = cost(below, kr) + cost(above[s + 1], kr);
      if (c < bestCost) {
        bestCost = c;
        bestDim = dim;
        bestBucket = s;
      }
    }
  }
  const auto first = entries.begin() + std::ptrdiff_t(begin), last = entries.begin() + std::ptrdiff_t(end);
  std::size_t mid = begin + (end - begin) / 2;
  if (bestDim >= 0) {
    mid = std::size_t(std::stable_partition(
                          first, last, [&](const Entry& e) { return bucketOf(e, bestDim) <= bestBucket; }) -
                      entries.begin());
  } else {
    // No split by cost (all at one spot, or deep): halve along the widest axis.
    const int dim = widest;
    std::stable_sort(first, last, [dim](const Entry& a, const Entry& b) {
      return a.bounds.bounds.center()[dim] < b.bounds.bounds.center()[dim];
    });
  }
  if (mid == begin || mid == end) mid = begin + (end - begin) / 2;

  const std::size_t node = nodes_.size();
  nodes_.push_back({ImportanceBounds(all), 0, 0, {}});
  build(entries, begin, mid, trail, depth + 1);
  nodes_[node].childOrFirst = std::uint32_t(nodes_.size());
  build(entries, mid, end, trail | (std::uint64_t{1} << depth), depth + 1);
  nodes_[node].children = ImportancePair(nodes_[node + 1].bounds, nodes_[nodes_[node].childOrFirst].bounds);
}

bool LightTree::flatPatch(const std::vector<Entry>& entries, std::size_t begin, std::size_t end,
                          const LightBounds& all) {
  // Normals within about a degree of each other, emitting alike: within
  // such a patch the importance of one part differs from another's only
  // close to it, not worth a level of the walk.
  if (end - begin > kMaxLeafLights || !(all.cosThetaO >= 0.99985f)) return false;
  for (std::size_t k = begin; k < end; ++k) {
    const LightBounds& b = entries[k].bounds;
    if (b.twoSided != all.twoSided || b.cosThetaE != all.cosThetaE || !(b.cosThetaO >= 0.99985f))
      return false;
  }
  return true;
}

bool LightTree::smallEmitter(const std::vector<Entry>& entries, std::size_t begin, std::size_t end,
                             const LightBounds& all) const {
  const std::int32_t id = entries[begin].emitter;
  if (id < 0 || !(0.5f * length(all.bounds.diagonal()) <= smallRadius_)) return false;
  for (std::size_t k = begin; k < end; ++k)
    if (entries[k].emitter != id) return false;
  return true;
}

float LightTree::firstChildProbability(float importance0, float importance1) {
  return float(double(importance0) / (double(importance0) + double(importance1)));
}

std::optional<LightPick> LightTree::sample(const Vec3f& p, const Vec3f& n, float uFloat) const {
  if (nodes_.empty()) return std::nullopt;
  double u = uFloat;  // rescaled at each level; double keeps deep levels stratified
  std::size_t i = 0;
  float pmf = 1;
  while (!nodes_[i].leaf()) {
    const std::size_t c0 = i + 1, c1 = nodes_[i].childOrFirst;
    const auto [i0, i1] = importancePair(nodes_[i].children, p, n);
    if (!(i0 > 0) && !(i1 > 0)) return std::nullopt;
    const float p0 = firstChildProbability(i0, i1);
    if (u < double(p0)) {
      u = std::min(u / double(p0), kOneMinusEpsilon);
      pmf *= p0;
      i = c0;
    } else {
      u = std::min((u - double(p0)) / double(1 - p0), kOneMinusEpsilon);
      pmf *= 1 - p0;
      i = c1;
    }
  }
  // Within the leaf by power. (A tree that is one leaf skips the walk and
  // any importance: a light it picks that cannot reach p gives nothing.)
  const Node& leaf = nodes_[i];
  std::size_t k = leaf.childOrFirst;
  if (leaf.count > 1) {
    // u's place among the leaf's lights by their phi.
    const auto first = leafCdf_.begin() + std::ptrdiff_t(k), last = first + std::ptrdiff_t(leaf.count - 1);
    k = std::size_t(std::upper_bound(first, last, u * *last) - leafCdf_.begin());
    pmf *= leafPhi_[k] / leafPhiTotal_[k];
  }
  return LightPick{leafLights_[k], pmf};
}

float LightTree::pmf(const Vec3f& p, const Vec3f& n, std::size_t light) const {
  if (light >= depth_.size() || depth_[light] == kNotInTree) return 0;
  const std::uint64_t trail = trail_[light];
  std::size_t i = 0;
  float pmf = 1;
  for (int depth = 0; !nodes_[i].leaf(); ++depth) {
    const std::size_t c0 = i + 1, c1 = nodes_[i].childOrFirst;
    const auto [i0, i1] = importancePair(nodes_[i].children, p, n);
    if (!(i0 > 0) && !(i1 > 0)) return 0;
    const float p0 = firstChildProbability(i0, i1);
    if ((trail >> depth) & 1) {
      pmf *= 1 - p0;
      i = c1;
    } else {
      pmf *= p0;
      i = c0;
    }
  }
  if (nodes_[i].count > 1) {
    const std::size_t k = slot_[light];
    pmf *= leafPhi_[k] / leafPhiTotal_[k];
  }
  return pmf;
}

}  // namespace lensrt
