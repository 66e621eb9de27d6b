// Error messages in Russian for exam mode, in the words of the course notes
// (section 19: body, face, edge, vertex; 21-23: clipper, convexity; 26-28: Roberts).
//
// A template is the English text with placeholders: @x is copied as it is (numbers, names in
// quotes, lists of keys), @w is the name of a value in the file (translated when the table below
// knows it; keys of the file format stay as typed), @m is a nested message (translated by the
// same catalogue). The Russian text names them @1, @2, ... in the English order.
#include "io/explain/messages_ru.hpp"

#include <algorithm>
#include <map>
#include <string_view>
#include <vector>

namespace hlr {
namespace {

struct Entry {
  const char* en;
  const char* ru;
};

// Order matters only where one template is a special case of another: the special one first.
const std::vector<Entry>& catalogue() {
  static const std::vector<Entry> c = {
      // ---- the problem reader (io/explain/problem.cpp)
      {"a problem file needs 'problem: TYPE' (roberts, cyrus-beck, midpoint, convexity, decompose, transform, horizon, weiler-atherton, priority, "
       "raster, ray-tree, section)",
       "в файле задачи нужна строка 'problem: ТИП' (roberts, cyrus-beck, midpoint, convexity, decompose, transform, horizon, weiler-atherton, "
       "priority, raster, ray-tree, section)"},
      {"unknown problem type '@x' (known: roberts, cyrus-beck, midpoint, convexity, decompose, transform, horizon, weiler-atherton, priority, "
       "raster, ray-tree, section)",
       "неизвестный тип задачи '@1' (известны: roberts, cyrus-beck, midpoint, convexity, decompose, transform, horizon, weiler-atherton, priority, "
       "raster, ray-tree, section)"},
      {"a horizon problem takes heights, not bodies", "задача horizon принимает высоты (heights), а не тела (bodies)"},
      {"a raster problem takes an orthographic view (the notes' depth is linear across the picture)",
       "задача raster принимает только параллельную проекцию (глубина в конспекте линейна по картине)"},
      {"size must be [width, height] in pixels", "размер size задаётся как [ширина, высота] в пикселах"},
      {"size: a problem's grid is 1 to 32 pixels each way", "size: сетка задачи — от 1 до 32 пикселов по каждой оси"},
      {"window: x0 < x1 and y0 < y1", "window: нужно x0 < x1 и y0 < y1"},
      {"window: every pixel centre must be a binary fraction (halves, quarters, ...)",
       "window: центр каждого пиксела должен быть двоичной дробью (половины, четверти, ...)"},
      {"trace must be a list of pixels [column, row]", "trace задаётся списком пикселов [столбец, строка]"},
      {"a traced pixel is [column, row]", "прослеживаемый пиксел задаётся как [столбец, строка]"},
      {"the pixel is outside the grid", "пиксел вне сетки"},
      {"a ray-tree problem needs 'ray: {from: [x, y, z], direction: [dx, dy, dz]}'",
       "задаче ray-tree нужен луч 'ray: {from: [x, y, z], direction: [dx, dy, dz]}'"},
      {"the ray's direction has zero length", "направление луча имеет нулевую длину"},
      {"depth must be 0 to 8", "глубина depth — от 0 до 8"},
      {"a horizon problem needs 'heights': one list of heights per cut z = const",
       "задаче horizon нужны высоты 'heights': по списку высот для каждого сечения z = const"},
      {"each row of heights needs at least 2 numbers", "в каждой строке высот нужно не меньше 2 чисел"},
      {"every row of heights must have @x numbers, as the first", "в каждой строке высот должно быть @1 чисел, как в первой"},
      {"@x: from must be below to", "@1: начало должно быть меньше конца"},
      {"title must be text", "title: ожидается текст"},
      {"clipper must be one of {box: [6 numbers]}, {frustum: [7 numbers]}, {mesh: PATH}",
       "отсекатель clipper задаётся одним из: {box: [6 чисел]}, {frustum: [7 чисел]}, {mesh: ПУТЬ}"},
      {"mesh must be a path", "mesh: ожидается путь к файлу"},
      {"unknown clipper '@x' (known: box, frustum, mesh)", "неизвестный отсекатель '@1' (известны: box, frustum, mesh)"},
      {"clipper: @m", "отсекатель: @1"},
      {"not valid YAML/JSON: @m", "файл не является правильным YAML/JSON: @1"},
      {"a problem file must be a mapping with 'problem: TYPE'", "файл задачи должен быть словарём «ключ: значение» с ключом 'problem: ТИП'"},
      {"@x problems take exactly one body", "задача @1 принимает ровно одно тело"},
      {"a section problem needs one cutting plane: 'section: PLANE' (e.g. z<1 or A,B,C,D)",
       "задаче section нужна одна секущая плоскость: 'section: ПЛОСКОСТЬ' (например, z<1 или A,B,C,D)"},
      {"clipping problems take a clipper and segments, not bodies",
       "задача отсечения принимает отсекатель (clipper) и отрезки (segments), а не тела (bodies)"},
      {"edges must be a list of [body, vertex, vertex]", "edges: ожидается список [тело, вершина, вершина]"},
      {"an edge is [body, vertex, vertex]", "ребро задаётся как [тело, вершина, вершина]"},
      {"no body @x", "нет тела @1"},
      {"body @x has no edge @x-@x", "у тела @1 нет ребра @2-@3"},
      {"a clipping problem needs a 'clipper'", "задаче отсечения нужен отсекатель 'clipper'"},
      {"midpoint subdivision needs a box or a frustum", "разбиению средней точкой нужен отсекатель box или frustum"},
      {"a clipping problem needs 'segments': [[x1, y1, z1, x2, y2, z2], ...]",
       "задаче отсечения нужны отрезки 'segments': [[x1, y1, z1, x2, y2, z2], ...]"},
      {"eps must be positive", "точность eps должна быть положительной"},
      // ---- values in a YAML file (io/readers/yaml_context.hpp)
      {"@w must be a list of @x numbers", "@1: ожидается список из @2 чисел"},
      {"@w must be a list of 3 numbers [x, y, z]", "@1: ожидается список из 3 чисел [x, y, z]"},
      {"@w must be a mapping", "@1: ожидается словарь «ключ: значение»"},
      {"keys of @w must be names", "@1: ключи должны быть именами"},
      {"unknown key '@x' in @w (known: @x)", "@2: неизвестный ключ '@1' (известны: @3)"},
      {"key '@x' appears twice in @w", "@2: ключ '@1' встречается дважды"},
      {"@w must be a number", "@1: ожидается число"},
      {"@w must be text", "@1: ожидается текст"},
      {"@w must be an integer", "@1: ожидается целое число"},
      // ---- the Weiler–Atherton algorithm (algorithms/clip/weiler_atherton.cpp)
      {"Weiler-Atherton is for exam-sized scenes: more than @x polygons (use --method faces)",
       "алгоритм Вейлера–Азертона — для задач экзаменного размера: больше @1 многоугольников (используйте --method faces)"},
      {"Weiler-Atherton: body @x reaches the eye's plane or behind it",
       "алгоритм Вейлера–Азертона: тело @1 доходит до плоскости глаза или заходит за неё"},
      {"Weiler-Atherton: recursion did not end", "алгоритм Вейлера–Азертона: рекурсия не закончилась"},
      // ---- a perspective view's frame (io/readers/scene.cpp)
      {"@x shapes a frame: give fov, fov_v or focal", "@1 задаёт форму кадра: укажите fov, fov_v или focal"},
      {"@x must be a list of two numbers [W, H]", "@1: нужен список из двух чисел [W, H]"},
      {"view: @x", "view: @1"},
      {"a frame (fov, fov_v, frame, focal) belongs to a perspective view (with 'eye')",
       "кадр (fov, fov_v, frame, focal) бывает только у перспективного вида (с 'eye')"},
      {"give 'view' or 'camera' (the same keys), not both", "укажите 'view' или 'camera' (ключи те же), но не оба"},
      // ---- view options (io/views/view_choice.cpp)
      {"@x needs three numbers X,Y,Z, got '@x'", "@1: нужны три числа X,Y,Z, получено '@2'"},
      // ---- the ground plane (io/readers/scene.cpp)
      {"ground needs a 'plane' (x = C, y = C or z = C)", "для ground нужна плоскость 'plane' (x = C, y = C или z = C)"},
      {"ground must be a plane x = C, y = C or z = C", "ground должна быть плоскостью x = C, y = C или z = C"},
      {"ground needs bodies to lie under", "для ground нужны тела, которые на ней стоят"},
      {"ground size must be positive", "размер ground должен быть положительным"},
      // ---- the priority list (algorithms/surfaces/priority_list.cpp)
      {"priority list: more than @x polygons after the cuts", "список приоритетов: после разбиений больше @1 многоугольников"},
      {"priority list: body @x reaches the eye's plane or behind it", "список приоритетов: тело @1 доходит до плоскости глаза или заходит за неё"},
      {"priority list: a cyclic overlap that no cut breaks", "список приоритетов: циклическое экранирование, которое не разрешает ни одно разбиение"},
      {"priority list: a cut that made no parts", "список приоритетов: разбиение не дало частей"},
      // ---- lights and materials (io/readers/scene_lighting.cpp)
      {"@w must be between @x and @x", "@1: ожидается число от @2 до @3"},
      {"light direction has zero length", "направление источника света имеет нулевую длину"},
      {"attenuation has zero length", "все коэффициенты затухания attenuation равны нулю"},
      {"@w must be [r, g, b] from 0 to 1 or #rrggbb", "@1: ожидается цвет [r, g, b] от 0 до 1 или #rrggbb"},
      {"a light needs a 'type' (directional, point or spot)", "источнику света нужен тип 'type' (directional, point или spot)"},
      {"light type must be directional, point or spot", "тип источника света type: directional, point или spot"},
      {"transparency_model must be linear, kay or path", "transparency_model: linear, kay или path"},
      {"a @x light needs a 'direction'", "источнику света @1 нужно направление 'direction'"},
      {"a point light has no 'direction'", "у точечного источника point нет направления 'direction'"},
      {"a @x light needs a 'position'", "источнику света @1 нужно положение 'position'"},
      {"a directional light has no 'position' (it is at infinity)",
       "у направленного источника directional нет положения 'position' (он в бесконечности)"},
      {"give 'colour' or 'color', not both", "задайте 'colour' или 'color', но не оба"},
      {"give 'colour2' or 'color2', not both", "задайте 'colour2' или 'color2', но не оба"},
      {"texture '@x' cannot be read as PNG", "текстуру '@1' не удаётся прочитать как PNG"},
      {"ior must be between 1/10 and 10", "показатель преломления ior: ожидается число от 1/10 до 10"},
      {"reflection + transparency must not exceed 1", "сумма reflection + transparency не может быть больше 1"},
      {"a directional light has no attenuation (it is at infinity)",
       "у направленного источника directional нет затухания attenuation (он в бесконечности)"},
      {"attenuation [a0, a1, a2] must not be negative", "коэффициенты затухания attenuation [a0, a1, a2] не могут быть отрицательными"},
      {"'cone' and 'exponent' belong to a spot light", "'cone' и 'exponent' задаются только для прожектора spot"},
      {"specular must be phong or blinn", "модель блика specular: phong или blinn"},
      {"lights must be a list", "lights: ожидается список источников света"},
      // ---- numbers (kernel/number.cpp)
      {"@w: bad number '@x': @m", "@1: неверное число '@2': @3"},
      {"bad number '@x': @m", "неверное число '@1': @2"},
      {"empty", "пусто"},
      {"not a finite number (NaN and infinities are not accepted)", "не конечное число (NaN и бесконечности не принимаются)"},
      {"not a finite number", "не конечное число"},
      {"numerator is not an integer", "числитель не является целым числом"},
      {"denominator is not a positive integer", "знаменатель не является положительным целым числом"},
      {"zero denominator", "знаменатель равен нулю"},
      {"missing exponent", "нет порядка после e"},
      {"no digits", "нет цифр"},
      {"not a number (expected integer, decimal, scientific or fraction)",
       "не число (ожидается целое, десятичная дробь, запись с порядком или простая дробь p/q)"},
      {"bad exponent", "неверный порядок"},
      {"exponent out of range", "порядок вне допустимого диапазона"},
      // ---- the scene part of a problem (io/readers/scene.cpp)
      {"rotate needs an 'axis' (x, y or z)", "поворот rotate: нужна ось 'axis' (x, y или z)"},
      {"axis must be x, y or z", "ось axis: ожидается x, y или z"},
      {"rotate needs exactly one of: degrees, cos + sin, tan_half", "поворот rotate: нужно ровно одно из: degrees, cos + sin, tan_half"},
      {"rotate by cos and sin needs both", "поворот через cos и sin: нужны оба значения"},
      {"cos^2 + sin^2 = @x, not 1: not a rotation", "cos^2 + sin^2 = @1, а не 1: это не поворот"},
      {"give 'centre' or 'center', not both", "укажите 'centre' или 'center', но не оба"},
      {"each transform must be one of: translate, scale, rotate, reflect, matrix",
       "каждое преобразование задаётся одним из: translate, scale, rotate, reflect, matrix"},
      {"scale needs 'factors'", "масштабирование scale: нужны коэффициенты 'factors'"},
      {"a scale factor of 0 flattens the body", "коэффициент масштабирования 0 сплющивает тело"},
      {"reflect needs an 'axis'", "отражение reflect: нужна ось 'axis'"},
      {"reflect axis must be x, y or z (the coordinate that changes sign)", "ось отражения: ожидается x, y или z (координата, которая меняет знак)"},
      {"matrix must be 4 rows of 4 numbers", "матрица matrix: ожидается 4 строки по 4 числа"},
      {"matrix row must have 4 numbers", "в строке матрицы matrix должно быть 4 числа"},
      {"matrix is singular (it flattens the body)", "матрица вырождена (она сплющивает тело)"},
      {"unknown transform '@x' (known: translate, scale, rotate, reflect, matrix)",
       "неизвестное преобразование '@1' (известны: translate, scale, rotate, reflect, matrix)"},
      {"perspective needs at least one non-zero centre distance", "перспективному преобразованию нужно хотя бы одно ненулевое расстояние до центра"},
      {"the transform sends vertex @x through infinity (w <= 0)", "преобразование переводит вершину @1 через бесконечность (w <= 0)"},
      {"point @x goes to infinity (w = 0)", "точка @1 уходит в бесконечность (w = 0)"},
      {"an inline body needs both 'vertices' and 'faces'", "телу, заданному в файле, нужны и вершины 'vertices', и грани 'faces'"},
      {"vertices must be a non-empty list of [x, y, z]", "вершины vertices: ожидается непустой список [x, y, z]"},
      {"faces must be a non-empty list of vertex index lists", "грани faces: ожидается непустой список списков номеров вершин"},
      {"face @x must be a list of vertex indices", "грань @1: ожидается список номеров вершин"},
      {"face @x uses vertex @x, but there are only @x vertices", "грань @1 ссылается на вершину @2, а вершин всего @3"},
      {"face @x has fewer than 3 vertices", "у грани @1 меньше 3 вершин"},
      {"face @x has @x vertices; a face needs at least 3", "у грани @1 вершин: @2; у грани должно быть не меньше 3"},
      {"view has both 'direction' (orthographic) and 'eye' (perspective)",
       "в виде view заданы и 'direction' (параллельная проекция), и 'eye' (центральная проекция)"},
      {"view direction has zero length", "направление взгляда имеет нулевую длину"},
      {"'target' belongs to a perspective view (with 'eye')", "'target' задаётся только для центральной проекции (с 'eye')"},
      {"target is the eye point", "точка 'target' совпадает с точкой наблюдения 'eye'"},
      {"view needs 'direction' or 'eye'", "виду view нужно 'direction' или 'eye'"},
      {"up vector has zero length", "вектор 'up' имеет нулевую длину"},
      {"empty scene file", "пустой файл сцены"},
      {"nesting deeper than @x levels", "вложенность глубже @1 уровней"},
      {"the scene needs a 'bodies' list", "в сцене нужен список тел 'bodies'"},
      {"'bodies' must be a non-empty list", "'bodies': ожидается непустой список тел"},
      {"a body needs exactly one of: mesh, vertices + faces, box", "телу нужно ровно одно из: mesh, vertices + faces, box"},
      {"mesh '@x': @m", "файл сетки '@1': @2"},
      {"box needs 'min' and 'max' corners", "параллелепипеду box нужны углы 'min' и 'max'"},
      {"hatch pattern must be single, cross, solid or none, not '@x'",
       "узор штриховки hatch pattern должен быть single, cross, solid или none, а не '@1'"},
      {"hatch spacing must be between 0.05 and 1000 mm", "шаг штриховки hatch spacing должен быть от 0.05 до 1000 мм"},
      {"section must name at least one plane", "в разрезе section нужна хотя бы одна плоскость"},
      {"cut must be true or false", "cut должно быть true или false"},
      {"box min must be below max in x, y and z", "у параллелепипеда box угол min должен быть меньше max по x, y и z"},
      {"transform must be a list of steps", "transform: ожидается список шагов"},
      {"light vector has zero length", "вектор 'light' имеет нулевую длину"},
      {"the up vector @x is parallel to the viewing direction @x: give another up vector (--up X,Y,Z, or up: in the scene's view)",
       "вектор up @1 параллелен направлению взгляда @2: задайте другой вектор up (--up X,Y,Z или up: в виде view)"},
      {"give --view (orthographic) or --eye (perspective), not both", "задайте --view (параллельная проекция) или --eye (центральная), но не оба"},
      {"--target needs --eye (a perspective view)", "--target задаётся вместе с --eye (центральная проекция)"},
      {"the eye @x is the default target, the centre of the scene's bounding box: give a target (--target)",
       "точка наблюдения @1 совпадает с точкой 'target' по умолчанию, центром охватывающего параллелепипеда сцены: задайте 'target'"},
      // ---- files (io/readers/text_reader.cpp, io/readers/mesh_reader.cpp)
      {"is a directory, not a file", "это каталог, а не файл"},
      {"is not a regular file", "это не обычный файл"},
      {"is larger than @x GiB, the most hlr reads", "больше @1 ГиБ, а hlr читает не больше"},
      {"cannot open: No such file or directory", "не удаётся открыть: нет такого файла или каталога"},
      {"cannot open: Permission denied", "не удаётся открыть: нет прав доступа"},
      {"cannot open: @x", "не удаётся открыть (@1)"},
      {"read error", "ошибка чтения"},
      {"unknown mesh file extension '@x' (expected .off, .obj, .stl or .ply; standard input: - with --input-format)",
       "неизвестное расширение файла сетки '@1' (ожидается .off, .obj, .stl или .ply; стандартный ввод: - с --input-format)"},
      {"unknown mesh format '@x' (expected off, obj, stl or ply)", "неизвестный формат сетки '@1' (ожидается off, obj, stl или ply)"},
      {"standard input needs --input-format (off, obj, stl, ply, yaml or json)",
       "для стандартного ввода нужен --input-format (off, obj, stl, ply, yaml или json)"},
      {"empty mesh: no vertices", "пустая сетка: нет вершин"},
      {"empty mesh: no faces", "пустая сетка: нет граней"},
      // ---- the body matrix and convexity (kernel/body_matrix.cpp, algorithms/solids/convexity.cpp)
      {"face @x has zero area: it has no plane", "грань @1 имеет нулевую площадь: у неё нет плоскости"},
      {"the interior point @x lies on the plane of face @x: the body is flat or not convex",
       "внутренняя точка @1 лежит в плоскости грани @2: тело плоское или невыпуклое"},
      {"the body has no vertices", "у тела нет вершин"},
      {"the transform is singular: it has no inverse", "преобразование вырождено: у него нет обратного"},
      {"not convex: face @x has vertex @x on one side of its plane and vertex @x on the other",
       "невыпуклое: вершина @2 лежит по одну сторону плоскости грани @1, а вершина @3 — по другую"},
      {"flat (degenerate): every vertex lies in every face plane", "плоское (вырожденное): каждая вершина лежит в плоскости каждой грани"},
      {"no faces", "без граней"},
      {"convex", "выпуклое"},
      // ---- a body the algorithm cannot take (algorithms/hlr/roberts*.cpp, face engine)
      {"body @x is @m; Roberts' algorithm takes convex bodies (split non-convex ones into convex pieces first)",
       "тело @1 — @2; алгоритм Робертса работает с выпуклыми телами (невыпуклые сначала разбейте на выпуклые части)"},
      {"body @x is not closed (boundary edge @x)", "тело @1 не замкнуто (граничное ребро @2)"},
      {"body @x is not manifold", "тело @1 не является многообразием"},
      {"body @x is not consistently oriented (edge @x)", "грани тела @1 ориентированы несогласованно (ребро @2)"},
      {"body @x has a degenerate face (face @x: @m)", "у тела @1 вырожденная грань (грань @2: @3)"},
      {"body @x has a non-planar face (face @x, vertex @x is off its plane)", "у тела @1 неплоская грань (грань @2, вершина @3 вне её плоскости)"},
      {"body @x has a non-planar face (face @x)", "у тела @1 неплоская грань (грань @2)"},
      {"body @x has duplicate vertices (@x and @x)", "у тела @1 совпадающие вершины (@2 и @3)"},
      {"body @x has a T-junction (vertex @x inside edge @x)", "у тела @1 Т-образный стык (вершина @2 внутри ребра @3)"},
      {"body @x has a self-intersecting face (face @x)", "у тела @1 самопересекающаяся грань (грань @2)"},
      {"body @x has a degenerate face (face @x)", "у тела @1 вырожденная грань (грань @2)"},
      {"body @x contains the eye @x: an eye inside a solid sees nothing", "тело @1 содержит точку наблюдения @2: изнутри тела ничего не видно"},
      {"body @x holds the eye @x on its surface and is not convex: move the eye off the surface (by any amount)",
       "точка наблюдения @2 лежит на поверхности невыпуклого тела @1: сдвиньте её с поверхности (на любую величину)"},
      {"body @x is not a valid closed solid: its volume is not positive (inside out)",
       "тело @1 не является правильным замкнутым телом: его объём не положителен (нормали внутрь)"},
      {"body @x is not a valid closed solid: @m", "тело @1 не является правильным замкнутым телом: @2"},
      {"body @x has a component with negative volume (the one with face @x: inside out, or a cavity): Roberts' algorithm "
       "takes solids without; use --method faces",
       "у тела @1 есть компонента с отрицательным объёмом (та, что с гранью @2: вывернута нормалями внутрь или это полость): "
       "алгоритм Робертса работает только с телами без таких компонент"},
      {"body @x decomposes into convex pieces of volume @x != its volume @x (its components overlap: give each solid as "
       "its own body, or use --method faces)",
       "тело @1 разбивается на выпуклые части общим объёмом @2, а его объём @3 (его компоненты пересекаются: задайте каждое "
       "тело отдельно)"},
      {"repeated vertex @x", "вершина @1 повторяется"},
      {"collinear vertices", "вершины на одной прямой"},
      {"edge @x is in three or more faces (not manifold)", "ребро @1 принадлежит трём или более граням (не многообразие)"},
      {"vertex @x joins separate fans of faces (not manifold)", "вершина @1 соединяет несвязанные веера граней (не многообразие)"},
      {"edge @x is in one face only (not closed)", "ребро @1 принадлежит только одной грани (тело не замкнуто)"},
      {"edge @x is traversed twice in one direction (faces not consistently oriented)",
       "ребро @1 обходится дважды в одном направлении (грани ориентированы несогласованно)"},
      {"face @x is not planar (vertex @x is off its plane)", "грань @1 неплоская (вершина @2 вне её плоскости)"},
      {"face @x is degenerate (@m)", "грань @1 вырождена (@2)"},
      {"face @x crosses itself", "грань @1 самопересекается"},
      {"vertices @x and @x are the same point", "вершины @1 и @2 совпадают"},
      {"vertex @x lies inside edge @x (a T-junction)", "вершина @1 лежит внутри ребра @2 (Т-образный стык)"},
      // ---- clippers (algorithms/clip/cyrus_beck.cpp, midpoint_clip.cpp)
      {"the clipper '@x' is not a closed, manifold, oriented solid with planar non-degenerate faces",
       "отсекатель '@1' не является замкнутым ориентированным многогранником-многообразием с плоскими невырожденными гранями"},
      {"the clipper '@x' is @m; Cyrus-Beck needs a convex clipper", "отсекатель '@1' — тело @2; алгоритму Кируса–Бека нужен выпуклый отсекатель"},
      {"box clipper: need XMIN < XMAX, YMIN < YMAX, ZMIN < ZMAX", "отсекатель box: нужно XMIN < XMAX, YMIN < YMAX, ZMIN < ZMAX"},
      {"frustum clipper: need XL < XR and YB < YT", "отсекатель frustum: нужно XL < XR и YB < YT"},
      {"frustum clipper: need ZCP > ZNEAR > ZFAR (viewer on +z)", "отсекатель frustum: нужно ZCP > ZNEAR > ZFAR (наблюдатель на +z)"},
      {"midpoint clipping needs a tolerance eps > 0", "разбиению средней точкой нужна точность eps > 0"},
      // ---- convex decomposition (algorithms/solids/convex_decomposition.cpp)
      {"convex decomposition needs an outward-oriented solid: the volume is not positive",
       "разбиению на выпуклые части нужно тело с внешними нормалями: его объём не положителен"},
      {"convex decomposition needs a valid solid: @m", "разбиению на выпуклые части нужно правильное замкнутое тело: @1"},
      {"convex decomposition does not terminate (depth 256)", "разбиение на выпуклые части не завершается (глубина 256)"},
      // ---- the YAML parser's own messages (yaml-cpp)
      {"end of map not found", "не найден конец словаря"},
      {"end of map flow not found", "не найден конец словаря в фигурных скобках"},
      {"end of sequence not found", "не найден конец списка"},
      {"end of sequence flow not found", "не найден конец списка в квадратных скобках"},
      {"illegal map value", "недопустимое значение словаря"},
      {"illegal map key", "недопустимый ключ словаря"},
      {"illegal block entry", "недопустимый элемент блока"},
      {"illegal flow end", "недопустимая закрывающая скобка"},
      {"unknown token", "неизвестная лексема"},
      {"illegal character in scalar", "недопустимый символ в значении"},
      {"illegal EOF in scalar", "файл кончился внутри значения"},
      {"illegal document indicator in scalar", "недопустимый признак документа в значении"},
      {"unexpected character in block scalar", "неожиданный символ в блочном значении"},
      {"unknown escape character: @x", "неизвестная экранированная последовательность: @1"},
      {"the referenced anchor is not defined", "упомянутая метка (anchor) не определена"},
      {"invalid scalar", "неверное значение"},
  };
  return c;
}

// Names of values in the files, as the readers pass them to "@w must be ...": the keys of the
// file format stay as typed (they are what the student writes), descriptions are translated.
const std::map<std::string, std::string>& what_words() {
  static const std::map<std::string, std::string> w = {
      {"body", "тело"},
      {"vertex", "вершина"},
      {"vertex index", "номер вершины"},
      {"scale factors", "коэффициенты масштабирования"},
      {"reflect axis", "ось отражения"},
      {"matrix entry", "элемент матрицы"},
      {"view direction", "направление взгляда"},
      {"the scene", "сцена"},
      {"the problem", "задача"},
      {"a body", "тело"},
      {"box min", "угол min параллелепипеда box"},
      {"box max", "угол max параллелепипеда box"},
      {"a segment [x1, y1, z1, x2, y2, z2]", "отрезок [x1, y1, z1, x2, y2, z2]"},
      {"box [xmin, xmax, ymin, ymax, zmin, zmax]", "параллелепипед box [xmin, xmax, ymin, ymax, zmin, zmax]"},
      {"frustum [xl, xr, yb, yt, znear, zfar, zcp]", "пирамида видимости frustum [xl, xr, yb, yt, znear, zfar, zcp]"},
      {"height", "высота"},
      {"a light", "источник света"},
      {"a material", "материал"},
      {"light direction", "направление источника света"},
      {"light position", "положение источника света"},
      {"light colour", "цвет источника света"},
      {"light intensity", "яркость источника света"},
      {"light type", "тип источника света"},
      {"colour", "цвет"},
      {"x [from, to]", "x [начало, конец]"},
      {"z [from, to]", "z [начало, конец]"},
  };
  return w;
}

// A template split into literal text and placeholders ('x', 'w', 'm').
struct Part {
  std::string literal;
  char kind = 0;  // 0: literal
};

std::vector<Part> split(std::string_view t) {
  std::vector<Part> parts;
  std::string lit;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] == '@' && i + 1 < t.size() && (t[i + 1] == 'x' || t[i + 1] == 'w' || t[i + 1] == 'm')) {
      if (!lit.empty()) parts.push_back({lit, 0});
      lit.clear();
      parts.push_back({{}, t[i + 1]});
      ++i;
    } else {
      lit += t[i];
    }
  }
  if (!lit.empty()) parts.push_back({lit, 0});
  return parts;
}

// Matches `text` from `pos` against parts[k..]; placeholders take the shortest non-empty text
// after which the rest matches (a nested message @m takes the longest). Backtracking over the
// occurrences of the next literal: templates have few parts, so this is quick on any text.
bool match(const std::vector<Part>& parts, std::size_t k, std::string_view text, std::size_t pos,
           std::vector<std::string>& args) {
  if (k == parts.size()) return pos == text.size();
  const Part& p = parts[k];
  if (p.kind == 0) {
    if (text.compare(pos, p.literal.size(), p.literal) != 0) return false;
    return match(parts, k + 1, text, pos + p.literal.size(), args);
  }
  if (k + 1 == parts.size()) {
    if (pos >= text.size()) return false;
    args.emplace_back(text.substr(pos));
    return true;
  }
  const std::string& next = parts[k + 1].literal;  // placeholders are always separated by text
  std::vector<std::size_t> at;
  for (std::size_t f = text.find(next, pos + 1); f != std::string_view::npos; f = text.find(next, f + 1)) at.push_back(f);
  if (p.kind == 'm') std::reverse(at.begin(), at.end());
  for (std::size_t f : at) {
    args.emplace_back(text.substr(pos, f - pos));
    if (match(parts, k + 1, text, f, args)) return true;
    args.resize(args.size() - 1);
  }
  return false;
}

std::string fill(std::string_view ru, const std::vector<std::string>& values) {
  std::string out;
  for (std::size_t i = 0; i < ru.size(); ++i) {
    if (ru[i] == '@' && i + 1 < ru.size() && ru[i + 1] >= '1' && ru[i + 1] <= '9') {
      std::size_t n = static_cast<std::size_t>(ru[i + 1] - '1');
      if (n < values.size()) out += values[n];
      ++i;
    } else {
      out += ru[i];
    }
  }
  return out;
}

std::string translate(const std::string& en, bool& ok, int depth) {
  if (depth > 8) {
    ok = false;
    return en;
  }
  for (const Entry& e : catalogue()) {
    std::vector<Part> parts = split(e.en);
    std::vector<std::string> args;
    if (!match(parts, 0, en, 0, args)) continue;
    std::size_t a = 0;
    for (const Part& p : parts) {
      if (p.kind == 0) continue;
      std::string& v = args[a++];
      if (p.kind == 'm') {
        v = translate(v, ok, depth + 1);
      } else if (p.kind == 'w') {
        auto it = what_words().find(v);
        if (it != what_words().end()) v = it->second;
      }
    }
    return fill(e.ru, args);
  }
  // "PATH: message" or "PATH:LINE: message" (a nested reader error): the place stays.
  for (std::size_t c = en.find(": "); c != std::string::npos; c = en.find(": ", c + 1)) {
    std::string_view place(en.data(), c);
    if (place.find(' ') != std::string_view::npos) break;
    if (place.find('/') == std::string_view::npos && place.find('.') == std::string_view::npos) continue;
    return std::string(place) + ": " + translate(en.substr(c + 2), ok, depth + 1);
  }
  ok = false;
  return en;
}

}  // namespace

std::string message_ru(const std::string& english, bool* translated) {
  bool ok = true;
  std::string out = translate(english, ok, 0);
  if (translated) *translated = ok;
  return out;
}

std::vector<std::string> message_ru_templates() {
  std::vector<std::string> out;
  for (const Entry& e : catalogue()) out.emplace_back(e.en);
  return out;
}

}  // namespace hlr
