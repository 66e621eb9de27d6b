// Exam mode, clipping (see explain_parts.hpp; course notes sections 21-22).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "algorithms/clip/cyrus_beck.hpp"
#include "algorithms/clip/midpoint_clip.hpp"
#include "io/explain/explain_parts.hpp"

namespace hlr::explain_parts {

// The name of face `f` of a box or viewing-pyramid clipper (in their face order), as a word id.
std::string face_name(const std::string& clipper, int f) {
  static const char* box[] = {"left", "right", "bottom", "top", "back", "front"};
  static const char* frustum[] = {"left", "right", "bottom", "top", "near", "far"};
  if (f < 0 || f >= 6) return "-";
  if (clipper.rfind("box ", 0) == 0) return box[f];
  if (clipper.rfind("frustum ", 0) == 0) return frustum[f];
  return "-";
}

// The viewing pyramid as the notes write it: the coefficients α1..δ2 of the side planes and the
// test functions f of each plane at both ends (f_right = x − zα1 − α2 > 0: right of the right
// plane, ...; f_near = z − z_near > 0: nearer than the near plane; f_far = z − z_far).
void frustum_tables(const FrustumWindow& w, const Point3& p1, const Point3& p2, Section& sec) {
  J& c = sec.table("coefficients", {"side", "c1", "c2"});
  c.push_back({"right", "α1 = " + q(w.alpha1()), "α2 = " + q(w.alpha2())});
  c.push_back({"left", "β1 = " + q(w.beta1()), "β2 = " + q(w.beta2())});
  c.push_back({"top", "γ1 = " + q(w.gamma1()), "γ2 = " + q(w.gamma2())});
  c.push_back({"bottom", "δ1 = " + q(w.delta1()), "δ2 = " + q(w.delta2())});
  J& f = sec.table("test_functions", {"end", "f_right", "f_left", "f_top", "f_bottom", "f_near", "f_far"});
  for (auto [name, p] : {std::make_pair("P1", &p1), std::make_pair("P2", &p2)}) {
    const Rational &x = p->x(), &y = p->y(), &z = p->z();
    f.push_back({name, q(x - z * w.alpha1() - w.alpha2()), q(x - z * w.beta1() - w.beta2()), q(y - z * w.gamma1() - w.gamma2()),
                 q(y - z * w.delta1() - w.delta2()), q(z - w.znear), q(z - w.zfar)});
  }
}

// "box [..]" / "frustum [..]" / "mesh F" in the course's Russian words.
std::string clipper_ru(const std::string& en) {
  for (auto [from, to] : {std::pair<std::string, std::string>{"box ", "параллелепипед "}, {"frustum ", "пирамида видимости "},
                          {"mesh ", "выпуклый многогранник "}})
    if (en.rfind(from, 0) == 0) return to + en.substr(from.size());
  return en;
}

J cyrus_beck_solution(const Problem& pr) {
  J out;
  out["sections"] = J::array();
  J results = J::array();
  for (std::size_t i = 0; i < pr.segments.size(); ++i) {
    const auto& [p1, p2] = pr.segments[i];
    CyrusBeckResult r = cyrus_beck(*pr.clipper, p1, p2, true);
    Section sec("cyrus_beck", std::to_string(i + 1));
    sec.value("clipper", pr.clipper_text, clipper_ru(pr.clipper_text));
    sec.value("P1", pt(p1));
    sec.value("P2", pt(p2));
    sec.value("D", vec(p2 - p1));
    J& t = sec.table("cb_table", {"face", "face_name", "n", "Wn", "Dn", "t", "limit"});
    for (const CyrusBeckRow& row : r.table) {
      const char* kind = row.kind == CyrusBeckRow::Kind::Lower ? "lower" : row.kind == CyrusBeckRow::Kind::Upper ? "upper"
                         : row.kind == CyrusBeckRow::Kind::ParallelInside ? "parallel-inside" : "parallel-outside";
      t.push_back({ix(row.face), face_name(pr.clipper_text, row.face), vec(row.n), q(row.wn), q(row.dn),
                   row.t ? q(*row.t) : "-", kind});
    }
    sec.value("t_lower", q(r.t_lower));
    sec.value("t_upper", q(r.t_upper));
    J res;
    res["segment"] = i + 1;
    if (r.visible()) {
      Point3 a = p1 + r.t_lower * (p2 - p1), b = p1 + r.t_upper * (p2 - p1);
      sec.value("visible_part", pt(a) + " - " + pt(b));
      res["visible"] = true;
      res["from"] = pt(a);
      res["to"] = pt(b);
      res["t"] = J::array({q(r.t_lower), q(r.t_upper)});
    } else {
      if (r.status == CyrusBeckResult::Status::Point) {  // t_lower = t_upper: one point
        const std::string at = pt(p1 + r.t_lower * (p2 - p1));
        sec.value("visible_part", "a single point " + at + " (t = " + q(r.t_lower) + ")",
                  "одна точка " + at + " (t = " + q(r.t_lower) + ")");
        res["point"] = at;
      } else {
        sec.value("visible_part", "none");
      }
      res["visible"] = false;
    }
    results.push_back(res);
    out["sections"].push_back(sec.j);
  }
  out["result"]["segments"] = results;
  return out;
}

J midpoint_solution(const Problem& pr) {
  J out;
  out["sections"] = J::array();
  J results = J::array();
  for (std::size_t i = 0; i < pr.segments.size(); ++i) {
    const auto& [p1, p2] = pr.segments[i];
    std::vector<MidpointStep> trace;
    MidpointResult m = midpoint_clip(*pr.window, p1, p2, pr.eps, &trace);
    CyrusBeckResult cb = cyrus_beck(*pr.clipper, p1, p2, false);
    Section sec("midpoint", std::to_string(i + 1));
    sec.value("clipper", pr.clipper_text, clipper_ru(pr.clipper_text));
    sec.value("eps", q(pr.eps));
    if (const auto* fw = std::get_if<FrustumWindow>(&*pr.window)) frustum_tables(*fw, p1, p2, sec);
    J& t = sec.table("outcodes", {"end", "point", "outcode", "notes_outcode"});
    t.push_back({"P1", pt(p1), outcode_bits(outcode(*pr.window, p1)), outcode_bits(notes_outcode(*pr.window, p1))});
    t.push_back({"P2", pt(p2), outcode_bits(outcode(*pr.window, p2)), outcode_bits(notes_outcode(*pr.window, p2))});
    // The notes' trivial tests: both codes zero (inside), or their logical product non-zero
    // (both ends beyond one plane: invisible).
    const auto c1 = outcode(*pr.window, p1), c2 = outcode(*pr.window, p2);
    sec.value("codes_and", outcode_bits(c1 & c2) + ((c1 & c2) != 0 ? " ≠ 0" : " = 0"));
    J& st = sec.table("steps", {"n_step", "phase", "point", "outcode"});
    for (std::size_t k = 0; k < trace.size(); ++k)
      st.push_back({std::to_string(k + 1), trace[k].phase, pt(trace[k].point), outcode_bits(trace[k].code)});
    sec.value("trivial", m.trivially_accepted ? "accepted" : m.trivially_rejected ? "rejected" : "no");
    sec.value("subdivisions", std::to_string(m.subdivisions));
    J res;
    res["segment"] = i + 1;
    res["visible"] = m.visible;
    if (m.visible) {
      sec.value("visible_part", pt(m.from) + " - " + pt(m.to));
      res["from"] = pt(m.from);
      res["to"] = pt(m.to);
    } else {
      sec.value("visible_part", "none");
    }
    if (cb.visible())
      sec.value("exact_part", pt(p1 + cb.t_lower * (p2 - p1)) + " - " + pt(p1 + cb.t_upper * (p2 - p1)));
    results.push_back(res);
    out["sections"].push_back(sec.j);
  }
  out["result"]["segments"] = results;
  return out;
}


}  // namespace hlr::explain_parts
