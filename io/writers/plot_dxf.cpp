// The sheet as DXF through dxflib (see plot_output.hpp): AutoCAD 2000 (AC1015), one layer per
// visibility and line kind with its lineweight, hidden layers with the DASHED linetype (or
// their dashes cut as geometry), each stroke one LWPOLYLINE, millimetres with y up ($INSUNITS
// 4); the sheet's texts (view labels, section letters, the scale caption) as TEXT entities in
// the layer "labels". dxflib
// writes the file's frame; the entities are made on all cores in its format (parallel_text.hpp).
#include <dxflib/dl_dxf.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "io/writers/parallel_text.hpp"
#include "io/writers/plot_output.hpp"

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
                  const PlotStyle& style, bool labels) {
  dw.sectionTables();
  dxf.writeVPort(dw);
  dw.tableLinetypes(4);
  dxf.writeLinetype(dw, DL_LinetypeData("BYBLOCK", "", 0, 0, 0.0));
  dxf.writeLinetype(dw, DL_LinetypeData("BYLAYER", "", 0, 0, 0.0));
  dxf.writeLinetype(dw, DL_LinetypeData("CONTINUOUS", "Solid line", 0, 0, 0.0));
  double dash[2] = {12 * style.weights.at("hidden"), -3 * style.weights.at("hidden")};
  dxf.writeLinetype(dw, DL_LinetypeData("DASHED", "Dashed __ __ __", 0, 2, dash[0] - dash[1], dash));
  dw.tableEnd();
  dw.tableLayers(static_cast<int>(names.size()) + 1 + (labels ? 1 : 0));
  dxf.writeLayer(dw, DL_LayerData("0", 0), DL_Attributes("", 7, -1, 25, "CONTINUOUS"));
  if (labels) dxf.writeLayer(dw, DL_LayerData("labels", 0), DL_Attributes("", 7, -1, 25, "CONTINUOUS"));
  for (std::size_t i = 0; i < names.size(); ++i) {
    const bool dashed = style.pattern_dashed(*layers[i]);
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

constexpr const char* kEntitiesMark = "hlr: the entities go here";

// A number as dxflib writes it: fixed, 16 decimals, trailing zeros cut to one after the point.
void append_real(std::string& d, double v) {
  char buf[512];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, 16);
  char* end = r.ptr;
  const char* dot = std::find(buf, end, '.');
  if (dot != end)
    while (end > dot + 2 && end[-1] == '0') --end;
  d.append(buf, end);
}

// A group: its code right-aligned in three columns, then its value, each on its own line.
void append_code(std::string& d, int code) {
  d += code < 10 ? "  " : code < 100 ? " " : "";
  d += std::to_string(code);
  d += '\n';
}

// Text for a DXF TEXT entity: ASCII as it is, every other character as AutoCAD's \U+XXXX
// (the file's code page is ANSI_1252; "A–A" is "A\U+2013A").
std::string dxf_text(const std::string& utf8) {
  std::string out;
  for (std::size_t i = 0; i < utf8.size();) {
    const unsigned char c = static_cast<unsigned char>(utf8[i]);
    if (c < 0x80) {
      out += static_cast<char>(c);
      ++i;
      continue;
    }
    const int n = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : 2;
    unsigned long cp = c & (n == 4 ? 0x07 : n == 3 ? 0x0F : 0x1F);
    for (int k = 1; k < n && i + k < utf8.size(); ++k) cp = (cp << 6) | (static_cast<unsigned char>(utf8[i + k]) & 0x3F);
    char buf[16];
    std::snprintf(buf, sizeof buf, "\\U+%04lX", cp);
    out += buf;
    i += n;
  }
  return out;
}

// dxflib's writer, which counts the handles it writes, told of those written here.
struct Writer : DL_WriterA {
  using DL_WriterA::DL_WriterA;
  void skip_handles(unsigned long n) const { m_handle += n; }
};

// Each stroke as one LWPOLYLINE of layer `layer` (colour, weight and linetype by layer), y up
// from the sheet's bottom edge; handles from `handle` on, which moves past them.
void append_entities(std::string& out, const PageStrokes& st, const std::string& layer, unsigned long& handle, double height) {
  const unsigned long first = handle;
  append_stroke_text(out, st.size(), [&](std::size_t s) { return st.size(s); },
                     [&](std::string& d, std::size_t s, std::size_t begin, std::size_t end) {
                       d.reserve(200 + 48 * (end - begin));
                       if (begin == 0) {
                         char hex[24];
                         std::snprintf(hex, sizeof hex, "%lX", first + s);
                         d += "  0\nLWPOLYLINE\n  5\n";
                         d += hex;
                         d += "\n100\nAcDbEntity\n  8\n" + layer + "\n 62\n256\n370\n-1\n 48\n1.0\n  6\nBYLAYER\n100\nAcDbPolyline\n";
                         append_code(d, 90);
                         d += std::to_string(st.size(s)) + "\n";
                         append_code(d, 70);
                         d += st.closed(s) ? "1\n" : "0\n";
                       }
                       for (std::size_t i = begin; i < end; ++i) {
                         const Point2 p = st.point(s, i);
                         d += " 10\n";
                         append_real(d, p[0]);
                         d += "\n 20\n";
                         append_real(d, height - p[1]);
                         d += '\n';
                       }
                     });
  handle = first + st.size();
}

// dxflib writes the OBJECTS section without owner handles (group 330 right after an object's
// handle), which DXF readers then repair (ezdxf's audit made 13 fixes): here each object gets
// its owner, the dictionary that lists it (350 or 360), the root dictionary the owner 0.
std::string with_owners(const std::string& frame) {
  const std::string head = "OBJECTS\n";
  const std::size_t begin = frame.find(head);
  if (begin == std::string::npos) return frame;
  const std::size_t end = frame.find("\nENDSEC\n", begin);
  std::vector<std::string> lines;
  std::istringstream in(frame.substr(begin + head.size(), end + 1 - begin - head.size()));
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  auto code = [](const std::string& c) { return std::atoi(c.c_str()); };
  std::map<std::string, std::string> owner;
  std::string dict;
  for (std::size_t i = 0; i + 1 < lines.size(); i += 2) {
    const int c = code(lines[i]);
    if (c == 0) dict = lines[i + 1] == "DICTIONARY" || lines[i + 1] == "ACDBDICTIONARYWDFLT" ? "?" : "";
    if (c == 5 && dict == "?") dict = lines[i + 1];
    if ((c == 350 || c == 360) && !dict.empty() && dict != "?") owner.emplace(lines[i + 1], dict);
  }
  std::string body;
  bool first = true;
  for (std::size_t i = 0; i + 1 < lines.size(); i += 2) {
    body += lines[i] + "\n" + lines[i + 1] + "\n";
    if (code(lines[i]) != 5) continue;
    auto it = owner.find(lines[i + 1]);
    if (it != owner.end() || first) body += "330\n" + (it != owner.end() ? it->second : std::string("0")) + "\n";
    first = false;
  }
  if (lines.size() % 2 == 1) body += lines.back() + "\n";  // the group code of ENDSEC
  return frame.substr(0, begin + head.size()) + body + frame.substr(end + 1);
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
  // Each layer's strokes on the page, in the order the entities are written.
  struct LayerStrokes {
    std::string name;
    PageStrokes strokes;
  };
  std::vector<LayerStrokes> drawn;
  std::size_t entities = 0;
  for (const std::string& n : names)
    for (const SheetView& v : sheet.views)
      for (const PlotLayer& l : v.plot->layers)
        if (l.name() == n) drawn.push_back({n, PageStrokes(v, l, style)}), entities += drawn.back().strokes.size();
  // dxflib writes the header, tables, blocks and objects, with a comment where the entities go;
  // the entities (each stroke a LWPOLYLINE) are made here on all cores in dxflib's format
  // (dxflib flushes its file after every number: 4 s of a 1M-triangle sheet).
  unsigned long handle = 0;
  {
    DL_Dxf dxf;  // writes AutoCAD 2000 unless told otherwise (DL_Dxf::out), as the writer does
    Writer dw(tmpl.c_str(), DL_Codes::AC1015);
    if (dw.openFailed()) throw std::runtime_error("cannot write the DXF");
    dxf.writeHeader(dw);
    dw.dxfString(9, "$INSUNITS");  // millimetres
    dw.dxfInt(70, 4);
    dw.dxfString(9, "$MEASUREMENT");  // metric
    dw.dxfInt(70, 1);
    dw.sectionEnd();
    const std::vector<SheetText> texts = sheet_texts(sheet);
    write_tables(dxf, dw, names, layers, style, !texts.empty());
    dw.sectionEntities();
    for (const SheetText& t : texts) {  // centred (or right-aligned) on their baseline point, y up
      const double x = t.at[0], y = sheet.height_mm - t.at[1];
      dxf.writeText(dw,
                    DL_TextData(x, y, 0, x, y, 0, t.size_mm, 1.0, 0,
                                t.anchor >= 1  ? 2
                                : t.anchor > 0 ? 1
                                               : 0,
                                0, dxf_text(t.text), "Standard", 0.0),
                    DL_Attributes("labels", 256, -1, -1, "BYLAYER"));
    }
    dw.dxfString(999, kEntitiesMark);
    handle = dw.getNextHandle();  // the entities' handles follow the tables', the objects' them
    dw.skip_handles(entities);
    dw.sectionEnd();
    dxf.writeObjects(dw);
    dxf.writeObjectsEnd(dw);
    dw.dxfEOF();
    dw.close();
  }
  std::ifstream in(tmpl, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string frame = with_owners(ss.str());
  const std::string mark = std::string("999\n") + kEntitiesMark + "\n";
  const std::size_t at = frame.find(mark);
  if (at == std::string::npos || frame.find(mark, at + 1) != std::string::npos) throw std::runtime_error("the DXF writer lost its entities' place");
  std::string out = frame.substr(0, at);
  for (const LayerStrokes& d : drawn) append_entities(out, d.strokes, d.name, handle, sheet.height_mm);
  out.append(frame, at + mark.size());
  return out;
}

}  // namespace hlr
