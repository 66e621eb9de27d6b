// A face of a polyhedron: its vertex indices in order (course notes section 19: a body is its
// vertex list and its faces as cycles of vertex indices). A vector of ints with the first four
// in place: triangles and quads, nearly every face of a large mesh, cost 24 bytes and no
// allocation of their own (a std::vector<int> took 24 bytes plus a 32-byte heap block).
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <iterator>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace hlr {

class Face {
 public:
  using value_type = int;
  using size_type = std::size_t;
  using difference_type = std::ptrdiff_t;
  using reference = int&;
  using const_reference = const int&;
  using pointer = int*;
  using const_pointer = const int*;
  using iterator = int*;
  using const_iterator = const int*;

  Face() noexcept {}
  Face(std::initializer_list<int> l) { assign(l.begin(), l.end()); }
  explicit Face(std::size_t n, int value = 0) { resize(n, value); }
  template <class It, class = typename std::iterator_traits<It>::iterator_category>
  Face(It first, It last) {
    assign(first, last);
  }
  Face(const std::vector<int>& v) { assign(v.begin(), v.end()); }  // NOLINT: implicit, as the vector it replaces
  Face(const Face& o) { assign(o.begin(), o.end()); }
  Face(Face&& o) noexcept { take(o); }
  Face& operator=(const Face& o) {
    if (this != &o) {
      clear();
      assign(o.begin(), o.end());
    }
    return *this;
  }
  Face& operator=(Face&& o) noexcept {
    if (this != &o) {
      release();
      take(o);
    }
    return *this;
  }
  Face& operator=(std::initializer_list<int> l) {
    clear();
    assign(l.begin(), l.end());
    return *this;
  }
  ~Face() { release(); }

  /// The indices as a std::vector (a copy).
  std::vector<int> to_vector() const { return std::vector<int>(begin(), end()); }
  operator std::vector<int>() const { return to_vector(); }  // NOLINT: implicit, for callers of the vector it replaces

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  std::size_t capacity() const { return cap_; }
  int* data() { return cap_ > kInPlace ? heap_ : in_; }
  const int* data() const { return cap_ > kInPlace ? heap_ : in_; }
  int* begin() { return data(); }
  int* end() { return data() + size_; }
  const int* begin() const { return data(); }
  const int* end() const { return data() + size_; }
  const int* cbegin() const { return begin(); }
  const int* cend() const { return end(); }
  std::reverse_iterator<int*> rbegin() { return std::reverse_iterator<int*>(end()); }
  std::reverse_iterator<int*> rend() { return std::reverse_iterator<int*>(begin()); }
  std::reverse_iterator<const int*> rbegin() const { return std::reverse_iterator<const int*>(end()); }
  std::reverse_iterator<const int*> rend() const { return std::reverse_iterator<const int*>(begin()); }
  int& operator[](std::size_t i) { return data()[i]; }
  const int& operator[](std::size_t i) const { return data()[i]; }
  int& at(std::size_t i) {
    if (i >= size_) throw std::out_of_range("Face::at");
    return data()[i];
  }
  const int& at(std::size_t i) const {
    if (i >= size_) throw std::out_of_range("Face::at");
    return data()[i];
  }
  int& front() { return data()[0]; }
  const int& front() const { return data()[0]; }
  int& back() { return data()[size_ - 1]; }
  const int& back() const { return data()[size_ - 1]; }

  void reserve(std::size_t n) {
    if (n <= cap_) return;
    if (n > UINT32_MAX) throw std::length_error("Face: more than 2^32 vertices");
    int* p = new int[n];
    if (size_) std::memcpy(p, data(), size_ * sizeof(int));
    if (cap_ > kInPlace) delete[] heap_;
    heap_ = p;
    cap_ = static_cast<std::uint32_t>(n);
  }
  void push_back(int v) {
    if (size_ == cap_) reserve(2 * static_cast<std::size_t>(cap_));
    data()[size_++] = v;
  }
  void emplace_back(int v) { push_back(v); }
  void pop_back() { --size_; }
  void clear() { size_ = 0; }
  void resize(std::size_t n, int value = 0) {
    reserve(n);
    for (std::size_t i = size_; i < n; ++i) data()[i] = value;
    size_ = static_cast<std::uint32_t>(n);
  }
  int* insert(const int* pos, int v) {
    const std::size_t at = static_cast<std::size_t>(pos - begin());
    push_back(v);
    std::rotate(begin() + at, end() - 1, end());
    return begin() + at;
  }
  int* erase(const int* pos) { return erase(pos, pos + 1); }
  int* erase(const int* first, const int* last) {
    const std::size_t a = static_cast<std::size_t>(first - begin()), b = static_cast<std::size_t>(last - begin());
    std::move(begin() + b, end(), begin() + a);
    size_ -= static_cast<std::uint32_t>(b - a);
    return begin() + a;
  }
  void swap(Face& o) noexcept {
    Face t(std::move(o));
    o = std::move(*this);
    *this = std::move(t);
  }

  friend bool operator==(const Face& a, const Face& b) { return std::equal(a.begin(), a.end(), b.begin(), b.end()); }
  friend bool operator!=(const Face& a, const Face& b) { return !(a == b); }
  friend bool operator<(const Face& a, const Face& b) {
    return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end());
  }
  friend bool operator==(const Face& a, const std::vector<int>& b) { return std::equal(a.begin(), a.end(), b.begin(), b.end()); }
  friend bool operator==(const std::vector<int>& a, const Face& b) { return b == a; }

 private:
  static constexpr std::uint32_t kInPlace = 4;
  template <class It>
  void assign(It first, It last) {
    if constexpr (std::is_base_of_v<std::forward_iterator_tag, typename std::iterator_traits<It>::iterator_category>)
      reserve(static_cast<std::size_t>(std::distance(first, last)));
    for (; first != last; ++first) push_back(static_cast<int>(*first));
  }
  void release() {
    if (cap_ > kInPlace) delete[] heap_;
    cap_ = kInPlace;
    size_ = 0;
  }
  void take(Face& o) {  // *this is empty and in place
    size_ = o.size_;
    cap_ = o.cap_;
    if (o.cap_ > kInPlace) heap_ = o.heap_;
    else std::memcpy(in_, o.in_, sizeof(in_));
    o.cap_ = kInPlace;
    o.size_ = 0;
  }

  union {
    int in_[kInPlace];
    int* heap_;
  };
  std::uint32_t size_ = 0;
  std::uint32_t cap_ = kInPlace;
};

inline void swap(Face& a, Face& b) noexcept { a.swap(b); }

static_assert(sizeof(Face) == 24, "a face is 24 bytes");

}  // namespace hlr
