// The vertex array of curves: a std::vector whose resize() leaves new points unwritten instead of zeroing
// them, so that the threads of a parallel kernel are the first to touch their own slices of fresh memory.
// On this project's VMs the first touch of fresh memory costs more than drawing into it (bench/README.md);
// zeroing 200 MB on one thread and then writing it again on all of them paid that cost twice.
// Only resize() and the count constructor differ from std::vector: every other way in writes its values.
// Vec2 and Vec3 are aggregates (implicit-lifetime types), so allocated storage holds them already.
#pragma once

#include <cstddef>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace selfsim {

template <class T>
struct UninitializedAllocator {
  using value_type = T;

  UninitializedAllocator() = default;
  template <class U>
  UninitializedAllocator(const UninitializedAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) { return std::allocator<T>().allocate(n); }
  void deallocate(T* p, std::size_t n) noexcept { std::allocator<T>().deallocate(p, n); }

  // Value-less construction (resize, the count constructor) writes nothing; the caller writes every point.
  template <class U>
  void construct(U*) noexcept {
    static_assert(std::is_trivially_destructible_v<U> && std::is_aggregate_v<U>, "points only");
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }

  friend bool operator==(const UninitializedAllocator&, const UninitializedAllocator&) { return true; }
};

template <class V>
using PointArray = std::vector<V, UninitializedAllocator<V>>;

}  // namespace selfsim
