// Exam mode, the words of the course in English and Russian (see explain_parts.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "io/explain_parts.hpp"

namespace hlr::explain_parts {

namespace {

const std::map<std::string, std::pair<std::string, std::string>>& words() {
  static const std::map<std::string, std::pair<std::string, std::string>> w = {
      {"input", {"Input", "Исходные данные"}},
      {"vertices", {"Vertices", "Вершины"}},
      {"faces", {"Faces", "Грани"}},
      {"vertex", {"vertex", "вершина"}},
      {"face", {"face", "грань"}},
      {"body_matrix", {"Body matrix", "Матрица тела"}},
      {"planes", {"Face planes, [S]·[V] and the corrected body matrix", "Плоскости граней, [S]·[V] и исправленная матрица тела"}},
      {"plane", {"plane [a b c d]", "плоскость [a b c d]"}},
      {"S_V", {"[S]·[V]", "[S]·[V]"}},
      {"negated", {"column negated", "столбец умножен на -1"}},
      {"V", {"column of [V]", "столбец [V]"}},
      {"VT", {"[VT] = [T]^-1·[V]", "[VT] = [T]^-1·[V]"}},
      {"T", {"[T]", "[T]"}},
      {"T_inverse", {"[T]^-1", "[T]^-1"}},
      {"interior_point", {"interior point [S]", "внутренняя точка [S]"}},
      {"facing", {"Non-facing faces and hidden edges", "Нелицевые грани и невидимые рёбра"}},
      {"facing_table", {"E·[VT] per face", "E·[VT] для каждой грани"}},
      {"EV", {"E·[VT]", "E·[VT]"}},
      {"class", {"class", "вид"}},
      {"v:non-facing", {"non-facing", "нелицевая"}},
      {"v:facing", {"facing", "лицевая"}},
      {"v:edge-on", {"edge-on", "видна с ребра"}},
      {"v:parallel", {"parallel", "параллельны"}},
      {"v:parallel-inside", {"parallel, inside", "параллельна, внутри"}},
      {"v:parallel-outside", {"parallel, outside", "параллельна, снаружи"}},
      {"v:accepted", {"accepted", "принят"}},
      {"v:rejected", {"rejected", "отброшен"}},
      {"v:point", {"a single point", "одна точка"}},
      {"v:yes", {"yes", "да"}},
      {"v:no", {"no", "нет"}},
      {"v:none", {"none", "нет"}},
      {"v:lower", {"lower", "нижний"}},
      {"v:upper", {"upper", "верхний"}},
      {"face_pair", {"faces", "грани"}},
      {"self_hidden", {"Hidden edges (both faces non-facing)", "Невидимые рёбра (обе грани нелицевые)"}},
      {"edge", {"edge", "ребро"}},
      {"light_table", {"L·[VT] per face (light)", "L·[VT] для каждой грани (свет)"}},
      {"LV", {"L·[VT]", "L·[VT]"}},
      {"self_shadowed", {"self-shadowed", "в собственной тени"}},
      {"visible_shadow", {"visible and in shadow", "видима и в тени"}},
      {"edge_vs_body", {"Edge against body", "Ребро и тело"}},
      {"inequalities", {"p = P1·[VT], q = (P2 - P1)·[VT], w = g·[VT], h_j > 0", "p = P1·[VT], q = (P2 - P1)·[VT], w = g·[VT], h_j > 0"}},
      {"candidates", {"Candidate vertices of the region (pairs of boundary lines)", "Вершины-кандидаты области (пары граничных прямых)"}},
      {"lines", {"lines", "прямые"}},
      {"feasible", {"feasible", "допустима"}},
      {"hidden_interval", {"hidden part of the edge (t)", "скрытая часть ребра (t)"}},
      {"junction_lines", {"Penetration (junction) lines", "Линии протыкания"}},
      {"junctions", {"Junction lines", "Линии протыкания"}},
      {"bodies", {"bodies", "тела"}},
      {"visible_segments", {"Visible segments", "Видимые отрезки"}},
      {"visible", {"Visible pieces", "Видимые части"}},
      {"line", {"line", "линия"}},
      {"from", {"from", "от"}},
      {"to", {"to", "до"}},
      {"cyrus_beck", {"Cyrus-Beck clipping, segment", "Отсечение Кируса-Бека, отрезок"}},
      {"cb_table", {"Per face: inner normal n, W·n, D·n, t = -(W·n)/(D·n)", "Для каждой грани: внутренняя нормаль n, W·n, D·n, t = -(W·n)/(D·n)"}},
      {"n", {"n", "n"}},
      {"Wn", {"W·n", "W·n"}},
      {"Dn", {"D·n", "D·n"}},
      {"limit", {"limit", "предел"}},
      {"lower", {"lower", "нижний"}},
      {"upper", {"upper", "верхний"}},
      {"t_lower", {"t lower", "t нижнее"}},
      {"t_upper", {"t upper", "t верхнее"}},
      {"visible_part", {"visible part", "видимая часть"}},
      {"exact_part", {"exact visible part (Cyrus-Beck)", "точная видимая часть (Кирус-Бек)"}},
      {"midpoint", {"Midpoint subdivision, segment", "Разбиение средней точкой, отрезок"}},
      {"outcodes", {"Outcodes (LRBTNF)", "Коды концов (ЛПНВБД)"}},
      {"outcode", {"outcode", "код"}},
      {"notes_outcode", {"outcode by the notes' rule", "код по правилу конспекта"}},
      {"end", {"end", "конец"}},
      {"point", {"point", "точка"}},
      {"trivial", {"trivially", "тривиально"}},
      {"subdivisions", {"subdivisions", "делений"}},
      {"convexity", {"Convexity test", "Проверка выпуклости"}},
      {"signs", {"Side of every vertex per face plane", "Положение каждой вершины относительно плоскости грани"}},
      {"one_side", {"all on one side", "все с одной стороны"}},
      {"verdict", {"verdict", "вывод"}},
      {"decompose", {"Convex decomposition", "Разбиение на выпуклые части"}},
      {"n_cut", {"cut", "разрез"}},
      {"cuts", {"Cuts (planes of faces at which the body is not convex)", "Разрезы (плоскости граней, относительно которых тело невыпукло)"}},
      {"pieces", {"Pieces", "Части"}},
      {"piece", {"piece", "часть"}},
      {"volume", {"volume", "объём"}},
      {"surface", {"faces on the surface", "граней на поверхности"}},
      {"cut", {"faces on a cut", "граней на разрезе"}},
      {"both", {"faces on both", "граней на обоих"}},
      {"total_volume", {"total volume of the pieces", "суммарный объём частей"}},
      {"body_volume", {"volume of the body", "объём тела"}},
      {"transform", {"Transformation", "Преобразование"}},
      {"vertices_moved", {"Vertices [X]·[T]", "Вершины [X]·[T]"}},
      {"before", {"before", "до"}},
      {"after", {"after", "после"}},
      {"row", {"row", "строка"}},
      {"step", {"[T] of step", "[T] шага"}},
      {"steps", {"Midpoints in order", "Средние точки по порядку"}},
      {"phase", {"phase", "этап"}},
      {"n_step", {"step", "шаг"}},
      {"v:search", {"search for an inside point", "поиск внутренней точки"}},
      {"v:end 1", {"halving toward end 1", "деление к концу 1"}},
      {"v:end 2", {"halving toward end 2", "деление к концу 2"}},
      {"penetration", {"penetration points (a = 0)", "точки протыкания (a = 0)"}},
      {"yes", {"yes", "да"}},
      {"no", {"no", "нет"}},
      {"none", {"none", "нет"}},
      {"clipper", {"clipper", "отсекатель"}},
      {"eps", {"eps", "eps"}},
      {"segment", {"segment", "отрезок"}},
      {"note", {"note", "примечание"}},
      {"problem", {"Problem", "Задача"}},
      {"face_name", {"face of the clipper", "грань отсекателя"}},
      {"reoriented", {"note", "примечание"}},
      {"v:left", {"left", "левая"}},
      {"v:right", {"right", "правая"}},
      {"v:bottom", {"bottom", "нижняя"}},
      {"v:top", {"top", "верхняя"}},
      {"v:back", {"back", "задняя"}},
      {"v:front", {"front", "передняя"}},
      {"v:near", {"near", "ближняя"}},
      {"v:far", {"far", "дальняя"}},
      {"codes_and", {"logical product (AND) of the end codes", "логическое произведение (И) кодов концов"}},
      {"strict_test", {"strict test", "строгая проверка"}},
      {"type:roberts", {"roberts", "алгоритм Робертса"}},
      {"type:cyrus-beck", {"cyrus-beck", "отсечение Кируса-Бека"}},
      {"type:midpoint", {"midpoint", "разбиение средней точкой"}},
      {"type:convexity", {"convexity", "проверка выпуклости"}},
      {"type:decompose", {"decompose", "разбиение на выпуклые части"}},
      {"type:transform", {"transform", "преобразование"}},
      {"step:translate", {"translate", "перенос"}},
      {"step:scale", {"scale", "масштабирование"}},
      {"step:rotate", {"rotate", "поворот"}},
      {"step:reflect", {"reflect", "отражение"}},
      {"step:matrix", {"matrix", "матрица"}},
      {"g", {"g (the viewpoint)", "g (точка наблюдения)"}},
      {"E", {"E = −g", "E = −g"}},
      {"L", {"L = −[light 0] (light: from the scene toward the light source, as E = −[v 0])", "L = −[light 0] (light — направление от сцены к источнику света, как E = −[v 0])"}},
      {"solution", {"Solution", "Решение"}},
      {"drawing", {"Drawing", "Рисунок"}},
      {"region", {"The region of hidden points in the (t, a) plane", "Область скрытых точек на плоскости (t, a)"}},
  };
  return w;
}

}  // namespace

std::string word(const std::string& id, Lang lang) {
  const auto& w = words();
  auto it = w.find(id);
  if (it == w.end()) return id;
  return lang == Lang::Ru ? it->second.second : it->second.first;
}

std::string cell(const J& c, Lang lang) {
  if (c.is_object()) return c.value(lang == Lang::Ru ? "ru" : "en", "");
  std::string s = c.get<std::string>();
  if (words().count("v:" + s)) return word("v:" + s, lang);
  return s;
}


}  // namespace hlr::explain_parts
