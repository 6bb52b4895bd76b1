// Render progress on a stream (stderr): a bar redrawn in place with \r on a
// terminal, a plain line every few seconds otherwise (logs, CI), nothing when
// quiet. A background thread does the printing, so workers only bump an atomic.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <mutex>
#include <thread>

namespace lensrt {

class Progress {
 public:
  enum class Style { Quiet, Terminal, Plain };
  // Terminal when `stream` is a tty, Plain otherwise; Quiet when `quiet`.
  static Style styleFor(std::FILE* stream, bool quiet);

  Progress(std::uint64_t totalSamples, Style style, std::FILE* stream = stderr);
  ~Progress();  // finishes if finish() was not called
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  void add(std::uint64_t samples) { done_.fetch_add(samples, std::memory_order_relaxed); }
  // Samples of the total that will not be taken (adaptive sampling stopped
  // their pixels): they advance the bar and the ETA, not the sample rate.
  void skip(std::uint64_t samples) { skipped_.fetch_add(samples, std::memory_order_relaxed); }
  void finish();

 private:
  void run();
  void print(bool final);

  std::uint64_t total_;
  Style style_;
  std::FILE* stream_;
  std::atomic<std::uint64_t> done_{0};
  std::atomic<std::uint64_t> skipped_{0};
  std::chrono::steady_clock::time_point start_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  std::thread thread_;
};

}  // namespace lensrt
