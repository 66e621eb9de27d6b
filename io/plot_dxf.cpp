// The sheet as DXF through dxflib (see plot_output.hpp): AutoCAD 2000 (AC1015), one layer per
// visibility and line kind with its lineweight, hidden layers with the DASHED linetype (or
// their dashes cut as geometry), each stroke one POLYLINE, millimetres with y up.
#include <dxflib/dl_dxf.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "io/plot_output.hpp"

namespace hlr {
namespace {

// DXF lineweights are hundredths of a millimetre from a fixed list.
int lineweight(double mm) {
  static const int list[] = {0, 5, 9, 13, 15, 18, 20, 25, 30, 35, 40, 50, 53, 60, 70, 80, 90, 100, 106, 120, 140, 158, 200, 211};
  int want = static_cast<int>(std::lround(mm * 100)), best = list[0];
  for (int w : list)
    if (std::abs(w - want) < std::abs(best - want)) best = w;
  return best;
}

void write_tables(DL_Dxf& dxf, DL_WriterA& dw, const std::vector<std::string>& names, const std::vector<const PlotLayer*>& layers,
                  const PlotStyle& style) {
  dw.sectionTables();
  dxf.writeVPort(dw);
  dw.tableLinetypes(4);
  dxf.writeLinetype(dw, DL_LinetypeData("BYBLOCK", "", 0, 0, 0.0));
  dxf.writeLinetype(dw, DL_LinetypeData("BYLAYER", "", 0, 0, 0.0));
  dxf.writeLinetype(dw, DL_LinetypeData("CONTINUOUS", "Solid line", 0, 0, 0.0));
  double dash[2] = {12 * style.weights.at("hidden"), -3 * style.weights.at("hidden")};
  dxf.writeLinetype(dw, DL_LinetypeData("DASHED", "Dashed __ __ __", 0, 2, dash[0] - dash[1], dash));
  dw.tableEnd();
  dw.tableLayers(static_cast<int>(names.size()) + 1);
  dxf.writeLayer(dw, DL_LayerData("0", 0), DL_Attributes("", 7, -1, 25, "CONTINUOUS"));
  for (std::size_t i = 0; i < names.size(); ++i) {
    const bool dashed = !layers[i]->visible && !layers[i]->through && style.hidden_dashed && style.dashes == DashMode::Pattern;
    dxf.writeLayer(dw, DL_LayerData(names[i], 0),
                   DL_Attributes("", layers[i]->visible ? 7 : 8, -1, lineweight(style.weight(*layers[i])), dashed ? "DASHED" : "CONTINUOUS"));
  }
  dw.tableEnd();
  dw.tableStyle(1);
  dxf.writeStyle(dw, DL_StyleData("Standard", 0, 2.5, 1.0, 0.0, 0, 2.5, "txt", ""));
  dw.tableEnd();
  dxf.writeView(dw);
  dxf.writeUcs(dw);
  dw.tableAppid(1);
  dxf.writeAppid(dw, "ACAD");
  dw.tableEnd();
  dxf.writeDimStyle(dw, 1, 1, 1, 1, 1);
  dxf.writeBlockRecord(dw);
  dw.tableEnd();
  dw.sectionEnd();
  dw.sectionBlocks();
  dxf.writeBlock(dw, DL_BlockData("*Model_Space", 0, 0.0, 0.0, 0.0));
  dxf.writeEndBlock(dw, "*Model_Space");
  dxf.writeBlock(dw, DL_BlockData("*Paper_Space", 0, 0.0, 0.0, 0.0));
  dxf.writeEndBlock(dw, "*Paper_Space");
  dxf.writeBlock(dw, DL_BlockData("*Paper_Space0", 0, 0.0, 0.0, 0.0));
  dxf.writeEndBlock(dw, "*Paper_Space0");
  dw.sectionEnd();
}

}  // namespace

std::string sheet_to_dxf(const Sheet& sheet, const PlotStyle& style) {
  std::vector<std::string> names = sheet_layer_names(sheet);
  std::vector<const PlotLayer*> layers;
  for (const std::string& n : names)
    for (const SheetView& v : sheet.views) {
      const PlotLayer* found = nullptr;
      for (const PlotLayer& l : v.plot->layers)
        if (l.name() == n) found = &l;
      if (found) {
        layers.push_back(found);
        break;
      }
    }
  // dxflib writes files: a private temporary one, read back and removed.
  std::string tmpl = (std::filesystem::temp_directory_path() / "hlr-dxf-XXXXXX").string();
  int fd = mkstemp(tmpl.data());
  if (fd < 0) throw std::runtime_error("cannot create a temporary file for the DXF writer");
  close(fd);
  struct Remove {
    std::string path;
    ~Remove() { std::remove(path.c_str()); }
  } remove_tmp{tmpl};
  {
    DL_Dxf dxf;
    std::unique_ptr<DL_WriterA> dw(dxf.out(tmpl.c_str(), DL_Codes::AC1015));
    if (!dw) throw std::runtime_error("cannot write the DXF");
    dxf.writeHeader(*dw);
    dw->sectionEnd();
    write_tables(dxf, *dw, names, layers, style);
    dw->sectionEntities();
    for (const std::string& n : names)
      for (const SheetView& v : sheet.views)
        for (const PlotLayer& l : v.plot->layers) {
          if (l.name() != n) continue;
          std::vector<char> closed;
          DL_Attributes attr(n, 256, -1, -1, "BYLAYER");  // colour, weight and linetype by layer
          auto strokes = page_strokes(v, l, style, &closed);
          for (std::size_t s = 0; s < strokes.size(); ++s) {
            dxf.writePolyline(*dw, DL_PolylineData(static_cast<int>(strokes[s].size()), 0, 0, closed[s] ? 1 : 0), attr);
            for (const Point2& p : strokes[s]) dxf.writeVertex(*dw, DL_VertexData(p[0], sheet.height_mm - p[1], 0.0));
            dxf.writePolylineEnd(*dw);
          }
        }
    dw->sectionEnd();
    dxf.writeObjects(*dw);
    dxf.writeObjectsEnd(*dw);
    dw->dxfEOF();
    dw->close();
  }
  std::ifstream in(tmpl, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace hlr
