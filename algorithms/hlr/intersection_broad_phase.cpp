// Broad phase (see intersection_broad_phase.hpp): cell size twice the mean box size, dense cell
// ids sorted by a stable radix sort (a large grid's a slab of x layers at a time); a box over
// too many cells (a section's cap triangle across the mesh) against the boxes in the slab of
// cells it reaches on its thinnest axis; a coarse single cell when such boxes are too many.
#include "algorithms/hlr/intersection_broad_phase.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "algorithms/support/parallel_scan.hpp"
#include "kernel/error_bounds.hpp"

namespace hlr {
namespace {

// A box's entry in one cell. The entries and the radix sort's copy are the broad phase's
// largest arrays: 12 bytes (not 16) for any cell id, 8 (the cell id in the high half of one
// word) when the grid's cells are below 2^32, as for any mesh of fewer than a billion cells.
struct __attribute__((packed)) Entry {
  std::uint64_t cell_;
  std::uint32_t item_;
  Entry() = default;
  Entry(std::uint64_t c, std::uint32_t i) : cell_(c), item_(i) {}
  std::uint64_t cell() const { return cell_; }
  std::uint32_t item() const { return item_; }
};
static_assert(sizeof(Entry) == 12);
struct SmallEntry {
  std::uint64_t word;
  SmallEntry() = default;
  SmallEntry(std::uint64_t c, std::uint32_t i) : word(c << 32 | i) {}
  std::uint64_t cell() const { return word >> 32; }
  std::uint32_t item() const { return static_cast<std::uint32_t>(word); }
};
static_assert(sizeof(SmallEntry) == 8);

struct Cells {
  double lo[3], cell;
  std::int64_t dims[3];
  std::int64_t key(int k, double x) const { return static_cast<std::int64_t>(std::floor((x - lo[k]) / cell)); }
  std::uint64_t id(std::int64_t x, std::int64_t y, std::int64_t z) const {
    return static_cast<std::uint64_t>((x * dims[1] + y) * dims[2] + z);
  }
};

// Huge boxes (over 64 cells) against the others: each against the boxes whose low cells on
// its two thinnest axes k and k2 (counted in cells, with the widest span of those boxes added)
// lie where they can reach it: the layers of cells it reaches on k, and in each layer the run
// of boxes whose low cell on k2 can reach it, from the boxes ordered by their low cells on k,
// then on k2. Long boxes (over kLong cells on some axis, a sliver: one would widen every
// reach) and the huge boxes among themselves pair by pair. pair(i, j, worker) is called for
// every candidate pair once (i huge; when both are, from the lower index).
template <class Box, class Pair>
void huge_box_pairs(std::span<const Box> bb, const Cells& g, const std::vector<std::array<std::int32_t, 3>>& low,
                    const std::vector<std::uint32_t>& big, const ParallelLoop& loop, const Pair& pair) {
  if (big.empty()) return;
  const std::size_t n = bb.size();
  std::vector<char> is_big(n, 0);
  for (std::uint32_t i : big) is_big[i] = 1;
  auto high = [&](std::size_t i, int k) { return g.key(k, bb[i][k + 3]); };
  constexpr std::int64_t kLong = 4;
  std::vector<std::uint32_t> longs;  // boxes over kLong cells on some axis (not huge)
  for (std::size_t i = 0; i < n; ++i) {
    if (is_big[i]) continue;
    bool is_long = false;
    for (int k = 0; k < 3; ++k) is_long = is_long || high(i, k) - low[i][k] > kLong;
    if (is_long) is_big[i] = 2, longs.push_back(static_cast<std::uint32_t>(i));
  }
  PerWorker<std::array<std::int64_t, 3>> widest(loop, {0, 0, 0});  // of the ordered boxes, in cells
  loop.run(n, 8192, [&](unsigned w, std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i)
      for (int k = 0; k < 3 && !is_big[i]; ++k) widest[w][k] = std::max(widest[w][k], high(i, k) - low[i][k]);
  });
  std::array<std::int64_t, 3> W = {0, 0, 0};
  for (unsigned w = 0; w < widest.size(); ++w)
    for (int k = 0; k < 3; ++k) W[k] = std::max(W[k], widest[w][k]);
  auto axes_of = [&](std::uint32_t i) {  // the two axes with the fewest cells to read, relative to their length
    std::array<int, 3> a = {0, 1, 2};
    auto share = [&](int k) { return static_cast<double>(high(i, k) - low[i][k] + 1 + W[k]) / static_cast<double>(g.dims[k]); };
    std::sort(a.begin(), a.end(), [&](int x, int y) { return share(x) < share(y) || (share(x) == share(y) && x < y); });
    return std::array<int, 2>{a[0], a[1]};
  };
  // The other boxes in order of their low cell on k, then on k2 (then of index), for each pair
  // of axes a huge box reads; first[c]: where the boxes of layer c on k start.
  struct Order {
    std::vector<std::uint32_t> items;
    std::vector<std::size_t> first;
  };
  std::array<std::array<Order, 3>, 3> orders;
  // (Two stable counting sorts: by the low cell on k2, then on k.)
  auto counting = [&](const std::vector<std::uint32_t>& in, int axis, std::vector<std::size_t>& first) {
    first.assign(static_cast<std::size_t>(g.dims[axis]) + 1, 0);
    for (std::uint32_t j : in) ++first[static_cast<std::size_t>(low[j][axis]) + 1];
    for (std::size_t c = 0; c + 1 < first.size(); ++c) first[c + 1] += first[c];
    std::vector<std::uint32_t> out(in.size());
    std::vector<std::size_t> at(first.begin(), first.end() - 1);
    for (std::uint32_t j : in) out[at[static_cast<std::size_t>(low[j][axis])]++] = j;
    return out;
  };
  std::vector<std::uint32_t> others;
  for (std::size_t j = 0; j < n; ++j)
    if (!is_big[j]) others.push_back(static_cast<std::uint32_t>(j));
  for (std::uint32_t i : big) {
    const std::array<int, 2> axes = axes_of(i);
    const int k = axes[0], k2 = axes[1];
    Order& o = orders[k][k2];
    if (!o.first.empty()) continue;
    std::vector<std::size_t> unused;
    o.items = counting(counting(others, k2, unused), k, o.first);
  }
  loop.run(big.size(), 1, [&](unsigned w, std::size_t b, std::size_t e) {
    for (std::size_t q = b; q < e; ++q) {
      const std::uint32_t i = big[q];
      const std::array<int, 2> axes = axes_of(i);
      const int k = axes[0], k2 = axes[1];
      const Order& o = orders[k][k2];
      const std::int64_t lo = std::max<std::int64_t>(0, low[i][k] - W[k]), hi = std::min<std::int64_t>(g.dims[k] - 1, high(i, k));
      const std::int64_t lo2 = low[i][k2] - W[k2], hi2 = high(i, k2);
      for (std::int64_t c = lo; c <= hi; ++c) {
        const auto begin = o.items.begin() + static_cast<std::ptrdiff_t>(o.first[static_cast<std::size_t>(c)]);
        const auto end = o.items.begin() + static_cast<std::ptrdiff_t>(o.first[static_cast<std::size_t>(c) + 1]);
        auto r = std::lower_bound(begin, end, lo2, [&](std::uint32_t x, std::int64_t v) { return low[x][k2] < v; });
        for (; r != end && low[*r][k2] <= hi2; ++r) pair(i, *r, w);
      }
      for (std::uint32_t j : longs) pair(i, j, w);
      for (std::uint32_t j : big)
        if (j > i) pair(i, j, w);
    }
  });
}

template <class Box>
BoxPairs box_pairs(std::span<const Box> bb, const ParallelLoop& loop, const std::function<PairVerdict(std::uint32_t, std::uint32_t)>& judge,
                   std::size_t slab_entries, BoxCorners corners) {
  BoxPairs out;
  const std::size_t n = bb.size();
  if (n < 2) return out;
  // Sums, extents and finiteness per fixed chunk on all cores, then combined in chunk order
  // (the same cell size on any number of threads).
  constexpr std::size_t kChunk = 16384;
  struct Part {
    double mean = 0, lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    bool finite = true;
  };
  std::vector<Part> parts((n + kChunk - 1) / kChunk);
  loop.for_each(parts.size(), 1, [&](std::size_t c) {
    Part& p = parts[c];
    for (std::size_t i = c * kChunk, e = std::min(n, i + kChunk); i < e; ++i) {
      const Box& b = bb[i];
      p.mean += std::max({double(b[3]) - b[0], double(b[4]) - b[1], double(b[5]) - b[2]});
      for (int k = 0; k < 3; ++k) p.lo[k] = std::min<double>(p.lo[k], b[k]), p.hi[k] = std::max<double>(p.hi[k], b[k + 3]);
      for (double x : b) p.finite = p.finite && std::isfinite(x);
    }
  });
  double mean = 0;
  Cells g;
  double hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (int k = 0; k < 3; ++k) g.lo[k] = INFINITY;
  bool finite = true;
  for (const Part& p : parts) {
    mean += p.mean;
    for (int k = 0; k < 3; ++k) g.lo[k] = std::min(g.lo[k], p.lo[k]), hi[k] = std::max(hi[k], p.hi[k]);
    finite = finite && p.finite;
  }
  g.cell = std::max(2 * mean / static_cast<double>(n), 1e-300);
  // Doubles that lost the scene (coordinates beyond their range: infinities, NaN) or cells too
  // many to index: one coarse list. Checked before any cell index is formed.
  bool coarse = !std::isfinite(g.cell) || !std::isfinite(mean) || !finite;
  for (int k = 0; k < 3 && !coarse; ++k) {
    const double d = std::floor((hi[k] - g.lo[k]) / g.cell);
    if (!(d < (1 << 20))) coarse = true;
    else g.dims[k] = static_cast<std::int64_t>(d) + 1;
  }
  // A box that spans more than 64 cells (a huge triangle among small ones) stays out of the
  // cells and is tested against every box instead: a few such boxes cost a few linear passes.
  // Each box's cell count on all cores, then its entries into their place (item order).
  std::vector<std::uint32_t> big;
  // Each box's low cell: the low corner of two boxes' overlap lies in the cell of the larger
  // low keys (floor((x - lo) / cell) does not decrease with x), so no division per pair.
  std::vector<std::array<std::int32_t, 3>> low;
  std::vector<std::size_t> at;  // where each box's entries start (a box over 64 cells has none)
  auto span = [&](std::size_t i, std::int64_t* c0, std::int64_t* c1) {
    for (int k = 0; k < 3; ++k) c0[k] = g.key(k, bb[i][k]), c1[k] = g.key(k, bb[i][k + 3]);
    return (c1[0] - c0[0] + 1) * (c1[1] - c0[1] + 1) * (c1[2] - c0[2] + 1);
  };
  if (!coarse) {
    reserve_touched(low, n, loop);  // fresh pages zeroed on all cores, not by the resize alone
    low.resize(n);
    // count is called once per box, so it also records the box's low cell.
    at = parallel_offsets(
        n,
        [&](std::size_t i) -> std::size_t {
          std::int64_t c0[3], c1[3];
          const std::int64_t cells = span(i, c0, c1);
          for (int k = 0; k < 3; ++k) low[i][k] = static_cast<std::int32_t>(c0[k]);  // 0 <= c0 < 2^20
          return cells > 64 ? 0 : static_cast<std::size_t>(cells);
        },
        loop);
    big = parallel_select(
        n,
        [&](std::size_t i) {
          std::int64_t c0[3], c1[3];
          return at[i + 1] == at[i] && span(i, c0, c1) > 64;
        },
        loop);
  }
  if (coarse || big.size() * 8 > n) {  // unusable cells, or too many huge boxes: one coarse list
    coarse = true;
    big.clear();
  }
  struct Found {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> kept;
    std::size_t tested = 0;
  };
  PerWorker<Found> found(loop);
  auto overlap = [&](std::uint32_t ta, std::uint32_t tc) {
    const Box &P = bb[ta], &Q = bb[tc];
    return !(P[0] > Q[3] || Q[0] > P[3] || P[1] > Q[4] || Q[1] > P[4] || P[2] > Q[5] || Q[2] > P[5]);
  };
  auto take = [&](std::uint32_t ta, std::uint32_t tc, unsigned w) {
    PairVerdict v = judge(ta, tc);
    if (v == PairVerdict::Skip) return;
    Found& f = found[w];
    ++f.tested;
    if (v == PairVerdict::Keep) f.kept.push_back({std::min(ta, tc), std::max(ta, tc)});
  };
  // The entries of every box, sorted by cell, and the pairs of each cell; E: Entry, or
  // SmallEntry when every cell id is below 2^32. A large grid's entries are made and sorted a
  // slab of x layers at a time (the cell ids are x-major, so the slabs' cells come in the same
  // order as one sort's), so that the entries and the sort's copy do not hold all of them at once.
  auto cell_pass = [&](auto layout) {
    using E = decltype(layout);
    // A cell's boxes and low cells are read once into a local list (the items lie far apart in
    // the arrays; reading them for every pair cost more than the tests).
    struct Local {
      Box box;
      std::array<std::int32_t, 3> low;
      std::uint32_t item;
      std::array<int, 3> corner;  // (with corners: read here once, not for every pair)
    };
    const bool with_corners = corners.first != nullptr;
    auto pairs_of = [&](std::vector<E>& entries) {
      radix_sort(
          entries, [](const E& e) { return e.cell(); }, loop);  // stable: a cell's boxes in item order
      std::vector<std::size_t> cell_start = parallel_select<std::size_t>(
          entries.size(), [&](std::size_t i) { return i == 0 || entries[i].cell() != entries[i - 1].cell(); }, loop, 1);
      cell_start.push_back(entries.size());
      const std::size_t ncells = cell_start.size() - 1;
      auto cell_pairs = [&](std::size_t i, std::size_t j, unsigned w, std::vector<Local>& cell) {
        cell.clear();
        for (std::size_t a = i; a < j; ++a) {
          const std::uint32_t t = entries[a].item();
          const std::array<int, 3> corner = with_corners ? corners.of(t) : std::array<int, 3>{};
          cell.push_back({bb[t], coarse ? std::array<std::int32_t, 3>{} : low[t], t, corner});
        }
        const std::uint64_t here = entries[i].cell();
        for (std::size_t a = 0; a < cell.size(); ++a)
          for (std::size_t c = a + 1; c < cell.size(); ++c) {
            const Box &P = cell[a].box, &Q = cell[c].box;
            if (P[0] > Q[3] || Q[0] > P[3] || P[1] > Q[4] || Q[1] > P[4] || P[2] > Q[5] || Q[2] > P[5]) continue;
            if (!coarse) {  // the pair only in the cell of the overlap's low corner
              const auto &A = cell[a].low, &B = cell[c].low;
              std::uint64_t own = g.id(std::max(A[0], B[0]), std::max(A[1], B[1]), std::max(A[2], B[2]));
              if (own != here) continue;
            }
            if (with_corners && BoxCorners::share(cell[a].corner, cell[c].corner)) continue;
            take(cell[a].item, cell[c].item, w);
          }
      };
      loop.run(ncells, 256, [&](unsigned w, std::size_t b, std::size_t e) {
        std::vector<Local> cell;
        for (std::size_t c = b; c < e; ++c)
          if (cell_start[c + 1] - cell_start[c] > 1) cell_pairs(cell_start[c], cell_start[c + 1], w, cell);
      });
    };
    if (coarse) {
      std::vector<E> entries;
      entries.reserve(n);
      for (std::size_t i = 0; i < n; ++i) entries.emplace_back(0, static_cast<std::uint32_t>(i));
      pairs_of(entries);
      return;
    }
    const std::size_t total = at[n];
    std::vector<std::size_t>().swap(at);
    const auto slabs =
        static_cast<std::int64_t>(std::min<std::size_t>(total / std::max<std::size_t>(slab_entries, 1) + 1, static_cast<std::size_t>(g.dims[0])));
    const std::int64_t layers = (g.dims[0] + slabs - 1) / slabs;
    for (std::int64_t x0 = 0; x0 < g.dims[0]; x0 += layers) {
      const std::int64_t x1 = std::min(g.dims[0], x0 + layers) - 1;  // the slab's x layers: x0..x1
      // A box's cells in the slab (none for a box over 64 cells).
      auto slab_span = [&](std::size_t i, std::int64_t* c0, std::int64_t* c1) -> std::size_t {
        if (low[i][0] > x1 || span(i, c0, c1) > 64) return 0;  // (low: the box's first cells)
        c0[0] = std::max(c0[0], x0), c1[0] = std::min(c1[0], x1);
        return c1[0] < c0[0] ? 0 : static_cast<std::size_t>((c1[0] - c0[0] + 1) * (c1[1] - c0[1] + 1) * (c1[2] - c0[2] + 1));
      };
      std::vector<std::size_t> first = parallel_offsets(
          n,
          [&](std::size_t i) {
            std::int64_t c0[3], c1[3];
            return slab_span(i, c0, c1);
          },
          loop);
      std::vector<E> entries;
      reserve_touched(entries, first[n], loop);
      entries.resize(first[n]);
      loop.for_each(n, 8192, [&](std::size_t i) {
        if (first[i + 1] == first[i]) return;
        std::int64_t c0[3] = {}, c1[3] = {};  // (set: the box has cells in the slab)
        slab_span(i, c0, c1);
        std::size_t w = first[i];
        for (std::int64_t x = c0[0]; x <= c1[0]; ++x)
          for (std::int64_t y = c0[1]; y <= c1[1]; ++y)
            for (std::int64_t z = c0[2]; z <= c1[2]; ++z) entries[w++] = E(g.id(x, y, z), static_cast<std::uint32_t>(i));
      });
      std::vector<std::size_t>().swap(first);
      pairs_of(entries);
    }
  };
  if (coarse || static_cast<double>(g.dims[0]) * static_cast<double>(g.dims[1]) * static_cast<double>(g.dims[2]) < 4294967296.0)
    cell_pass(SmallEntry{});
  else cell_pass(Entry{});
  huge_box_pairs(bb, g, low, big, loop, [&](std::uint32_t i, std::uint32_t j, unsigned w) {
    if (overlap(i, j) && !(corners.first && BoxCorners::share(corners.of(i), corners.of(j)))) take(std::min(i, j), std::max(i, j), w);
  });
  for (unsigned w = 0; w < found.size(); ++w) {
    out.kept.insert(out.kept.end(), found[w].kept.begin(), found[w].kept.end());
    out.tested += found[w].tested;
  }
  std::sort(out.kept.begin(), out.kept.end());
  return out;
}

}  // namespace

BoxPairs overlapping_box_pairs(std::span<const Box3> boxes, const ParallelLoop& loop,
                               const std::function<PairVerdict(std::uint32_t, std::uint32_t)>& judge, std::size_t slab_entries, BoxCorners corners) {
  return box_pairs(boxes, loop, judge, slab_entries, corners);
}

BoxPairs overlapping_box_pairs(std::span<const Box3f> boxes, const ParallelLoop& loop,
                               const std::function<PairVerdict(std::uint32_t, std::uint32_t)>& judge, std::size_t slab_entries, BoxCorners corners) {
  return box_pairs(boxes, loop, judge, slab_entries, corners);
}

bool outward_floats(const Box3& b, Box3f& out) {
  for (int k = 0; k < 6; ++k) {
    if (!(std::fabs(b[k]) < 1e38)) return false;  // NaN, infinite or near the floats' end
    float f = static_cast<float>(b[k]);
    if (k < 3 && f > b[k]) f = next_float_down(f);
    if (k >= 3 && f < b[k]) f = next_float_up(f);
    out[k] = f;
  }
  return true;
}

}  // namespace hlr
