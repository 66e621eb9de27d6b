// 3MF models (see threemf_reader.hpp; docs/design.md, "Models").
#include "io/models/threemf_reader.hpp"

#include <Model/COM/NMR_DLLInterfaces.h>

#include <algorithm>
#include <filesystem>

#include "io/models/mesh_assembly.hpp"
#include "io/readers/input_error.hpp"

namespace hlr {

namespace {

// One lib3mf interface, released when it goes out of scope.
class Handle3mf {
 public:
  Handle3mf() = default;
  Handle3mf(const Handle3mf&) = delete;
  Handle3mf& operator=(const Handle3mf&) = delete;
  ~Handle3mf() {
    if (p_) NMR::lib3mf_release(p_);
  }
  NMR::PLib3MFBase** out() { return &p_; }
  NMR::PLib3MFBase* get() const { return p_; }

 private:
  NMR::PLib3MFBase* p_ = nullptr;  // lib3mf's handles are pointers to its void* classes
};

struct Reader {
  const std::string& path;
  Model& out;
  long dropped = 0;

  void check(LIB3MFRESULT r, NMR::PLib3MFBase* from, const std::string& what) const {
    if (r == 0) return;
    DWORD code = 0;
    LPCSTR message = nullptr;
    if (from) NMR::lib3mf_getlasterror(from, &code, &message);
    throw InputError(path, 0, what + (message && *message ? std::string(": ") + message : std::string()));
  }

  static Matrix4 matrix(const NMR::MODELTRANSFORM& t) {
    // lib3mf keeps the column-vector matrix's three rows; the row-vector matrix is its transpose.
    Matrix4 m = identity_transform();
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 3; ++j) m(i, j) = Rational(t.m_fFields[j][i]);
    return m;
  }

  std::string name_of(NMR::PLib3MFBase* object) const {
    ULONG needed = 0;
    if (NMR::lib3mf_object_getnameutf8(object, nullptr, 0, &needed) != 0 || needed == 0) return "";
    std::string s(needed + 1, '\0');
    if (NMR::lib3mf_object_getnameutf8(object, s.data(), needed + 1, &needed) != 0) return "";
    s.resize(std::min<std::size_t>(needed, s.size()));
    while (!s.empty() && s.back() == '\0') s.pop_back();
    return s;
  }

  void add_mesh(NMR::PLib3MFBase* object, const Matrix4& m, const std::string& name) {
    DWORD nv = 0, nt = 0;
    check(NMR::lib3mf_meshobject_getvertexcount(object, &nv), object, "reading a mesh");
    check(NMR::lib3mf_meshobject_gettrianglecount(object, &nt), object, "reading a mesh");
    std::vector<NMR::MODELMESHVERTEX> v(nv);
    std::vector<NMR::MODELMESHTRIANGLE> t(nt);
    if (nv > 0) check(NMR::lib3mf_meshobject_getvertices(object, v.data(), nv, nullptr), object, "reading vertices");
    if (nt > 0) check(NMR::lib3mf_meshobject_gettriangleindices(object, t.data(), nt, nullptr), object, "reading triangles");
    FloatBody b;
    b.name = name;
    b.transform = m;
    for (const NMR::MODELMESHVERTEX& p : v) b.positions.push_back({p.m_fPosition[0], p.m_fPosition[1], p.m_fPosition[2]});
    for (const NMR::MODELMESHTRIANGLE& x : t) {
      for (DWORD i : x.m_nIndices)
        if (i >= nv) throw InputError(path, 0, "'" + name + "': a triangle's vertex index is out of range");
      b.triangles.push_back({static_cast<int>(x.m_nIndices[0]), static_cast<int>(x.m_nIndices[1]), static_cast<int>(x.m_nIndices[2])});
    }
    if (!b.triangles.empty()) out.bodies.push_back(assemble_body(b, dropped));
  }

  void add_object(NMR::PLib3MFBase* object, const Matrix4& m, const std::string& above, int depth) {
    if (depth > 64) throw InputError(path, 0, "components nest deeper than 64 levels");
    std::string name = name_of(object);
    if (name.empty()) name = above;
    BOOL is_mesh = false, is_components = false;
    check(NMR::lib3mf_object_ismeshobject(object, &is_mesh), object, "reading an object");
    check(NMR::lib3mf_object_iscomponentsobject(object, &is_components), object, "reading an object");
    if (is_mesh) return add_mesh(object, m, name);
    if (!is_components) return;
    DWORD n = 0;
    check(NMR::lib3mf_componentsobject_getcomponentcount(object, &n), object, "reading components");
    for (DWORD k = 0; k < n; ++k) {
      Handle3mf c, child;
      check(NMR::lib3mf_componentsobject_getcomponent(object, k, c.out()), object, "reading a component");
      check(NMR::lib3mf_component_getobjectresource(c.get(), child.out()), c.get(), "reading a component");
      BOOL has = false;
      Matrix4 local = identity_transform();
      check(NMR::lib3mf_component_hastransform(c.get(), &has), c.get(), "reading a component");
      if (has) {
        NMR::MODELTRANSFORM t;
        check(NMR::lib3mf_component_gettransform(c.get(), &t), c.get(), "reading a transform");
        local = matrix(t);
      }
      add_object(child.get(), compose(local, m), name + "/" + std::to_string(k + 1), depth + 1);
    }
  }

  void read_build(NMR::PLib3MFBase* model) {
    Handle3mf items;
    check(NMR::lib3mf_model_getbuilditems(model, items.out()), model, "reading the build");
    BOOL more = false;
    int k = 0;
    while (NMR::lib3mf_builditemiterator_movenext(items.get(), &more) == 0 && more) {
      Handle3mf item, object;
      check(NMR::lib3mf_builditemiterator_getcurrent(items.get(), item.out()), items.get(), "reading the build");
      check(NMR::lib3mf_builditem_getobjectresource(item.get(), object.out()), item.get(), "reading a build item");
      BOOL has = false;
      Matrix4 m = identity_transform();
      check(NMR::lib3mf_builditem_hasobjecttransform(item.get(), &has), item.get(), "reading a build item");
      if (has) {
        NMR::MODELTRANSFORM t;
        check(NMR::lib3mf_builditem_getobjecttransform(item.get(), &t), item.get(), "reading a transform");
        m = matrix(t);
      }
      add_object(object.get(), m, "item " + std::to_string(++k), 0);
    }
  }
};

std::string unit_name(DWORD u, std::vector<std::string>& notes) {
  switch (u) {
    case NMR::MODELUNIT_MICROMETER:
      return "um";
    case NMR::MODELUNIT_MILLIMETER:
      return "mm";
    case NMR::MODELUNIT_CENTIMETER:
      return "cm";
    case NMR::MODELUNIT_INCH:
      return "in";
    case NMR::MODELUNIT_FOOT:
      return "ft";
    case NMR::MODELUNIT_METER:
      return "m";
    default:
      notes.push_back("unknown unit in the file: millimetres assumed");
      return "mm";
  }
}

}  // namespace

bool is_3mf_file(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return e == ".3mf";
}

Model read_3mf_file(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) throw InputError(path, 0, "cannot open file");
  Model out;
  out.z_up = true;
  Reader r{path, out, 0};
  Handle3mf model, reader;
  r.check(NMR::lib3mf_createmodel(model.out()), nullptr, "lib3mf could not make a model");
  r.check(NMR::lib3mf_model_queryreader(model.get(), "3mf", reader.out()), model.get(), "lib3mf has no 3MF reader");
  r.check(NMR::lib3mf_reader_readfromfileutf8(reader.get(), path.c_str()), reader.get(), "not a 3MF file lib3mf can read");
  DWORD unit = NMR::MODELUNIT_MILLIMETER;
  r.check(NMR::lib3mf_model_getunit(model.get(), &unit), model.get(), "reading the unit");
  out.units = unit_name(unit, out.notes);
  r.read_build(model.get());
  note_dropped(r.dropped, out.notes);
  if (out.bodies.empty()) throw InputError(path, 0, "the file's build holds no triangles");
  return out;
}

}  // namespace hlr
