#pragma once
// Counting allocations, for the tests that prove a hot path allocates nothing after set-up:
// every form of the global operator new / delete is replaced by a counting version, and Eigen is
// built with EIGEN_RUNTIME_NO_MALLOC and an eigen_assert that counts instead of aborting (Eigen
// allocates dynamic matrices through malloc, not operator new). Include this first, in exactly
// one translation unit of a standalone test binary (tests/<folder>/*.standalone.cpp), so the
// replacement affects nothing else.
#include <atomic>
#include <cstdlib>
#include <new>

namespace {
std::atomic<long> g_news{0};
std::atomic<long> g_eigen_asserts{0};
}  // namespace
inline void gaitsynth_test_count_eigen_assert() {
  ++g_eigen_asserts;
}
#define EIGEN_RUNTIME_NO_MALLOC
#define eigen_assert(x)                                             \
  do {                                                              \
    if (!static_cast<bool>(x)) gaitsynth_test_count_eigen_assert(); \
  } while (false)

namespace {
// malloc and free out of line, so that GCC does not see a malloc'd pointer reach operator delete
// (a false -Wmismatched-new-delete). Every form goes through these two, so that sanitizers see
// matching malloc / free pairs.
[[gnu::noinline]] void* acquire(std::size_t n) noexcept {
  ++g_news;
  return std::malloc(n ? n : 1);
}
[[gnu::noinline]] void* acquire_aligned(std::size_t n, std::align_val_t a) noexcept {
  ++g_news;
  const std::size_t al = static_cast<std::size_t>(a);
  return std::aligned_alloc(al, (n + al - 1) / al * al);
}
[[gnu::noinline]] void release(void* p) noexcept {
  std::free(p);
}
void* checked(void* p) {
  if (!p) throw std::bad_alloc();
  return p;
}
}  // namespace

void* operator new(std::size_t n) {
  return checked(acquire(n));
}
void* operator new[](std::size_t n) {
  return checked(acquire(n));
}
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  return acquire(n);
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
  return acquire(n);
}
void* operator new(std::size_t n, std::align_val_t a) {
  return checked(acquire_aligned(n, a));
}
void* operator new[](std::size_t n, std::align_val_t a) {
  return checked(acquire_aligned(n, a));
}
void* operator new(std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  return acquire_aligned(n, a);
}
void* operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  return acquire_aligned(n, a);
}
void operator delete(void* p) noexcept {
  release(p);
}
void operator delete[](void* p) noexcept {
  release(p);
}
void operator delete(void* p, std::size_t) noexcept {
  release(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  release(p);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
  release(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
  release(p);
}
void operator delete(void* p, std::align_val_t) noexcept {
  release(p);
}
void operator delete[](void* p, std::align_val_t) noexcept {
  release(p);
}
void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
  release(p);
}
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept {
  release(p);
}
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept {
  release(p);
}
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept {
  release(p);
}

#include <Eigen/Core>  // after the eigen_assert above
#include <vector>

/// Whether both counters see an allocation: without it, a test that counts nothing would pass.
inline bool counters_see_allocations() {
  const long news = g_news.load(), eigen = g_eigen_asserts.load();
  auto* probe = new std::vector<int>(10);
  const bool news_seen = g_news.load() >= news + 2;
  delete probe;
  Eigen::internal::set_is_malloc_allowed(false);
  Eigen::VectorXd x(7);
  Eigen::internal::set_is_malloc_allowed(true);
  x.setZero();
  return news_seen && g_eigen_asserts.load() > eigen;
}
