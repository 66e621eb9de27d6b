// Vectors whose new elements are left unconstructed by resize(): a resize of millions of
// records is then no serial pass of zeroes, and the caller constructs or writes every element
// on all cores (parallel.hpp) before any use.
#pragma once

#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace hlr {

/// An allocator whose construct() without arguments does nothing: the element's storage is
/// left as it is. Elements of a type with a non-trivial constructor must be constructed by
/// placement new before use (and before the vector is destroyed); others written.
template <class T>
struct Uninitialised : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = Uninitialised<U>;
  };
  Uninitialised() = default;
  template <class U>
  Uninitialised(const Uninitialised<U>&) {}
  template <class U>
  void construct(U*) {}
  template <class U, class... A>
  void construct(U* p, A&&... a) {
    ::new (static_cast<void*>(p)) U(std::forward<A>(a)...);
  }
};

/// A vector whose resize() leaves the new elements unconstructed (Uninitialised).
template <class T>
using RawVector = std::vector<T, Uninitialised<T>>;

}  // namespace hlr
