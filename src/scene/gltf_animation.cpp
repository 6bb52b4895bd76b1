#include "scene/gltf_animation.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "core/error.h"
#include "scene/gltf_accessor.h"

namespace lensrt::gltf {

std::array<double, 4> slerp(const std::array<double, 4>& qa, const std::array<double, 4>& qb, double u) {
  // Keyframes written with few digits (0.707 for 1/sqrt 2) are rotations
  // all the same: the angle between them is that of the unit quaternions.
  const auto unit = [](std::array<double, 4> q) {
    const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (double& c : q) c /= n;
    return q;
  };
  const std::array<double, 4> a = unit(qa), b = unit(qb);
  double d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
  // The shorter way round: q and -q are the same rotation.
  const double sign = d < 0 ? -1.0 : 1.0;
  d = std::abs(d);
  double wa = 1.0 - u, wb = u;
  if (d < 0.9995) {  // nearly equal rotations: the linear blend, normalised below
    const double theta = std::acos(d), s = std::sin(theta);
    wa = std::sin((1.0 - u) * theta) / s;
    wb = std::sin(u * theta) / s;
  }
  std::array<double, 4> q{};
  double norm = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    q[i] = wa * a[i] + sign * wb * b[i];
    norm += q[i] * q[i];
  }
  norm = std::sqrt(norm);
  for (double& c : q) c /= norm;
  return q;
}

double hermite(double v0, double b0, double a1, double v1, double dt, double u) {
  const double u2 = u * u, u3 = u2 * u;
  return (2 * u3 - 3 * u2 + 1) * v0 + (u3 - 2 * u2 + u) * dt * b0 + (-2 * u3 + 3 * u2) * v1 +
         (u3 - u2) * dt * a1;
}

namespace {

enum class Interpolation { Linear, Step, CubicSpline };

// The animations that play: one named or numbered, or all.
std::vector<std::size_t> playing(const Context& ctx, const std::string& which) {
  const auto& animations = ctx.model.animations;
  std::vector<std::size_t> all;
  for (std::size_t i = 0; i < animations.size(); ++i) all.push_back(i);
  if (which.empty()) return all;
  for (std::size_t i = 0; i < animations.size(); ++i)
    if (animations[i].name == which) return {i};
  char* end = nullptr;
  const long index = std::strtol(which.c_str(), &end, 10);
  if (*end == '\0' && index >= 0 && std::size_t(index) < animations.size()) return {std::size_t(index)};
  std::string known;
  for (std::size_t i = 0; i < animations.size(); ++i)
    known +=
        fmt::format("{}{}{}", i ? ", " : "", i,
                    animations[i].name.empty() ? std::string() : fmt::format(" '{}'", animations[i].name));
  throw UsageError("--animation", fmt::format("{} has no animation '{}' ({})", ctx.file, which,
                                              animations.empty() ? std::string("it has none")
                                                                 : fmt::format("choose from: {}", known)));
}

// One channel's value at `t`, or why it cannot be read (a warning).
struct ChannelValue {
  std::vector<double> value;
  std::string problem;
};

// `components` values per keyframe; a SCALAR output holds them one after
// another (morph weights: one per target).
ChannelValue evaluate(const Context& ctx, const tinygltf::AnimationSampler& sampler, int components, double t,
                      bool rotation, bool scalarOutput, const std::string& label) {
  Interpolation mode = Interpolation::Linear;
  if (sampler.interpolation == "STEP")
    mode = Interpolation::Step;
  else if (sampler.interpolation == "CUBICSPLINE")
    mode = Interpolation::CubicSpline;
  else if (!sampler.interpolation.empty() && sampler.interpolation != "LINEAR")
    return {{}, fmt::format("interpolation '{}' is not LINEAR, STEP or CUBICSPLINE", sampler.interpolation)};
  const std::vector<float> times = readFloats(ctx, sampler.input, 1, fmt::format("{} input", label).c_str());
  const std::vector<float> values =
      readFloats(ctx, sampler.output, scalarOutput ? 1 : components, fmt::format("{} output", label).c_str());
  if (times.empty()) return {{}, "its sampler has no keyframes"};
  for (std::size_t k = 0; k < times.size(); ++k) {
    if (!std::isfinite(times[k])) return {{}, fmt::format("its keyframe time {} is not finite", k)};
    if (k > 0 && !(times[k] > times[k - 1]))
      return {{}, fmt::format("its keyframe times do not increase (at keyframe {})", k)};
  }
  const std::size_t perKey = mode == Interpolation::CubicSpline ? 3 : 1;
  const std::size_t keys = values.size() / std::size_t(components);
  if (keys != times.size() * perKey)
    return {{},
            fmt::format("it has {} output values for {} keyframes ({})", keys, times.size(),
                        perKey == 3 ? "CUBICSPLINE needs 3 each" : "one each")};
  for (const float v : values)
    if (!std::isfinite(v)) return {{}, "an output value is not finite"};
  // Element e of keyframe k: the value itself (CUBICSPLINE: in-tangent,
  // value, out-tangent).
  const auto at = [&](std::size_t k, std::size_t part, int c) {
    return double(values[(k * perKey + part) * std::size_t(components) + std::size_t(c)]);
  };
  const std::size_t valuePart = perKey == 3 ? 1 : 0;
  std::vector<double> out(static_cast<std::size_t>(components));
  const auto keyValue = [&](std::size_t k) {
    for (int c = 0; c < components; ++c) out[std::size_t(c)] = at(k, valuePart, c);
  };
  if (t <= times.front() || times.size() == 1) {
    keyValue(0);
  } else if (t >= times.back()) {
    keyValue(times.size() - 1);
  } else {
    const std::size_t k =
        std::size_t(std::upper_bound(times.begin(), times.end(), float(t)) - times.begin()) - 1;
    const double t0 = times[k], t1 = times[k + 1], dt = t1 - t0, u = (t - t0) / dt;
    if (mode == Interpolation::Step) {
      keyValue(k);
    } else if (mode == Interpolation::Linear && rotation) {
      const std::array<double, 4> q =
          slerp({at(k, 0, 0), at(k, 0, 1), at(k, 0, 2), at(k, 0, 3)},
                {at(k + 1, 0, 0), at(k + 1, 0, 1), at(k + 1, 0, 2), at(k + 1, 0, 3)}, u);
      out.assign(q.begin(), q.end());
    } else if (mode == Interpolation::Linear) {
      for (int c = 0; c < components; ++c) out[std::size_t(c)] = at(k, 0, c) * (1 - u) + at(k + 1, 0, c) * u;
    } else {
      for (int c = 0; c < components; ++c)
        out[std::size_t(c)] = hermite(at(k, 1, c), at(k, 2, c), at(k + 1, 0, c), at(k + 1, 1, c), dt, u);
    }
  }
  if (rotation) {
    double norm = 0;
    for (const double c : out) norm += c * c;
    norm = std::sqrt(norm);
    if (!(norm > 0)) return {{}, "its rotation is zero"};
    for (double& c : out) c /= norm;
  }
  return {out, ""};
}

}  // namespace

std::map<int, AnimatedTrs> animatedNodes(const Context& ctx, const AnimationTime& time) {
  std::map<int, AnimatedTrs> nodes;
  const auto& animations = ctx.model.animations;
  const std::vector<std::size_t> play = playing(ctx, time.animation);
  if (time.animation.empty() && play.size() > 1)
    ctx.warnings.warn(
        fmt::format("{} animations play together (--animation NAME|INDEX plays one)", play.size()));
  for (const std::size_t a : play) {
    const tinygltf::Animation& animation = animations[a];
    for (std::size_t c = 0; c < animation.channels.size(); ++c) {
      const tinygltf::AnimationChannel& channel = animation.channels[c];
      const std::string label =
          fmt::format("animation {}{} channel {} ({})", a,
                      animation.name.empty() ? std::string() : fmt::format(" '{}'", animation.name), c,
                      channel.target_path);
      const auto skip = [&](const std::string& why) {
        ctx.warnings.warn(fmt::format("{} is skipped: {}", label, why));
      };
      const bool rotation = channel.target_path == "rotation", weights = channel.target_path == "weights";
      int components = rotation ? 4 : 3;
      if (!rotation && !weights && channel.target_path != "translation" && channel.target_path != "scale") {
        skip("the path is not translation, rotation, scale or weights");
        continue;
      }
      if (channel.target_node < 0 || std::size_t(channel.target_node) >= ctx.model.nodes.size()) {
        skip("its target node does not exist");
        continue;
      }
      if (weights) {
        // One weight per morph target of the node's mesh.
        const int mesh = ctx.model.nodes[std::size_t(channel.target_node)].mesh;
        std::size_t targets = 0;
        if (mesh >= 0 && std::size_t(mesh) < ctx.model.meshes.size())
          for (const tinygltf::Primitive& prim : ctx.model.meshes[std::size_t(mesh)].primitives)
            targets = std::max(targets, prim.targets.size());
        if (targets == 0) {
          skip("its node has no mesh with morph targets");
          continue;
        }
        components = int(targets);
      } else if (!ctx.model.nodes[std::size_t(channel.target_node)].matrix.empty()) {
        skip("its node has a matrix (glTF animates only translation, rotation and scale)");
        continue;
      }
      if (channel.sampler < 0 || std::size_t(channel.sampler) >= animation.samplers.size()) {
        skip("its sampler does not exist");
        continue;
      }
      const ChannelValue v = evaluate(ctx, animation.samplers[std::size_t(channel.sampler)], components,
                                      time.seconds, rotation, weights, label);
      if (!v.problem.empty()) {
        skip(v.problem);
        continue;
      }
      AnimatedTrs& trs = nodes[channel.target_node];
      if (weights)
        trs.weights = v.value;
      else if (rotation)
        trs.rotation = std::array<double, 4>{v.value[0], v.value[1], v.value[2], v.value[3]};
      else if (channel.target_path == "translation")
        trs.translation = std::array<double, 3>{v.value[0], v.value[1], v.value[2]};
      else
        trs.scale = std::array<double, 3>{v.value[0], v.value[1], v.value[2]};
    }
  }
  return nodes;
}

}  // namespace lensrt::gltf
