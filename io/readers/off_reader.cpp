// OFF reader with exact coordinates (Geomview OFF: header, counts, vertices, faces; extra
// per-vertex and per-face values such as colours are skipped). Large files are read in chunks
// of lines on every core: a quick pass finds where each chunk of vertex and face lines starts,
// then the chunks are parsed at once; any surprise (a record over several lines, bad text, too
// few lines) falls back to reading the whole file in order, so the result and every error
// message are exactly the sequential reader's.
#include <algorithm>
#include <atomic>
#include <exception>
#include <optional>
#include <string_view>

#include "algorithms/support/parallel.hpp"
#include "io/readers/mesh_reader.hpp"
#include "io/readers/text_reader.hpp"

namespace hlr {
namespace {

struct Header {
  long nv = 0, nf = 0;
};

Header read_header(TokenStream& ts) {
  std::string_view header;
  if (!ts.next(header)) ts.fail("empty file: expected an OFF header");
  std::string h(header);
  bool ok = h.size() >= 3 && h.compare(h.size() - 3, 3, "OFF") == 0 && h.find_first_not_of("STCN") == h.size() - 3;
  if (!ok) ts.fail("expected an OFF header (OFF, COFF, NOFF, STOFF...), found '" + h.substr(0, 40) + "'");
  Header r;
  r.nv = ts.integer("vertex count", 0, 1L << 40);
  r.nf = ts.integer("face count", 0, 1L << 40);
  ts.integer("edge count", 0, 1L << 62);
  ts.skip_rest_of_line();
  // Each vertex needs at least "x y z" (5 bytes), each face at least "3 a b c" (7 bytes).
  if (r.nv * 5 + r.nf * 7 > static_cast<long>(ts.remaining_bytes()) + 1)
    ts.fail("declared " + std::to_string(r.nv) + " vertices and " + std::to_string(r.nf) + " faces, more than the file can hold");
  return r;
}

void read_vertex(TokenStream& ts, Point3& out) {
  out.fill([&](Rational& x, Rational& y, Rational& z) {
    ts.number_into("vertex x", x);
    ts.number_into("vertex y", y);
    ts.number_into("vertex z", z);
  });
  ts.skip_rest_of_line();
}

// A plain decimal (sign, digits, at most one point, at least one digit, 18 digits at most) as
// its digits without the point and the count after it; false for anything else (exponents,
// fractions, longer numbers: those vertices are read as exact rationals instead).
bool plain_decimal(std::string_view t, std::int64_t& mantissa, int& frac) {
  std::size_t i = 0;
  const bool neg = !t.empty() && t[0] == '-';
  if (!t.empty() && (t[0] == '-' || t[0] == '+')) ++i;
  std::int64_t m = 0;
  int digits = 0, after = -1;
  for (; i < t.size(); ++i) {
    const char c = t[i];
    if (c == '.' && after < 0) {
      after = 0;
      continue;
    }
    if (c < '0' || c > '9' || ++digits > 18) return false;
    m = m * 10 + (c - '0');
    if (after >= 0) ++after;
  }
  if (digits == 0) return false;
  mantissa = neg ? -m : m;
  frac = after < 0 ? 0 : after;
  return true;
}

// A vertex of plain decimals: each coordinate's digits and decimal places; false (the stream
// then unspecified) when a coordinate is missing or not a plain decimal.
bool read_vertex_decimals(TokenStream& ts, PointStore::Numerators& out, std::array<std::uint8_t, 3>& frac) {
  for (int k = 0; k < 3; ++k) {
    std::string_view t;
    int f = 0;
    if (!ts.next(t) || !plain_decimal(t, out[k], f)) return false;
    frac[k] = static_cast<std::uint8_t>(f);
  }
  ts.skip_rest_of_line();
  return true;
}

void read_face(TokenStream& ts, long f, long nv, Face& face, int& line) {
  long n = ts.integer("face vertex count", 0, kMaxFaceVertices);
  line = ts.line();
  if (n < 3) ts.fail("face " + std::to_string(f) + " has " + std::to_string(n) + " vertices; a face needs at least 3");
  face.resize(static_cast<std::size_t>(n));
  for (long k = 0; k < n; ++k) face[k] = static_cast<int>(ts.integer("vertex index", 0, std::max(0L, nv - 1)));
  ts.skip_rest_of_line();
}

MeshData read_in_order(TokenStream& ts, const Header& h) {
  MeshData m;
  m.vertices.resize(static_cast<std::size_t>(h.nv));
  for (long i = 0; i < h.nv; ++i) read_vertex(ts, m.vertices[i]);
  m.faces.resize(static_cast<std::size_t>(h.nf));
  m.face_lines.resize(static_cast<std::size_t>(h.nf));
  for (long f = 0; f < h.nf; ++f) read_face(ts, f, h.nv, m.faces[f], m.face_lines[f]);
  return m;
}

// The start (offset, line) of every k-th line holding a token (TokenStream skips blanks and
// '#' comments) among the first `nv` such lines from `at` (line `line`), the vertices', and among
// the `nf` after them, the faces'; each list ends with where the line after its last record
// starts. Lines are counted on all cores: blocks of about a MiB cut at line starts, each
// block's records and newlines counted, then marked from the sums before it. False when the
// text has fewer such lines than nv + nf, or more (a token after the faces).
struct Mark {
  std::size_t at;
  int line;
};
bool mark_records(std::string_view t, std::size_t at, int line, long nv, long nf, long k, std::vector<Mark>& vm,
                  std::vector<Mark>& fm, const ParallelLoop& loop) {
  constexpr std::size_t kBlock = std::size_t{1} << 20;
  std::vector<std::size_t> starts{at};
  for (std::size_t s = at + kBlock; s < t.size();) {
    const std::size_t eol = t.find('\n', s);
    if (eol == std::string_view::npos || eol + 1 >= t.size()) break;
    starts.push_back(eol + 1);
    s = eol + 1 + kBlock;
  }
  starts.push_back(t.size());
  const std::size_t blocks = starts.size() - 1;
  auto holds_token = [&](std::size_t p) {
    while (p < t.size() && (t[p] == ' ' || t[p] == '\t' || t[p] == '\r' || t[p] == '\f' || t[p] == '\v')) ++p;
    return p < t.size() && t[p] != '\n' && t[p] != '#';
  };
  // Calls line_at(start, next line's start, has a newline) for each line of block b.
  auto each_line = [&](std::size_t b, auto&& line_at) {
    for (std::size_t p = starts[b]; p < starts[b + 1];) {
      const std::size_t eol = t.find('\n', p);
      const std::size_t next = eol == std::string_view::npos ? t.size() : eol + 1;
      line_at(p, next);
      p = next;
    }
  };
  std::vector<long> records(blocks + 1, 0), lines(blocks + 1, 0);
  loop.for_each(blocks, 1, [&](std::size_t b) {
    long r = 0, n = 0;
    each_line(b, [&](std::size_t p, std::size_t) {
      r += holds_token(p);
      ++n;
    });
    records[b + 1] = r, lines[b + 1] = n;
  });
  for (std::size_t b = 0; b < blocks; ++b) records[b + 1] += records[b], lines[b + 1] += lines[b];
  if (records[blocks] != nv + nf) return false;
  vm.assign(static_cast<std::size_t>((nv + k - 1) / k + 1), Mark{at, line});
  fm.assign(static_cast<std::size_t>((nf + k - 1) / k + 1), Mark{at, line});
  loop.for_each(blocks, 1, [&](std::size_t b) {
    long r = records[b];
    int l = line + static_cast<int>(lines[b]);
    each_line(b, [&](std::size_t p, std::size_t next) {
      if (holds_token(p)) {
        if (r < nv) {
          if (r % k == 0) vm[static_cast<std::size_t>(r / k)] = {p, l};
          if (r == nv - 1) vm.back() = {next, l + 1};
        } else {
          const long f = r - nv;
          if (f % k == 0) fm[static_cast<std::size_t>(f / k)] = {p, l};
        }
        if (r == nv + nf - 1 && nf > 0) fm.back() = {next, l + 1};
        ++r;
      }
      ++l;
    });
  });
  if (nf == 0) fm.front() = vm.back();  // no faces: they end where the vertices do
  return true;
}

// The vertices' digits over 10^d, d the most decimal places of any coordinate: each brought to
// d places. False when d or a numerator passes the compact store's limit (below 2^53, point_store.hpp).
bool compact_vertices(std::vector<PointStore::Numerators> nums, const std::vector<std::array<std::uint8_t, 3>>& frac, int d, const ParallelLoop& loop,
                      PointStore& out) {
  std::int64_t pow10[19] = {1};
  for (int i = 1; i < 19; ++i) pow10[i] = pow10[i - 1] * 10;
  if (d > 15) return false;  // 10^16 > 2^53
  PerWorker<char> fits(loop, 1);
  loop.run(nums.size(), 16384, [&](unsigned w, std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i)
      for (int k = 0; k < 3; ++k) {
        const std::int64_t f = pow10[d - frac[i][k]], a = nums[i][k] < 0 ? -nums[i][k] : nums[i][k];
        if (a > PointStore::kLimit / f) fits[w] = 0;
        else nums[i][k] *= f;
      }
  });
  for (unsigned w = 0; w < fits.size(); ++w)
    if (!fits[w]) return false;
  out = PointStore(std::move(nums), pow10[d]);
  return true;
}

constexpr long kChunk = 4096;  // lines per chunk
constexpr long kParallelFrom = 8 * kChunk;

// The chunks, or nullopt when a surprise sends the file to the sequential reader.
std::optional<MeshData> read_in_chunks(std::string_view bytes, const std::string& file, std::size_t at, int line, const Header& h) {
  // The rest of the file must hold no token (the sequential reader ignores it too, but a
  // record spread over lines would end there: leave such files to it).
  const ParallelLoop loop;
  std::vector<Mark> vm, fm;
  if (!mark_records(bytes, at, line, h.nv, h.nf, kChunk, vm, fm, loop)) return std::nullopt;
  MeshData m;
  reserve_touched(m.faces, static_cast<std::size_t>(h.nf), loop);  // fresh pages zeroed on all cores
  reserve_touched(m.face_lines, static_cast<std::size_t>(h.nf), loop);
  m.faces.resize(static_cast<std::size_t>(h.nf));
  m.face_lines.resize(static_cast<std::size_t>(h.nf));
  const std::size_t vchunks = vm.size() - 1, fchunks = fm.size() - 1;
  std::vector<char> ok(vchunks + fchunks, 1);
  // The vertices first as plain decimals (compact_vertices): digits and decimal places.
  std::vector<PointStore::Numerators> nums;
  std::vector<std::array<std::uint8_t, 3>> frac;
  std::vector<std::uint8_t> places(vchunks, 0);  // each chunk's most decimal places
  reserve_touched(nums, static_cast<std::size_t>(h.nv), loop);
  reserve_touched(frac, static_cast<std::size_t>(h.nv), loop);
  nums.resize(static_cast<std::size_t>(h.nv));
  frac.resize(static_cast<std::size_t>(h.nv));
  bool decimals = true;
  std::atomic<bool> plain{true};
  auto chunk = [&](std::size_t c, bool compact) {
    const bool faces = c >= vchunks;
    const std::vector<Mark>& mk = faces ? fm : vm;
    const std::size_t k = faces ? c - vchunks : c;
    const long first = static_cast<long>(k) * kChunk, last = std::min(first + kChunk, faces ? h.nf : h.nv);
    TokenStream ts(bytes.substr(0, mk[k + 1].at), file, mk[k].at, mk[k].line);
    try {
      for (long i = first; i < last; ++i) {
        if (faces) read_face(ts, i, h.nv, m.faces[i], m.face_lines[i]);
        else if (!compact) read_vertex(ts, m.vertices[i]);
        else if (!plain.load(std::memory_order_relaxed) || !read_vertex_decimals(ts, nums[i], frac[i])) {
          plain.store(false, std::memory_order_relaxed);  // the other chunks stop too
          return void(ok[c] = 0);
        } else places[k] = std::max({places[k], frac[i][0], frac[i][1], frac[i][2]});
      }
      ok[c] = ts.at_end();  // exactly its lines
    } catch (const std::exception&) {
      ok[c] = 0;
    }
  };
  loop.for_each(vchunks + fchunks, 1, [&](std::size_t c) { chunk(c, true); });
  if (std::find(ok.begin() + vchunks, ok.end(), 0) != ok.end()) return std::nullopt;
  decimals = std::find(ok.begin(), ok.begin() + vchunks, 0) == ok.begin() + vchunks;
  if (decimals) {
    const int d = places.empty() ? 0 : *std::max_element(places.begin(), places.end());
    decimals = compact_vertices(std::move(nums), frac, d, loop, m.compact);
  }
  if (decimals) return m;
  nums = {}, frac = {};
  // Exact rationals: the vertices' construction (three GMP numbers each), then their chunks.
  reserve_touched(m.vertices, static_cast<std::size_t>(h.nv), loop);  // fresh pages zeroed on all cores
  m.vertices.resize(static_cast<std::size_t>(h.nv));
  std::fill(ok.begin(), ok.begin() + vchunks, 1);
  loop.for_each(vchunks, 1, [&](std::size_t c) { chunk(c, false); });
  if (std::find(ok.begin(), ok.end(), 0) != ok.end()) return std::nullopt;
  return m;
}

}  // namespace

MeshData read_off(std::string_view bytes, const std::string& file) {
  TokenStream ts(bytes, file);
  const Header h = read_header(ts);
  if (h.nv + h.nf >= kParallelFrom)
    if (auto m = read_in_chunks(bytes, file, ts.position(), ts.position_line(), h)) return std::move(*m);
  return read_in_order(ts, h);
}

}  // namespace hlr
