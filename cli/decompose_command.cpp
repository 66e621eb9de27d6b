// `hlr decompose MESH -o OUT`: convex decomposition of closed solids (course notes section 23),
// written as OFF (exact coordinates; faces colored by origin) with a report of the pieces.
#include <filesystem>
#include <iostream>
#include <sstream>

#include "algorithms/solids/convex_decomposition.hpp"
#include "algorithms/support/progress.hpp"
#include "cli/arguments.hpp"
#include "cli/commands.hpp"
#include "io/writers/atomic_file.hpp"
#include "io/readers/scene.hpp"

namespace hlr::cli {
namespace {

struct DecomposeArgs {
  std::string input, output, method = "planes";
  bool progress = false, quiet = false;
};

// A coordinate as exact text: a terminating decimal when there is one, else p/q (which hlr
// reads exactly; see docs/output-format.md).
std::string exact_text(const Rational& q) {
  mpz_class d = q.get_den();
  int twos = 0, fives = 0;
  while (mpz_divisible_ui_p(d.get_mpz_t(), 2)) d /= 2, ++twos;
  while (mpz_divisible_ui_p(d.get_mpz_t(), 5)) d /= 5, ++fives;
  if (d != 1) return to_string(q);
  int places = std::max(twos, fives);
  mpz_class scale;
  mpz_ui_pow_ui(scale.get_mpz_t(), 10, places);
  mpz_class n = q.get_num() * scale / q.get_den();
  bool neg = n < 0;
  std::string digits = mpz_class(abs(n)).get_str();
  if (places == 0) return (neg ? "-" : "") + digits;
  while (static_cast<int>(digits.size()) <= places) digits = "0" + digits;
  std::string s = digits.substr(0, digits.size() - places) + "." + digits.substr(digits.size() - places);
  return (neg ? "-" : "") + s;
}

const char* color(FaceOrigin o) {
  switch (o) {
    case FaceOrigin::Surface: return "0.8 0.8 0.8";
    case FaceOrigin::Cut: return "0.9 0.2 0.2";
    case FaceOrigin::Mixed: break;
  }
  return "0.9 0.6 0.2";
}

std::string off_text(const std::vector<const ConvexPiece*>& pieces, const std::string& source) {
  std::size_t nv = 0, nf = 0;
  for (const ConvexPiece* p : pieces) nv += p->body.num_vertices(), nf += p->body.num_faces();
  std::ostringstream o;
  o << "OFF\n# " << pieces.size() << " convex piece(s) of " << source << " (hlr decompose). Exact coordinates.\n"
    << "# Face colors: 0.8 0.8 0.8 on the original surface, 0.9 0.2 0.2 on a cut, 0.9 0.6 0.2 both.\n"
    << nv << " " << nf << " 0\n";
  for (const ConvexPiece* p : pieces)
    for (const Point3& v : p->body.vertices()) o << exact_text(v.x()) << " " << exact_text(v.y()) << " " << exact_text(v.z()) << "\n";
  std::size_t base = 0;
  for (const ConvexPiece* p : pieces) {
    for (std::size_t f = 0; f < p->body.num_faces(); ++f) {
      o << p->body.faces()[f].size();
      for (int v : p->body.faces()[f]) o << " " << base + v;
      o << " " << color(p->faces[f]) << "\n";
    }
    base += p->body.num_vertices();
  }
  return o.str();
}

int run_decompose(const DecomposeArgs& a) {
  Scene scene = is_scene_file(a.input) ? load_scene(a.input) : scene_from_mesh(a.input);
  DecompositionMethod m = a.method == "nef" ? DecompositionMethod::Nef : DecompositionMethod::FacePlanes;
  std::vector<Decomposition> all;
  ProgressLine line("decompose", a.progress, a.quiet);
  for (const SceneBody& b : scene.bodies) {
    try {
      all.push_back(convex_decomposition(b.body, m));
    } catch (const std::invalid_argument& e) {
      std::cerr << "hlr decompose: " << b.source << ": body '" << b.name << "': " << e.what() << "\n";
      return 1;
    }
  }
  std::vector<const ConvexPiece*> pieces;
  for (std::size_t i = 0; i < all.size(); ++i) {
    Rational total = 0;
    std::size_t counts[3] = {0, 0, 0};
    for (const ConvexPiece& p : all[i].pieces) {
      pieces.push_back(&p);
      total += six_volume(p.body);
      for (FaceOrigin o : p.faces) ++counts[static_cast<int>(o)];
    }
    Rational input = six_volume(scene.bodies[i].body);
    std::cout << scene.bodies[i].source << ": body '" << scene.bodies[i].name << "': " << all[i].pieces.size()
              << " convex piece(s) (method " << a.method << "), faces " << counts[0] << " surface, " << counts[1] << " cut, "
              << counts[2] << " surface+cut; volume " << to_string(total / 6) << (total == input ? " = " : " != ")
              << "input volume " << to_string(input / 6) << "\n";
    if (total != input) return 1;
  }
  if (a.output.empty()) return 0;
  namespace fs = std::filesystem;
  bool folder = a.output.back() == '/' || fs::is_directory(a.output);
  if (!folder) {
    write_file_atomically(a.output, off_text(pieces, a.input));
    return 0;
  }
  fs::create_directories(a.output);
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "piece_%03zu.off", k);
    write_file_atomically((fs::path(a.output) / name).string(), off_text({pieces[k]}, a.input));
  }
  return 0;
}

}  // namespace

void add_decompose_command(CLI::App& app, int& exit_code) {
  auto a = std::make_shared<DecomposeArgs>();
  CLI::App* cmd = app.add_subcommand("decompose", "Split closed solids into convex pieces (course notes section 23)");
  cmd->add_option("input", a->input, "Mesh file or scene file")->required();
  cmd->add_flag("--progress", a->progress, "Say what it is doing on standard error (default: when it is a terminal)");
  cmd->add_flag("--quiet", a->quiet, "No progress messages");
  cmd->add_option("-o", a->output,
                  "Output: FILE.off (every piece as a separate component of one mesh) or a folder DIR/ (piece_000.off, ...)");
  cmd->add_option("--method", a->method, "planes (default: split by face planes, the course's method) or nef (CGAL's convex_decomposition_3)")
      ->check(CLI::IsMember({"planes", "nef"}));
  cmd->callback([a, &exit_code] { exit_code = run_decompose(*a); });
}

}  // namespace hlr::cli
