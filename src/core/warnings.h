// Warnings from loaders and tools go through a sink the caller owns, so the
// library never prints and each distinct warning is reported once.
#pragma once

#include <functional>
#include <set>
#include <string>

namespace lensrt {

class Warnings {
 public:
  using Sink = std::function<void(const std::string&)>;
  Warnings() = default;
  explicit Warnings(Sink sink) : sink_(std::move(sink)) {}

  void warn(const std::string& message) {
    if (!seen_.insert(message).second) return;
    if (sink_) sink_(message);
  }
  const std::set<std::string>& all() const { return seen_; }

 private:
  Sink sink_;
  std::set<std::string> seen_;
};

}  // namespace lensrt
