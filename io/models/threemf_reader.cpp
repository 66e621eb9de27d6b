// 3MF models (see threemf_reader.hpp; docs/design.md, "Models").
#include "io/models/threemf_reader.hpp"

#include <Model/COM/NMR_DLLInterfaces.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <map>

#include "io/models/mesh_assembly.hpp"
#include "io/models/model_module.hpp"
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
  NMR::PLib3MFBase* model = nullptr;
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
    b.colour = mesh_colour(object, nt);
    if (!b.triangles.empty()) out.bodies.push_back(assemble_body(b, dropped));
  }

  using Srgb = std::array<BYTE, 3>;

  // A base material's display colour.
  std::optional<Srgb> base_colour(DWORD group, DWORD index) const {
    Handle3mf material;
    BYTE r = 0, g = 0, b = 0, a = 0;
    if (NMR::lib3mf_model_getbasematerialbyid(model, group, material.out()) != 0 ||
        NMR::lib3mf_basematerial_getdisplaycolor(material.get(), index, &r, &g, &b, &a) != 0)
      return std::nullopt;
    return Srgb{r, g, b};
  }

  // The colour of most of a mesh's triangles (a colour, or a base material's display colour;
  // the first corner's for a gradient), else the object's default property's: the body's colour
  // in --surfaces, as glTF's base colour.
  std::optional<Rgb> mesh_colour(NMR::PLib3MFBase* object, DWORD nt) const {
    std::map<Srgb, long> count;
    Handle3mf h;
    if (nt && NMR::lib3mf_meshobject_createpropertyhandler(object, h.out()) == 0)
      for (DWORD i = 0; i < nt; ++i) {
        NMR::eModelPropertyType type = NMR::MODELPROPERTYTYPE_NONE;
        if (NMR::lib3mf_propertyhandler_getpropertytype(h.get(), i, &type) != 0) continue;
        DWORD group = 0, index = 0;
        NMR::MODELMESH_TRIANGLECOLOR_SRGB c;
        if (type == NMR::MODELPROPERTYTYPE_COLOR && NMR::lib3mf_propertyhandler_getcolor(h.get(), i, &c) == 0)
          ++count[Srgb{c.m_Colors[0].m_Red, c.m_Colors[0].m_Green, c.m_Colors[0].m_Blue}];
        else if (type == NMR::MODELPROPERTYTYPE_BASEMATERIALS && NMR::lib3mf_propertyhandler_getbasematerial(h.get(), i, &group, &index) == 0)
          if (auto m = base_colour(group, index)) ++count[*m];
      }
    if (count.empty()) {  // the object's default property
      Handle3mf d;
      NMR::eModelPropertyType type = NMR::MODELPROPERTYTYPE_NONE;
      DWORD group = 0, index = 0;
      NMR::MODELMESHCOLOR_SRGB c;
      if (NMR::lib3mf_object_createdefaultpropertyhandler(object, d.out()) == 0 &&
          NMR::lib3mf_defaultpropertyhandler_getpropertytype(d.get(), &type) == 0) {
        if (type == NMR::MODELPROPERTYTYPE_COLOR && NMR::lib3mf_defaultpropertyhandler_getcolor(d.get(), 0, &c) == 0)
          ++count[Srgb{c.m_Red, c.m_Green, c.m_Blue}];
        else if (type == NMR::MODELPROPERTYTYPE_BASEMATERIALS && NMR::lib3mf_defaultpropertyhandler_getbasematerial(d.get(), &group, &index) == 0)
          if (auto m = base_colour(group, index)) ++count[*m];
      }
    }
    if (count.empty()) return std::nullopt;
    const auto most = std::max_element(count.begin(), count.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
    return Rgb{most->first[0] / 255.0, most->first[1] / 255.0, most->first[2] / 255.0};
  }

  // An optional transform (a component's or a build item's; identity without one).
  template <class Has, class Get>
  Matrix4 optional_transform(NMR::PLib3MFBase* of, Has has_transform, Get get_transform) const {
    BOOL has = false;
    check(has_transform(of, &has), of, "reading a transform");
    if (!has) return identity_transform();
    NMR::MODELTRANSFORM t;
    check(get_transform(of, &t), of, "reading a transform");
    return matrix(t);
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
      const Matrix4 local = optional_transform(c.get(), NMR::lib3mf_component_hastransform, NMR::lib3mf_component_gettransform);
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
      const Matrix4 m = optional_transform(item.get(), NMR::lib3mf_builditem_hasobjecttransform, NMR::lib3mf_builditem_getobjecttransform);
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

Model models::read_3mf(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) throw InputError(path, 0, "cannot open file");
  Model out;
  out.z_up = true;
  Handle3mf model, reader;
  Reader r{path, out, nullptr, 0};
  r.check(NMR::lib3mf_createmodel(model.out()), nullptr, "lib3mf could not make a model");
  r.model = model.get();
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
