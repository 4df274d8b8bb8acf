#pragma once
// Reads a 3MF file back with lib3mf, for the tests of paved.3mf.
#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <Model/COM/NMR_DLLInterfaces.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace paver::test {

// What lib3mf reads back from a file: the unit, the mesh objects (name, type, size) and the
// components of the "stones" and "beads" objects.
struct ReadBack3mf {
  DWORD unit = 0;
  struct Mesh {
    std::string name;
    DWORD type = 0;
    DWORD vertices = 0, triangles = 0;
    std::vector<glm::dvec3> positions;
  };
  std::map<DWORD, Mesh> meshes;  // by resource id
  struct Component {
    DWORD object = 0;
    NMR::MODELTRANSFORM transform{};
  };
  std::vector<Component> components;       // of the "stones" object
  std::vector<Component> bead_components;  // of the "beads" object, when there are beads
  std::vector<NMR::MODELTRANSFORM> build_items;
};

inline std::string object_name_3mf(NMR::PLib3MFBase* object) {
  ULONG needed = 0;
  NMR::lib3mf_object_getnameutf8(object, nullptr, 0, &needed);
  std::string name(needed + 1, '\0');  // the count leaves out the terminating zero
  NMR::lib3mf_object_getnameutf8(object, name.data(), ULONG(name.size()), &needed);
  while (!name.empty() && name.back() == '\0') name.pop_back();
  return name;
}

// Where transform t puts point v.
inline glm::dvec3 apply_3mf(const NMR::MODELTRANSFORM& t, glm::dvec3 v) {
  glm::dvec3 out;
  for (int row = 0; row < 3; ++row)
    out[row] = t.m_fFields[row][0] * v.x + t.m_fFields[row][1] * v.y + t.m_fFields[row][2] * v.z + t.m_fFields[row][3];
  return out;
}

inline ReadBack3mf read_3mf(const std::filesystem::path& path) {
  ReadBack3mf r;
  NMR::PLib3MFBase* model = nullptr;
  EXPECT_EQ(NMR::lib3mf_createmodel(&model), LIB3MF_OK);
  NMR::PLib3MFBase* reader = nullptr;
  EXPECT_EQ(NMR::lib3mf_model_queryreader(model, "3mf", &reader), LIB3MF_OK);
  EXPECT_EQ(NMR::lib3mf_reader_readfromfileutf8(reader, path.string().c_str()), LIB3MF_OK) << path;
  NMR::lib3mf_release(reader);
  NMR::lib3mf_model_getunit(model, &r.unit);

  NMR::PLib3MFBase* meshes = nullptr;
  NMR::lib3mf_model_getmeshobjects(model, &meshes);
  BOOL more = false;
  while (NMR::lib3mf_resourceiterator_movenext(meshes, &more) == LIB3MF_OK && more) {
    NMR::PLib3MFBase* object = nullptr;
    NMR::lib3mf_resourceiterator_getcurrent(meshes, &object);
    DWORD id = 0;
    NMR::lib3mf_resource_getresourceid(object, &id);
    ReadBack3mf::Mesh& m = r.meshes[id];
    m.name = object_name_3mf(object);
    NMR::lib3mf_object_gettype(object, &m.type);
    NMR::lib3mf_meshobject_getvertexcount(object, &m.vertices);
    NMR::lib3mf_meshobject_gettrianglecount(object, &m.triangles);
    for (DWORD v = 0; v < m.vertices; ++v) {
      NMR::MODELMESHVERTEX vertex;
      NMR::lib3mf_meshobject_getvertex(object, v, &vertex);
      m.positions.emplace_back(vertex.m_fPosition[0], vertex.m_fPosition[1], vertex.m_fPosition[2]);
    }
    NMR::lib3mf_release(object);
  }
  NMR::lib3mf_release(meshes);

  NMR::PLib3MFBase* groups = nullptr;
  NMR::lib3mf_model_getcomponentsobjects(model, &groups);
  while (NMR::lib3mf_resourceiterator_movenext(groups, &more) == LIB3MF_OK && more) {
    NMR::PLib3MFBase* object = nullptr;
    NMR::lib3mf_resourceiterator_getcurrent(groups, &object);
    const std::string name = object_name_3mf(object);
    EXPECT_TRUE(name == "stones" || name == "beads") << name;
    std::vector<ReadBack3mf::Component>& into = name == "beads" ? r.bead_components : r.components;
    DWORD count = 0;
    NMR::lib3mf_componentsobject_getcomponentcount(object, &count);
    for (DWORD c = 0; c < count; ++c) {
      NMR::PLib3MFBase* component = nullptr;
      NMR::lib3mf_componentsobject_getcomponent(object, c, &component);
      ReadBack3mf::Component& k = into.emplace_back();
      NMR::lib3mf_component_getobjectresourceid(component, &k.object);
      NMR::lib3mf_component_gettransform(component, &k.transform);
      NMR::lib3mf_release(component);
    }
    NMR::lib3mf_release(object);
  }
  NMR::lib3mf_release(groups);

  NMR::PLib3MFBase* items = nullptr;
  NMR::lib3mf_model_getbuilditems(model, &items);
  while (NMR::lib3mf_builditemiterator_movenext(items, &more) == LIB3MF_OK && more) {
    NMR::PLib3MFBase* item = nullptr;
    NMR::lib3mf_builditemiterator_getcurrent(items, &item);
    NMR::lib3mf_builditem_getobjecttransform(item, &r.build_items.emplace_back());
    NMR::lib3mf_release(item);
  }
  NMR::lib3mf_release(items);
  NMR::lib3mf_release(model);
  return r;
}

}  // namespace paver::test
