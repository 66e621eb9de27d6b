// Chaining edges into the fewest strokes (see path_chaining.hpp).
#include "algorithms/picture/path_chaining.hpp"

#include "algorithms/support/union_find.hpp"

#include <algorithm>
#include <numeric>

namespace hlr {
namespace {

constexpr std::uint32_t kNone = UINT32_MAX;

using Components = UnionFind;

// Degree per vertex, components, and the odd-degree vertices of each component in index order,
// flat: those of root r are odd[at[r] .. at[r + 1]).
struct OddVertices {
  std::vector<std::uint32_t> degree, at, odd;
};

void odd_vertices(std::size_t n, const std::vector<std::array<std::uint32_t, 2>>& edges, Components& comp, OddVertices& o) {
  o.degree.assign(n, 0);
  for (const auto& e : edges) {
    ++o.degree[e[0]], ++o.degree[e[1]];
    comp.unite(e[0], e[1]);
  }
  o.at.assign(n + 1, 0);
  for (std::uint32_t v = 0; v < n; ++v)
    if (o.degree[v] % 2) ++o.at[comp.find(v) + 1];
  for (std::size_t v = 0; v < n; ++v) o.at[v + 1] += o.at[v];
  o.odd.resize(o.at[n]);
  std::vector<std::uint32_t> fill(o.at.begin(), o.at.end() - 1);
  for (std::uint32_t v = 0; v < n; ++v)
    if (o.degree[v] % 2) o.odd[fill[comp.find(v)]++] = v;
}

// Per component (by root) max(1, odd vertices / 2): the fewest strokes.
std::size_t bound(std::size_t n, Components& comp, const OddVertices& o) {
  std::size_t count = 0;
  for (std::uint32_t v = 0; v < n; ++v)
    if (o.degree[v] > 0 && comp.find(v) == v) count += std::max<std::size_t>(1, (o.at[v + 1] - o.at[v]) / 2);
  return count;
}

}  // namespace

std::size_t minimum_chain_count(std::size_t n, const std::vector<std::array<std::uint32_t, 2>>& edges) {
  Components comp(n);
  OddVertices o;
  odd_vertices(n, edges, comp, o);
  return bound(n, comp, o);
}

std::vector<Chain> chain_edges(std::size_t n, const std::vector<std::array<std::uint32_t, 2>>& input, std::size_t* minimum) {
  Components comp(n);
  OddVertices o;
  odd_vertices(n, input, comp, o);
  if (minimum) *minimum = bound(n, comp, o);
  const std::vector<std::uint32_t>& degree = o.degree;
  // All edges: the input's, then the virtual ones pairing odd vertices of a component.
  std::vector<std::array<std::uint32_t, 2>> edges;
  edges.reserve(input.size() + o.odd.size() / 2);
  edges = input;
  const std::size_t real = input.size();
  for (std::uint32_t v = 0; v < n; ++v)
    for (std::uint32_t i = o.at[v]; i + 1 < o.at[v + 1]; i += 2) edges.push_back({o.odd[i], o.odd[i + 1]});
  // Adjacency (CSR), in edge order: deterministic.
  std::vector<std::uint32_t> start(n + 1, 0);
  for (const auto& e : edges) ++start[e[0] + 1], ++start[e[1] + 1];
  for (std::size_t v = 0; v < n; ++v) start[v + 1] += start[v];
  // Each entry holds the edge and the vertex at its other end (one read per step, not two).
  struct Adj {
    std::uint32_t edge, other;
  };
  std::vector<Adj> adj(2 * edges.size());
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::uint32_t i = 0; i < edges.size(); ++i) adj[fill[edges[i][0]]++] = {i, edges[i][1]}, adj[fill[edges[i][1]]++] = {i, edges[i][0]};
  std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
  std::vector<char> used(edges.size(), 0);
  std::vector<Chain> chains;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> stack, circuit;  // (vertex, edge that reached it)
  for (std::uint32_t root = 0; root < n; ++root) {
    if (degree[root] == 0 || comp.find(root) != root) continue;
    std::uint32_t s = o.at[root] == o.at[root + 1] ? root : o.odd[o.at[root]];
    stack.assign(1, {s, kNone});
    circuit.clear();
    while (!stack.empty()) {
      std::uint32_t v = stack.back().first;
      std::uint32_t k = next[v];
      const std::uint32_t end = start[v + 1];
      while (k < end && used[adj[k].edge]) ++k;
      next[v] = k;
      if (k == end) {
        circuit.push_back(stack.back());
        stack.pop_back();
        continue;
      }
      used[adj[k].edge] = 1;
      stack.push_back({adj[k].other, adj[k].edge});
    }
    std::reverse(circuit.begin(), circuit.end());  // v0 (no edge), then (v_i, e_i joining v_{i-1} and v_i)
    const std::size_t m = circuit.size() - 1;     // edges in the circuit
    std::size_t first_virtual = 0;
    for (std::size_t i = 1; i <= m; ++i)
      if (circuit[i].second >= real) {
        first_virtual = i;
        break;
      }
    if (first_virtual == 0) {  // a closed stroke
      Chain c;
      c.closed = true;
      for (std::size_t i = 0; i < m; ++i) c.points.push_back(circuit[i].first);
      for (std::size_t i = 1; i <= m; ++i) c.edges.push_back(circuit[i].second);
      chains.push_back(std::move(c));
      continue;
    }
    Chain c;
    c.points.push_back(circuit[first_virtual].first);
    for (std::size_t k = 1; k <= m; ++k) {
      std::size_t i = (first_virtual + k - 1) % m + 1;  // edges after the first virtual one, around
      if (circuit[i].second >= real) {
        if (!c.edges.empty()) chains.push_back(std::move(c));
        c = Chain{};
        c.points.push_back(circuit[i].first);
      } else {
        c.points.push_back(circuit[i].first);
        c.edges.push_back(circuit[i].second);
      }
    }
    if (!c.edges.empty()) chains.push_back(std::move(c));
  }
  return chains;
}

}  // namespace hlr
