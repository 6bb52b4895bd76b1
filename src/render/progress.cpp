#include "render/progress.h"

#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <string>

namespace lensrt {
namespace {

std::string clock(double seconds) {
  const long s = long(std::max(0.0, seconds) + 0.5);
  return s >= 3600 ? fmt::format("{}:{:02}:{:02}", s / 3600, (s / 60) % 60, s % 60)
                   : fmt::format("{:02}:{:02}", s / 60, s % 60);
}

}  // namespace

Progress::Style Progress::styleFor(std::FILE* stream, bool quiet) {
  if (quiet) return Style::Quiet;
  return isatty(fileno(stream)) ? Style::Terminal : Style::Plain;
}

Progress::Progress(std::uint64_t totalSamples, Style style, std::FILE* stream)
    : total_(std::max<std::uint64_t>(1, totalSamples)),
      style_(style),
      stream_(stream),
      start_(std::chrono::steady_clock::now()) {
  if (style_ != Style::Quiet) thread_ = std::thread([this] { run(); });
}

Progress::~Progress() {
  finish();
}

void Progress::finish() {
  {
    const std::lock_guard lock(mutex_);
    if (stop_) return;
    stop_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
  if (style_ != Style::Quiet) print(true);
}

void Progress::run() {
  // Redraw a bar often; print a log line rarely.
  const auto period =
      style_ == Style::Terminal ? std::chrono::milliseconds(250) : std::chrono::milliseconds(5000);
  std::unique_lock lock(mutex_);
  while (!wake_.wait_for(lock, period, [this] { return stop_; })) print(false);
}

void Progress::print(bool final) {
  const std::uint64_t taken = done_.load(std::memory_order_relaxed);
  const std::uint64_t done = std::min(taken + skipped_.load(std::memory_order_relaxed), total_);
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double fraction = double(done) / double(total_);
  const double rate = elapsed > 0 ? double(taken) / elapsed : 0.0;
  const double progressRate = elapsed > 0 ? double(done) / elapsed : 0.0;
  const double eta = progressRate > 0 ? double(total_ - done) / progressRate : 0.0;
  const std::string stats = fmt::format("{:5.1f}%  {:.3g} Msamples/s  elapsed {}  ETA {}", 100 * fraction,
                                        rate * 1e-6, clock(elapsed), clock(eta));
  if (style_ == Style::Terminal) {
    constexpr int kWidth = 30;
    const int filled = int(fraction * kWidth);
    fmt::print(stream_, "\r[{}{}] {}{}", std::string(filled, '#'), std::string(kWidth - filled, '.'), stats,
               final ? "\n" : "");
  } else {
    fmt::print(stream_, "render: {}\n", stats);
  }
  std::fflush(stream_);
}

}  // namespace lensrt
