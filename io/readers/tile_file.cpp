// Tile files (see tile_file.hpp).
#include "io/readers/tile_file.hpp"

#include <algorithm>
#include <charconv>
#include <string_view>
#include <sstream>
#include <vector>

#include "algorithms/support/parallel.hpp"
#include "algorithms/picture/picture_tiles.hpp"
#include "io/readers/input_error.hpp"
#include "io/readers/text_reader.hpp"
#include "kernel/number.hpp"

namespace hlr {
namespace {

void mix(std::uint64_t& h, std::int64_t v) {  // FNV-1a over the value's 8 bytes
  for (int k = 0; k < 8; ++k) {
    h ^= static_cast<std::uint64_t>(v >> (8 * k)) & 0xff;
    h *= 0x100000001b3ull;
  }
}

std::string kind_text(const Piece& p) {
  std::string k = p.visible ? "v" : "h";
  if (p.behind_eye) k += 'b';
  if (p.clipped) k += 'c';
  if (p.through) k += 't';
  return k;
}

bool parse_kind(const std::string& k, Piece& p) {
  if (k.empty() || (k[0] != 'v' && k[0] != 'h')) return false;
  p.visible = k[0] == 'v';
  std::size_t at = 1;
  for (char c : {'b', 'c', 't'}) {
    const bool has = at < k.size() && k[at] == c;
    (c == 'b' ? p.behind_eye : c == 'c' ? p.clipped : p.through) = has;
    at += has;
  }
  return at == k.size();
}

// Four fields separated by single spaces, nothing else.
bool split4(std::string_view s, std::string_view (&out)[4]) {
  for (int k = 0; k < 4; ++k) {
    const std::size_t sp = s.find(' ');
    if ((k < 3) != (sp != std::string_view::npos)) return false;
    out[k] = s.substr(0, sp);
    if (out[k].empty()) return false;
    if (k < 3) s = s.substr(sp + 1);
  }
  return true;
}

// Fields separated by single spaces (none empty).
std::vector<std::string_view> fields(std::string_view s) {
  std::vector<std::string_view> out;
  for (;;) {
    const std::size_t sp = s.find(' ');
    out.push_back(s.substr(0, sp));
    if (sp == std::string_view::npos) return out;
    s.remove_prefix(sp + 1);
  }
}

// A whole field as an unsigned number in `base` (no sign, no spaces) that is at most `max`.
bool parse_count(std::string_view s, std::uint64_t max, std::uint64_t& v, int base = 10) {
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v, base);
  return !s.empty() && ec == std::errc() && end == s.data() + s.size() && v <= max;
}

// "N/D" or "N" (get_str()'s form): digits, an optional '-' on N, D > 0.
bool parse_fraction(std::string_view s, Rational& q) {
  if (s.size() > 100000) return false;
  const std::size_t slash = s.find('/');
  auto digits = [](std::string_view d, bool sign) {
    if (sign && !d.empty() && d[0] == '-') d.remove_prefix(1);
    return !d.empty() && std::all_of(d.begin(), d.end(), [](char c) { return c >= '0' && c <= '9'; });
  };
  if (!digits(s.substr(0, slash), true) || (slash != std::string_view::npos && !digits(s.substr(slash + 1), false))) return false;
  const std::string text(s);
  if (mpq_set_str(q.get_mpq_t(), text.c_str(), 10) != 0) return false;
  if (sgn(q.get_den()) <= 0) return false;
  q.canonicalize();  // any form of the fraction is taken
  return true;
}

}  // namespace

std::uint64_t segment_fingerprint(const LineDrawing& d) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  mix(h, static_cast<std::int64_t>(d.segments.size()));
  for (const Segment& s : d.segments)
    for (std::int64_t v : {static_cast<std::int64_t>(s.kind), static_cast<std::int64_t>(s.line), std::int64_t{s.body},
                           std::int64_t{s.body2}, std::int64_t{s.v0}, std::int64_t{s.v1}, std::int64_t{s.face0},
                           std::int64_t{s.face1}, std::int64_t{s.self_hidden}})
      mix(h, v);
  return h;
}

std::string tile_text(const LineDrawing& d, int index, int count, const std::vector<std::string>& args) {
  std::ostringstream out;
  out << "hlr-tile 1\ntile " << index + 1 << " " << count << "\n";
  for (const std::string& a : args) {
    if (a.find('\n') != std::string::npos) throw std::invalid_argument("--tile: an argument with a line break cannot go into a tile file");
    out << "arg " << a << "\n";
  }
  out << "segments " << d.segments.size() << " " << std::hex << segment_fingerprint(d) << std::dec << "\n";
  const FaceRouteStats f = d.stats.faces.value_or(FaceRouteStats{});
  out << "counters " << d.stats.pairs_tested << " " << d.stats.pairs_skipped << " " << d.stats.pairs_rational << " "
      << f.comparisons << " " << f.comparisons_identical << " " << f.comparisons_exact << "\n";
  for (std::size_t i = 0; i < d.segments.size(); ++i)
    for (const Piece& p : d.segments[i].pieces)
      out << "piece " << i << " " << p.t0.get_str() << " " << p.t1.get_str() << " " << kind_text(p) << "\n";
  out << "end\n";
  return out.str();
}

TileFile read_tile(const std::string& path) { return read_tile_text(read_file_bytes(path), path); }

TileFile read_tile_text(const std::string& bytes, const std::string& path) {
  TileFile t;
  int n = 0;
  auto fail = [&](const std::string& what) { throw InputError(path, n, what); };
  bool header = false, tile = false, segments = false, counters = false, end = false;
  // A record given twice is refused: a second 'segments' would change the count the pieces
  // before it were checked against.
  auto once = [&](bool& seen, const char* record) {
    if (seen) fail(std::string("a second '") + record + "' record");
    seen = true;
  };
  for (std::size_t at = 0; at < bytes.size();) {
    std::size_t eol = bytes.find('\n', at);
    if (eol == std::string::npos) eol = bytes.size();
    const std::string_view line(bytes.data() + at, eol - at);
    at = eol + 1;
    ++n;
    if (end) fail("text after 'end'");
    if (!header) {
      if (line != "hlr-tile 1") fail("not an hlr tile file (the first line must be 'hlr-tile 1'; made by hlr render --tile I/N)");
      header = true;
      continue;
    }
    const std::size_t sp = line.find(' ');
    const std::string_view key = line.substr(0, sp);
    if (key == "piece") {
      std::string_view f4[4];
      if (!split4(line.substr(sp + 1), f4)) fail("'piece SEGMENT T0 T1 KIND' expected");
      std::size_t seg = 0;
      const auto [end_at, ec] = std::from_chars(f4[0].data(), f4[0].data() + f4[0].size(), seg);
      if (ec != std::errc() || end_at != f4[0].data() + f4[0].size()) fail("'piece SEGMENT T0 T1 KIND' expected");
      if (!segments || seg >= t.segments) fail("piece of segment " + std::to_string(seg) + ": not a segment of the drawing");
      Piece p;
      if (!parse_fraction(f4[1], p.t0) || !parse_fraction(f4[2], p.t1) || !(sgn(p.t0) >= 0 && p.t0 < p.t1 && p.t1 <= 1))
        fail("piece parameters must be exact fractions N/D (or integers) with 0 <= T0 < T1 <= 1");
      if (!parse_kind(std::string(f4[3]), p)) fail("piece kind '" + std::string(f4[3]) + "': v or h, then b, c, t");
      t.pieces.emplace_back(seg, std::move(p));
      continue;
    }
    const std::string_view rest = sp == std::string_view::npos ? std::string_view() : line.substr(sp + 1);
    const std::vector<std::string_view> f = fields(rest);
    constexpr std::uint64_t any = ~std::uint64_t{0};
    if (key == "arg") {
      t.args.emplace_back(rest);
    } else if (key == "tile") {
      once(tile, "tile");
      std::uint64_t i = 0, c = 0;
      if (f.size() != 2 || !parse_count(f[0], kMaxTiles, i) || !parse_count(f[1], kMaxTiles, c) || c < 1 || i < 1 || i > c)
        fail("'tile I N' with 1 <= I <= N <= " + std::to_string(kMaxTiles) + " expected");
      t.index = static_cast<int>(i - 1), t.count = static_cast<int>(c);
    } else if (key == "segments") {
      once(segments, "segments");
      std::uint64_t count = 0;
      if (f.size() != 2 || !parse_count(f[0], any, count) || !parse_count(f[1], any, t.fingerprint, 16))
        fail("'segments COUNT FINGERPRINT' expected (a decimal count and a hexadecimal hash)");
      t.segments = count;
    } else if (key == "counters") {
      once(counters, "counters");
      std::uint64_t c[6];
      bool ok = f.size() == 6;
      for (std::size_t k = 0; ok && k < 6; ++k) ok = parse_count(f[k], any, c[k]);
      if (!ok) fail("'counters' and six counts expected");
      t.pairs_tested = c[0], t.pairs_skipped = c[1], t.pairs_rational = c[2];
      t.comparisons = c[3], t.comparisons_identical = c[4], t.comparisons_exact = c[5];
    } else if (key == "end") {
      end = true;
    } else {
      fail("unknown record '" + std::string(key) + "'");
    }
  }
  if (!header) fail("empty file: not an hlr tile file");
  if (!tile || !segments) fail("the 'tile' or 'segments' record is missing");
  if (!end) fail("the file ends without 'end' (cut short?)");
  return t;
}

void merge_tiles(LineDrawing& d, const std::vector<TileFile>& tiles, const std::vector<std::string>& paths, unsigned threads) {
  if (tiles.empty()) throw std::invalid_argument("merge: no tile files");
  const TileFile& first = tiles[0];
  const std::uint64_t fingerprint = segment_fingerprint(d);
  std::vector<int> seen(static_cast<std::size_t>(first.count), -1);
  for (std::size_t k = 0; k < tiles.size(); ++k) {
    const TileFile& t = tiles[k];
    if (t.count != first.count) throw InputError(paths[k], 0, "a tile of " + std::to_string(t.count) + " tiles, " + paths[0] + " is one of " + std::to_string(first.count));
    if (t.args != first.args) throw InputError(paths[k], 0, "rendered with other input or options than " + paths[0]);
    if (t.segments != d.segments.size() || t.fingerprint != fingerprint)
      throw InputError(paths[k], 0, "its segments are not the drawing's (the input files changed since the tiles were made?)");
    int& s = seen[static_cast<std::size_t>(t.index)];
    if (s >= 0) throw InputError(paths[k], 0, "tile " + std::to_string(t.index + 1) + " is also " + paths[static_cast<std::size_t>(s)]);
    s = static_cast<int>(k);
  }
  for (std::size_t i = 0; i < seen.size(); ++i)
    if (seen[i] < 0) throw std::invalid_argument("merge: tile " + std::to_string(i + 1) + " of " + std::to_string(first.count) + " is missing");
  for (Segment& s : d.segments) s.pieces.clear();
  FaceRouteStats& f = d.stats.faces ? *d.stats.faces : d.stats.faces.emplace();
  d.stats.pairs_tested = d.stats.pairs_skipped = d.stats.pairs_rational = 0;
  f.comparisons = f.comparisons_identical = f.comparisons_exact = 0;
  for (const TileFile& t : tiles) {
    for (const auto& [i, p] : t.pieces) d.segments[i].pieces.push_back(p);
    d.stats.pairs_tested += t.pairs_tested, d.stats.pairs_skipped += t.pairs_skipped, d.stats.pairs_rational += t.pairs_rational;
    f.comparisons += t.comparisons, f.comparisons_identical += t.comparisons_identical, f.comparisons_exact += t.comparisons_exact;
  }
  std::vector<std::string> errors(d.segments.size());
  ParallelLoop(threads).for_each(d.segments.size(), 1024, [&](std::size_t i) {
    PieceList& pieces = d.segments[i].pieces;
    errors[i] = join_tile_pieces(pieces.edit());
    pieces.compact();
  });
  for (std::size_t i = 0; i < errors.size(); ++i)
    if (!errors[i].empty()) throw std::invalid_argument("merge: segment " + std::to_string(i) + ": " + errors[i]);
}

}  // namespace hlr
