// Compiled into every layer library so that a layer whose sources are all
// header-only still forms a valid static library target.
namespace lensrt::detail {
[[maybe_unused]] constexpr int kLayerAnchor = 0;
}  // namespace lensrt::detail
