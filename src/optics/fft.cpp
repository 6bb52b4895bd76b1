#include "optics/fft.h"

#include <fftw3.h>

#include <mutex>
#include <new>

namespace lensrt {
namespace {

// FFTW's planner is not thread-safe (its plans are).
std::mutex& plannerLock() {
  static std::mutex lock;
  return lock;
}

}  // namespace

ComplexGrid::ComplexGrid(int size) : size_(size) {
  const std::size_t count = std::size_t(size) * std::size_t(size);
  data_ = reinterpret_cast<std::complex<double>*>(fftw_malloc(sizeof(fftw_complex) * count));
  if (!data_) throw std::bad_alloc();
  clear();
}

ComplexGrid::~ComplexGrid() {
  fftw_free(data_);
}

void ComplexGrid::clear() {
  const std::size_t count = std::size_t(size_) * std::size_t(size_);
  for (std::size_t k = 0; k < count; ++k) data_[k] = 0.0;
}

void ComplexGrid::transform(int sign) {
  auto* data = reinterpret_cast<fftw_complex*>(data_);
  fftw_plan plan = nullptr;
  {
    const std::lock_guard<std::mutex> guard(plannerLock());
    plan = fftw_plan_dft_2d(size_, size_, data, data, sign > 0 ? FFTW_BACKWARD : FFTW_FORWARD, FFTW_ESTIMATE);
  }
  if (!plan) throw std::bad_alloc();
  fftw_execute(plan);
  const std::lock_guard<std::mutex> guard(plannerLock());
  fftw_destroy_plan(plan);
}

int fftFriendlySize(int n) {
  for (int m = std::max(n, 2);; ++m) {
    if (m % 2) continue;
    int r = m;
    for (const int p : {2, 3, 5, 7})
      while (r % p == 0) r /= p;
    if (r == 1) return m;
  }
}

}  // namespace lensrt
