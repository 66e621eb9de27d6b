// The methods of `hlr render`, one row each (docs/design.md, "Adding a method"): the enum, the
// name on the command line, in Python and in messages, the step that draws its lines (or
// no_lines: the method only makes polygons, so it implies surfaces), the step that makes its
// polygons (or no_polygons: it draws lines only), what else it takes, and one line of help.
// The enum RenderMethod, the lookups and the function declarations are made from this list;
// each step lives in its own file in io/pipeline/methods/.
#pragma once

// X(enum, name, lines step, polygons step, flags, help)
#define HLR_RENDER_METHODS(X)                                                                                                                \
  X(Faces, "faces", faces_lines, faces_polygons, kTakesShadows | kTakesTiles, "the default: per-face occluders, any mesh")                   \
  X(Roberts, "roberts", roberts_lines, no_polygons, kChecksSolids, "the course's algorithm; non-convex solids are split into convex pieces") \
  X(WeilerAtherton, "weiler-atherton", no_lines, weiler_atherton_polygons, 0,                                                                \
    "the course's visible-surface algorithm, exam-sized scenes; implies --surfaces")                                                         \
  X(Priority, "priority", no_lines, priority_polygons, 0,                                                                                    \
    "the course's priority-list painter's algorithm: shaded faces and their cut parts painted back to front")
