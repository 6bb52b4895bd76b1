// Two-dimensional discrete Fourier transforms through FFTW (libfftw3).
//
// FFTW's planner keeps global state and is not thread-safe, so plans are made
// and destroyed under one lock; executing a plan is safe from any thread.
// Plans are FFTW_ESTIMATE (no timing runs), and the arrays come from
// fftw_malloc (the same alignment every time), so the same input gives the
// same bits on every run.
#pragma once

#include <complex>
#include <cstddef>
#include <memory>
#include <utility>

namespace lensrt {

// size x size complex values, row by row; transformed in place.
class ComplexGrid {
 public:
  explicit ComplexGrid(int size);
  ~ComplexGrid();
  ComplexGrid(const ComplexGrid&) = delete;
  ComplexGrid& operator=(const ComplexGrid&) = delete;
  ComplexGrid(ComplexGrid&& other) noexcept
      : size_(std::exchange(other.size_, 0)), data_(std::exchange(other.data_, nullptr)) {}
  ComplexGrid& operator=(ComplexGrid&&) = delete;

  int size() const { return size_; }
  std::complex<double>& operator()(int i, int j) {
    return data_[std::size_t(j) * std::size_t(size_) + std::size_t(i)];
  }
  const std::complex<double>& operator()(int i, int j) const {
    return data_[std::size_t(j) * std::size_t(size_) + std::size_t(i)];
  }
  void clear();
  // out(k) = sum over m of in(m) exp(sign 2 pi i k.m / size), unnormalised:
  // sign +1 is FFTW's backward transform, -1 its forward one.
  void transform(int sign);

 private:
  int size_ = 0;
  std::complex<double>* data_ = nullptr;
};

// The smallest size >= n with no prime factor above 7 (FFTW's fast sizes), even.
int fftFriendlySize(int n);

}  // namespace lensrt
