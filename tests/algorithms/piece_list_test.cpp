// PieceList (algorithms/model/line_drawing.hpp): a segment's pieces, one piece over [0, 1] held as its
// flags only. Each degenerate case of the representation by name.
#include <gtest/gtest.h>

#include <cstring>

#include "algorithms/model/line_drawing.hpp"

using namespace hlr;

namespace {

Piece piece(const char* t0, const char* t1, bool visible) {
  Piece p;
  p.t0 = Rational(t0);
  p.t0.canonicalize();
  p.t1 = Rational(t1);
  p.t1.canonicalize();
  p.visible = visible;
  return p;
}

}  // namespace

TEST(PieceList, EmptyByDefault) {
  PieceList l;
  EXPECT_TRUE(l.empty());
  EXPECT_EQ(l.size(), 0u);
  EXPECT_EQ(l.begin(), l.end());
}

TEST(PieceList, WholeVisibleReadsAsOnePieceZeroToOne) {
  PieceList l;
  l.set_whole(true);
  ASSERT_EQ(l.size(), 1u);
  EXPECT_EQ(l[0].t0, 0);
  EXPECT_EQ(l[0].t1, 1);
  EXPECT_TRUE(l[0].visible);
  EXPECT_FALSE(l[0].behind_eye || l[0].clipped || l[0].through);
  l.set_whole(false);
  EXPECT_FALSE(l.front().visible);
  EXPECT_EQ(&l.front(), &l.back());
}

TEST(PieceList, EveryFlagCombinationSurvivesTheWholeForm) {
  for (int f = 0; f < 16; ++f) {
    Piece kind = piece("0", "1", (f & 1) != 0);
    kind.behind_eye = (f & 2) != 0, kind.clipped = (f & 4) != 0, kind.through = (f & 8) != 0;
    PieceList l{kind};
    ASSERT_EQ(l.size(), 1u);
    EXPECT_TRUE(l[0].same_kind(kind)) << f;
    EXPECT_EQ(l[0].t0, 0);
    EXPECT_EQ(l[0].t1, 1);
  }
}

TEST(PieceList, AVectorOfOnePieceOverZeroToOneIsStoredWhole) {
  PieceList l = std::vector<Piece>{piece("0", "1", false)};
  PieceList w;
  w.set_whole(false);
  EXPECT_EQ(l, w);
  // A lone piece that does not cover [0, 1] keeps its numbers.
  PieceList part = std::vector<Piece>{piece("0", "1/2", true)};
  ASSERT_EQ(part.size(), 1u);
  EXPECT_EQ(part[0].t1, Rational(1, 2));
}

TEST(PieceList, ManyPiecesKeepTheirOrderAndNumbers) {
  PieceList l{piece("0", "1/3", true), piece("1/3", "2/3", false), piece("2/3", "1", true)};
  ASSERT_EQ(l.size(), 3u);
  EXPECT_EQ(l[1].t0, Rational(1, 3));
  EXPECT_FALSE(l[1].visible);
  EXPECT_EQ(l.back().t0, Rational(2, 3));
  std::vector<Piece> v = l.to_vector();
  EXPECT_EQ(PieceList(v), l);
}

TEST(PieceList, EditUnpacksAndCompactPacksAgain) {
  PieceList l;
  l.set_whole(true);
  std::vector<Piece>& v = l.edit();
  ASSERT_EQ(v.size(), 1u);
  v[0].t1 = Rational(1, 2);
  v.push_back(piece("1/2", "1", false));
  l.compact();
  EXPECT_EQ(l.size(), 2u);
  // Joined back into one piece over [0, 1]: whole again.
  std::vector<Piece>& w = l.edit();
  w.pop_back();
  w[0].t1 = 1;
  l.compact();
  PieceList whole;
  whole.set_whole(true);
  EXPECT_EQ(l, whole);
  l.edit().clear();
  l.compact();
  EXPECT_TRUE(l.empty());
}

TEST(PieceList, CopiesAreDeepAndMovesLeaveTheSourceUsable) {
  PieceList a{piece("0", "1/2", true), piece("1/2", "1", false)};
  PieceList b = a;
  b.edit()[0].visible = false;
  EXPECT_TRUE(a[0].visible);
  PieceList c = std::move(a);
  EXPECT_EQ(c.size(), 2u);
  a = c;  // NOLINT: reuse after move
  EXPECT_EQ(a, c);
  a.push_back(piece("1", "2", true));
  EXPECT_EQ(a.size(), 3u);
  EXPECT_EQ(c.size(), 2u);
  a.clear();
  EXPECT_TRUE(a.empty());
}

// One word (a segment of a large drawing is 48 bytes): a moved-from list is all zero bytes, as
// are the pages a spent array of lists was given back with (release_pages), and reads as
// empty; move assignment frees what the target held (a sanitizer build sees every block).
TEST(PieceList, OneWordThatIsZeroWhenMovedFrom) {
  static_assert(sizeof(PieceList) == 8 && sizeof(Segment) == 48);
  PieceList a{piece("0", "1/3", false), piece("1/3", "1", true)};
  PieceList b = std::move(a);
  unsigned char bytes[sizeof(PieceList)];
  std::memcpy(bytes, static_cast<const void*>(&a), sizeof bytes);
  for (unsigned char x : bytes) EXPECT_EQ(x, 0);
  EXPECT_TRUE(a.empty());  // NOLINT: read after move
  PieceList c;
  c.set_whole(true);
  c = std::move(b);  // a whole list replaced by a vector
  EXPECT_EQ(c.size(), 2u);
  b = PieceList{piece("0", "1/2", true), piece("1/2", "1", false)};  // NOLINT: reuse after move
  c = std::move(b);                                                  // a vector replaced by a vector: the old one freed
  EXPECT_TRUE(c[0].visible);
  Piece through = piece("0", "1", false);
  through.through = true;
  c.set_whole(through);
  EXPECT_EQ(c.size(), 1u);
  EXPECT_TRUE(c[0].through && !c[0].visible);
}

TEST(PieceList, EqualityComparesNumbersAndFlags) {
  PieceList a{piece("0", "1/2", true), piece("1/2", "1", false)};
  PieceList b{piece("0", "1/2", true), piece("1/2", "1", true)};
  PieceList c{piece("0", "1/3", true), piece("1/3", "1", false)};
  EXPECT_NE(a, b);
  EXPECT_NE(a, c);
  EXPECT_EQ(a, PieceList(a.to_vector()));
}
