// Meshes load through assimp from STL (ASCII and binary), OBJ, COLLADA and 3DS, and from no other
// format.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>

#include "ambf_like/mesh.hpp"
#include "test_files.hpp"

namespace {

using ambf_like::Vec3;
using ::testing::HasSubstr;

/// A tetrahedron: the expected result of every file below.
const std::vector<Vec3> kCorners = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

void expectTetrahedron(const ambf_like::Mesh& mesh) {
  EXPECT_EQ(mesh.vertices.size(), 4u) << "vertices must be welded by position";
  EXPECT_EQ(mesh.triangles.size(), 4u);
  for (const auto& corner : kCorners) {
    bool found = false;
    for (const auto& v : mesh.vertices) found |= (v - corner).norm() < 1e-6;
    EXPECT_TRUE(found) << "missing corner " << corner.transpose();
  }
  EXPECT_TRUE(mesh.centroid().isApprox(Vec3(0.25, 0.25, 0.25), 1e-6));
}

const int kFaces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

std::shared_ptr<const ambf_like::Mesh> load(const std::filesystem::path& file) {
  ambf_like::MeshLibrary library;
  return library.load(file, {file, 0, "test"});
}

TEST(MeshFormats, AsciiStl) {
  test_support::TempDir dir;
  std::string stl = "solid tet\n";
  for (const auto& f : kFaces) {
    stl += " facet normal 0 0 0\n  outer loop\n";
    for (int i : f) {
      const auto& p = kCorners[static_cast<std::size_t>(i)];
      stl += "   vertex " + std::to_string(p.x()) + " " + std::to_string(p.y()) + " " +
             std::to_string(p.z()) + "\n";
    }
    stl += "  endloop\n endfacet\n";
  }
  stl += "endsolid tet\n";
  expectTetrahedron(*load(dir.write("tet.stl", stl)));
}

TEST(MeshFormats, BinaryStl) {
  test_support::TempDir dir;
  std::string stl(80, ' ');
  const std::uint32_t count = 4;
  stl.append(reinterpret_cast<const char*>(&count), 4);
  for (const auto& f : kFaces) {
    float values[12] = {0, 0, 0};
    for (int k = 0; k < 3; ++k) {
      for (int c = 0; c < 3; ++c) values[3 + 3 * k + c] = float(kCorners[std::size_t(f[k])][c]);
    }
    stl.append(reinterpret_cast<const char*>(values), sizeof values);
    stl.append(2, '\0');
  }
  expectTetrahedron(*load(dir.write("tet.stl", stl)));
}

/// The tetrahedron as an OBJ file.
std::string objTetrahedron() {
  std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
  for (const auto& f : kFaces) {
    obj += "f " + std::to_string(f[0] + 1) + " " + std::to_string(f[1] + 1) + " " +
           std::to_string(f[2] + 1) + "\n";
  }
  return obj;
}

TEST(MeshFormats, Obj) {
  test_support::TempDir dir;
  expectTetrahedron(*load(dir.write("tet.obj", objTetrahedron())));
}

/// A COLLADA file holding the tetrahedron as geometry "tet", with `head` (e.g. an <asset>) before
/// it and `scene` (libraries of nodes, the visual scene) after it.
std::string colladaTetrahedron(const std::string& head, const std::string& scene) {
  return R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
)" + head +
         R"(
  <library_geometries>
    <geometry id="tet" name="tet"><mesh>
      <source id="tet-pos">
        <float_array id="tet-pos-array" count="12">0 0 0 1 0 0 0 1 0 0 0 1</float_array>
        <technique_common><accessor source="#tet-pos-array" count="4" stride="3">
          <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
        </accessor></technique_common>
      </source>
      <vertices id="tet-vtx"><input semantic="POSITION" source="#tet-pos"/></vertices>
      <triangles count="4"><input semantic="VERTEX" source="#tet-vtx" offset="0"/>
        <p>0 2 1 0 1 3 0 3 2 1 2 3</p></triangles>
    </mesh></geometry>
  </library_geometries>
)" + scene +
         R"(
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
)";
}

TEST(MeshFormats, ColladaKeepsItsZUpCoordinates) {
  test_support::TempDir dir;
  const std::string dae = colladaTetrahedron(
      R"(  <asset><unit name="meter" meter="1"/><up_axis>Z_UP</up_axis></asset>)",
      R"(  <library_visual_scenes><visual_scene id="scene">
    <node id="n"><instance_geometry url="#tet"/></node>
  </visual_scene></library_visual_scenes>)");
  expectTetrahedron(*load(dir.write("tet.dae", dae)));
}

TEST(MeshFormats, ColladaBuildsANodeAsOftenAsItsSceneInstancesIt) {
  // The loader's guard against instance loops (BadInput) lets a shared node through, and a
  // name no node has.
  test_support::TempDir dir;
  const std::string dae = colladaTetrahedron("", R"(
  <library_nodes><node id="shared"><instance_geometry url="#tet"/></node></library_nodes>
  <library_visual_scenes><visual_scene id="scene">
    <node id="here"><instance_node url="#shared"/><instance_node url="#nowhere"/></node>
    <node id="there"><translate>5 0 0</translate><instance_node url="#shared"/></node>
  </visual_scene></library_visual_scenes>)");
  const auto mesh = load(dir.write("two.dae", dae));
  EXPECT_EQ(mesh->vertices.size(), 8u);
  EXPECT_EQ(mesh->triangles.size(), 8u);
}

TEST(MeshFormats, ThreeDsHasTheSameTopologyAsTheObjExport) {
  const auto shared = test_support::sharedDataDir();
  if (shared.empty()) GTEST_SKIP() << "../shared/data is absent: AMBF's cloth meshes are not here";
  const auto dir = shared / "ambf/ambf_models/descriptions/multi-bodies/sb/low_res";
  const auto three_ds = load(dir / "cloth.3DS");
  const auto obj = load(dir / "cloth.OBJ");
  // Blender exported the two with different axes and scale, so only the topology must agree.
  ASSERT_GT(three_ds->triangles.size(), 0u);
  EXPECT_EQ(three_ds->triangles.size(), obj->triangles.size());
  EXPECT_EQ(three_ds->vertices.size(), obj->vertices.size());
}

TEST(MeshFormats, AFormatAmbfDoesNotReadIsRefusedThoughAssimpCouldReadIt) {
  // assimp reads a PLY tetrahedron; AMBF reads STL, OBJ and 3DS only, and every other of
  // assimp's parsers is more code hostile bytes could reach.
  std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
  for (const auto& f : kFaces) {
    ply += "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) +
           "\n";
  }
  test_support::TempDir dir;
  for (const char* name : {"tet.ply", "tet.PLY", "tet.x", "tet"}) {
    const auto file = dir.write(name, ply);
    EXPECT_THAT(test_support::loadErrorOf([&] { load(file); }),
                HasSubstr(std::string(name) + ": not a mesh format"));
  }
  // The formats it does read, whatever the case of their extension.
  expectTetrahedron(*load(dir.write("TET.OBJ", objTetrahedron())));
}

TEST(MeshFormats, LibraryLoadsEachFileOnce) {
  test_support::TempDir dir;
  const auto file = dir.write("tet.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  ambf_like::MeshLibrary library;
  const auto first = library.load(file, {});
  const auto second = library.load(file, {});
  EXPECT_EQ(first.get(), second.get());
  EXPECT_EQ(library.size(), 1u);
}

}  // namespace
