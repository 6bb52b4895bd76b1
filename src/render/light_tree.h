// A bounding volume hierarchy over lights that picks one for a shading point
// with probability roughly proportional to what it contributes there (Conty
// Estevez and Kulla 2018; pbrt-v4's BVHLightSampler). Each inner node steps
// to a child with probability proportional to the child's importance at the
// point, so near, bright, facing lights are chosen more often than the power
// alone would choose them. A leaf holds one light, or the few lights of one
// flat patch (the two triangles of a quad light: coplanar, facing one way),
// chosen among by power: a walk one level shorter, and none at all for a
// scene whose only light is such a patch; or the triangles of one emitter
// (a mesh instance) that is small beside the scene's lights (an emissive
// sphere of a few centimetres made of thousands of triangles), chosen among
// by power as they would be without a tree.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/vec.h"
#include "render/light_bounds.h"

namespace lensrt {

struct LightPick {
  std::size_t light;  // index into the vector the tree was built from
  float pmf;          // the probability of this pick from this point
};

class LightTree {
 public:
  LightTree() = default;
  // One entry per light; those whose phi is not > 0 (or not finite) are left
  // out and never picked. `emitter` (empty, or one per light) names the
  // emitter each belongs to (-1: none). The build is serial and deterministic.
  explicit LightTree(const std::vector<LightBounds>& lights, const std::vector<std::int32_t>& emitter = {});

  bool empty() const { return nodes_.empty(); }
  std::size_t nodeCount() const { return nodes_.size(); }
  // At most this many lights of one flat patch share a leaf.
  static constexpr std::size_t kMaxLeafLights = 4;
  // One emitter's lights share a leaf when their bounding sphere's radius is
  // at most this fraction of all the lights' one.
  static constexpr float kSmallEmitter = 0.01f;

  // One light for the point p with normal n (zero: none), from u in [0, 1);
  // none when no light can reach p.
  std::optional<LightPick> sample(const Vec3f& p, const Vec3f& n, float u) const;
  // The probability that sample(p, n, .) returns `light`: the same product,
  // in the same order, so the two agree to the bit (as MIS needs).
  float pmf(const Vec3f& p, const Vec3f& n, std::size_t light) const;

 private:
  struct Node {
    ImportanceBounds bounds;
    // A leaf's first entry in leafLights_, or an inner node's second child
    // (its first is the next node).
    std::uint32_t childOrFirst = 0;
    std::uint32_t count = 0;  // a leaf's lights; 0 for an inner node
    // An inner node's children's bounds, as the walk weighs them.
    ImportancePair children;
    bool leaf() const { return count > 0; }
  };
  struct Entry {
    std::size_t light;
    LightBounds bounds;
    std::int32_t emitter;
  };
  void build(std::vector<Entry>& entries, std::size_t begin, std::size_t end, std::uint64_t trail, int depth);
  // The probability of stepping to the first child, from the children's
  // importances (the second's is one minus it).
  static float firstChildProbability(float importance0, float importance1);
  // Whether entries [begin, end) form one flat patch a leaf may hold.
  static bool flatPatch(const std::vector<Entry>& entries, std::size_t begin, std::size_t end,
                        const LightBounds& all);
  // Whether entries [begin, end) are one emitter's, within smallRadius_.
  bool smallEmitter(const std::vector<Entry>& entries, std::size_t begin, std::size_t end,
                    const LightBounds& all) const;

  std::vector<Node> nodes_;  // depth first: a node's first child follows it
  // The lights of the leaves, each leaf's together, with their phi and the
  // leaf's total (in order: the same float sums in sample() and pmf()).
  std::vector<std::uint32_t> leafLights_;
  std::vector<float> leafPhi_;
  std::vector<float> leafPhiTotal_;  // per entry of leafLights_: its leaf's total
  std::vector<double> leafCdf_;      // per entry: the leaf's phi up to and with it
  std::vector<std::uint32_t> slot_;  // per light: its entry in leafLights_
  float smallRadius_ = 0;            // kSmallEmitter of all the lights' radius
  // For each light, the turns from the root to its leaf: bit d set when the
  // walk takes the second child at depth d. kNotInTree for lights left out.
  std::vector<std::uint64_t> trail_;
  std::vector<std::uint8_t> depth_;  // the leaf's depth (trail bits used)
  static constexpr std::uint8_t kNotInTree = 255;
};

}  // namespace lensrt
