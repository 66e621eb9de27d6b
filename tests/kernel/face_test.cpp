// Face (kernel/face.hpp): vertex indices, the first four in place. The in-place and the heap
// form and the step between them by name.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <utility>
#include <vector>

#include "kernel/face.hpp"

using namespace hlr;

TEST(Face, TriangleAndQuadStayInPlace) {
  Face t{0, 1, 2};
  Face q{3, 4, 5, 6};
  EXPECT_EQ(t.size(), 3u);
  EXPECT_EQ(q.capacity(), 4u);
  EXPECT_GE(reinterpret_cast<const char*>(q.data()), reinterpret_cast<const char*>(&q));
  EXPECT_LT(reinterpret_cast<const char*>(q.data()), reinterpret_cast<const char*>(&q) + sizeof(Face));
  EXPECT_EQ(q, (std::vector<int>{3, 4, 5, 6}));
}

TEST(Face, FifthVertexMovesToTheHeapKeepingTheFirstFour) {
  Face f{7, 8, 9, 10};
  f.push_back(11);
  EXPECT_EQ(f.size(), 5u);
  EXPECT_GT(f.capacity(), 4u);
  EXPECT_EQ(f, (std::vector<int>{7, 8, 9, 10, 11}));
  for (int i = 12; i < 1000; ++i) f.push_back(i);
  EXPECT_EQ(f.size(), 993u);
  EXPECT_EQ(f.back(), 999);
  EXPECT_EQ(f[4], 11);
}

TEST(Face, CopiesAndMovesOfBothForms) {
  for (int n : {0, 3, 4, 5, 40}) {
    std::vector<int> v(static_cast<std::size_t>(n));
    std::iota(v.begin(), v.end(), 100);
    Face a(v.begin(), v.end());
    Face b = a;
    EXPECT_EQ(a, b);
    if (n) b[0] = -1;
    if (n) EXPECT_EQ(a[0], 100) << "copies are deep";
    Face c = std::move(a);
    EXPECT_EQ(c, v);
    EXPECT_TRUE(a.empty());  // NOLINT: a moved-from face is empty and usable
    a = c;
    EXPECT_EQ(a, c);
    Face d{1, 2, 3, 4, 5, 6};
    d = std::move(c);
    EXPECT_EQ(d, v);
    std::swap(a, d);
    EXPECT_EQ(a, v);
  }
}

TEST(Face, InsertEraseResizeAndOrder) {
  Face f{1, 2, 4};
  f.insert(f.begin() + 2, 3);
  EXPECT_EQ(f, (std::vector<int>{1, 2, 3, 4}));
  f.insert(f.begin(), 0);  // over four: to the heap
  EXPECT_EQ(f, (std::vector<int>{0, 1, 2, 3, 4}));
  f.erase(f.begin() + 1, f.begin() + 3);
  EXPECT_EQ(f, (std::vector<int>{0, 3, 4}));
  f.resize(6, 9);
  EXPECT_EQ(f, (std::vector<int>{0, 3, 4, 9, 9, 9}));
  std::reverse(f.begin(), f.end());
  EXPECT_EQ(f.front(), 9);
  EXPECT_TRUE((Face{1, 2}) < (Face{1, 3}));
  EXPECT_TRUE((Face{1, 2}) < (Face{1, 2, 0}));
  EXPECT_FALSE((Face{1, 2}) == (Face{1, 2, 0}));
  std::vector<int> back = f;
  EXPECT_EQ(back.size(), 6u);
  EXPECT_THROW(f.at(6), std::out_of_range);
}

TEST(Face, TwentyFourBytes) { EXPECT_EQ(sizeof(Face), 24u); }
