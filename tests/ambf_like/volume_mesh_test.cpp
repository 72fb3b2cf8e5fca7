// Tetrahedral volume meshes (legacy VTK) as soft bodies: what is built from them, and every
// malformed file refused with its file and line.

#include <BulletSoftBody/btSoftBody.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>

#include "test_files.hpp"

namespace {

using test_support::loadErrorOf;
using test_support::TempDir;
using testing::AllOf;
using testing::HasSubstr;

/// A cube of side 1 cut into six tetrahedra around its 0-7 diagonal (point i at the bits of i).
std::string cubeVtk(const std::string& cells_override = "") {
  std::ostringstream s;
  s << "# vtk DataFile Version 2.0\nunit cube\nASCII\nDATASET UNSTRUCTURED_GRID\n"
    << "POINTS 8 double\n";
  for (int i = 0; i < 8; ++i)
    s << (i & 1) << ' ' << ((i >> 1) & 1) << ' ' << ((i >> 2) & 1) << '\n';
  if (!cells_override.empty()) return s.str() + cells_override;
  s << "CELLS 6 30\n4 0 1 3 7\n4 0 1 5 7\n4 0 2 3 7\n4 0 2 6 7\n4 0 4 5 7\n4 0 4 6 7\n"
    << "CELL_TYPES 6\n10\n10\n10\n10\n10\n10\n";
  return s.str();
}

/// A soft body of `mesh` (scaled to 2 cm, 10 g) over a static floor.
std::string scene(const std::filesystem::path& mesh) {
  return "bodies: [BODY floor]\nsoft bodies: [BODY cube]\n"
         "BODY floor: {name: floor, mass: 0, collision shape: BOX, collision geometry: "
         "{x: 1, y: 1, z: 0.1}, location: {position: {x: 0, y: 0, z: -0.05}}}\n"
         "BODY cube:\n  name: cube\n  mesh: " +
         mesh.string() +
         "\n  mass: 0.01\n  scale: 0.02\n  collision margin: 0.0005\n"
         "  location: {position: {x: -0.01, y: -0.01, z: 0.002}}\n"
         "  contact friction: coulomb\n  substeps: 2\n  config: {kDF: 0.5, piterations: 2}\n";
}

TEST(VolumeMesh, ACubeOfSixTetrahedraBecomesASolidSoftBody) {
  TempDir dir;
  const auto mesh = dir.write("cube.vtk", cubeVtk());
  auto sim = test_support::simulate({dir.write("s.yaml", scene(mesh))});
  auto& cube = sim->world->softBody("cube");
  const btSoftBody& body = cube.bullet();
  EXPECT_EQ(body.m_nodes.size(), 8);
  EXPECT_EQ(body.m_tetras.size(), 6);
  EXPECT_EQ(body.m_links.size(), 19) << "12 edges, 6 face diagonals, the body diagonal";
  EXPECT_EQ(body.m_faces.size(), 12) << "two outward triangles per face of the cube";
  double mass = 0.0;
  for (int i = 0; i < body.m_nodes.size(); ++i) mass += 1.0 / body.m_nodes[i].m_im;
  EXPECT_NEAR(mass, 0.01, 1e-12);
  // Every boundary face points away from the cube's centre.
  const btVector3 centre(0.0, 0.0, 0.012);
  for (int i = 0; i < body.m_faces.size(); ++i) {
    const auto& f = body.m_faces[i];
    const btVector3 normal = (f.m_n[1]->m_x - f.m_n[0]->m_x).cross(f.m_n[2]->m_x - f.m_n[0]->m_x);
    EXPECT_GT(normal.dot(f.m_n[0]->m_x - centre), 0.0) << "face " << i;
  }
  // It lands on the floor and keeps its shape: its links hold its volume, not only its surface.
  sim->world->step(1000);
  EXPECT_TRUE(cube.isFinite());
  double low = 1.0, high = -1.0;
  for (const auto& p : cube.nodePositions()) {
    low = std::min(low, p.z());
    high = std::max(high, p.z());
  }
  EXPECT_NEAR(low, 0.0005, 0.0005) << "resting on the floor at its margin";
  EXPECT_NEAR(high - low, 0.02, 0.001) << "still 2 cm tall";
}

TEST(VolumeMesh, APointNoTetrahedronUsesIsNoNode) {
  // The cube with a ninth point that belongs to no cell: it would be a massless (fixed) node.
  std::string vtk = cubeVtk();
  vtk.replace(vtk.find("POINTS 8 double\n"), 16, "POINTS 9 double\n5 5 5\n");
  for (int cell = 0; cell < 6; ++cell) {  // every index moves up by one past the stray point
    const std::string row[] = {"4 0 1 3 7", "4 0 1 5 7", "4 0 2 3 7",
                               "4 0 2 6 7", "4 0 4 5 7", "4 0 4 6 7"};
    std::string shifted = "4";
    for (char c : row[cell].substr(2)) {
      if (c != ' ') shifted += std::string(" ") + std::to_string(c - '0' + 1);
    }
    vtk.replace(vtk.find(row[cell] + "\n"), row[cell].size(), shifted);
  }
  TempDir dir;
  auto sim = test_support::simulate({dir.write("s.yaml", scene(dir.write("stray.vtk", vtk)))});
  const btSoftBody& body = sim->world->softBody("cube").bullet();
  ASSERT_EQ(body.m_nodes.size(), 8) << "the stray point is dropped";
  for (int i = 0; i < body.m_nodes.size(); ++i) EXPECT_GT(body.m_nodes[i].m_im, 0.0) << i;
  EXPECT_EQ(body.m_links.size(), 19);
  EXPECT_EQ(body.m_faces.size(), 12);
}

TEST(VolumeMesh, NodeIIsTheFilesPointIWhateverOrderTheCellsUseThem) {
  // The cells name point 7 first; 'fixed nodes' and every node index count the file's points.
  const std::string cells =
      "CELLS 6 30\n4 7 1 3 0\n4 7 1 5 0\n4 7 2 3 0\n4 7 2 6 0\n4 7 4 5 0\n"
      "4 7 4 6 0\nCELL_TYPES 6\n10\n10\n10\n10\n10\n10\n";
  TempDir dir;
  auto sim = test_support::simulate(
      {dir.write("s.yaml", scene(dir.write("reordered.vtk", cubeVtk(cells))))});
  const btSoftBody& body = sim->world->softBody("cube").bullet();
  ASSERT_EQ(body.m_nodes.size(), 8);
  for (int i = 0; i < 8; ++i) {  // point i at the bits of i, scaled to 2 cm and placed
    const btVector3 expected =
        btVector3((i & 1), ((i >> 1) & 1), ((i >> 2) & 1)) * 0.02 + btVector3(-0.01, -0.01, 0.002);
    EXPECT_LT((body.m_nodes[i].m_x - expected).length(), 1e-12) << "node " << i;
  }
}

/// The load error of a scene whose cube mesh is `vtk`.
std::string errorOf(const std::string& vtk) {
  TempDir dir;
  const auto mesh = dir.write("bad.vtk", vtk);
  return loadErrorOf([&] { test_support::simulate({dir.write("s.yaml", scene(mesh))}); });
}

TEST(VolumeMesh, MalformedFilesAreRefusedWithFileAndLine) {
  const std::string header_end = "POINTS 8 double\n";
  // A hexahedron (8 points, VTK type 12) is not a tetrahedron.
  EXPECT_THAT(
      errorOf(cubeVtk("CELLS 1 9\n8 0 1 2 3 4 5 6 7\nCELL_TYPES 1\n12\n")),
      AllOf(HasSubstr("bad.vtk:15"), HasSubstr("only tetrahedra"), HasSubstr("BODY cube/mesh")));
  EXPECT_THAT(errorOf(cubeVtk("CELLS 1 5\n4 0 1 3 9\nCELL_TYPES 1\n10\n")),
              AllOf(HasSubstr("bad.vtk:15"), HasSubstr("point index"), HasSubstr("'9'")));
  EXPECT_THAT(errorOf(cubeVtk("CELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n")),
              AllOf(HasSubstr("bad.vtk:15"), HasSubstr("no volume")));
  // A sliver a billionth of its size thick: rounding alone would decide its sign (found by
  // fuzz_mesh; the input is in fuzz/regressions/mesh/).
  const std::string sliver =
      "# vtk DataFile Version 2.0\nsliver\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 double\n"
      "0 0 0\n1 0 0\n0 1 0\n0.3 0.3 1e-12\nCELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n";
  EXPECT_THAT(errorOf(sliver),
              AllOf(HasSubstr("bad.vtk: cell 0 is flat"), HasSubstr("BODY cube/mesh")));
  EXPECT_THAT(errorOf(cubeVtk("CELLS 1 5\n4 0 1 3 7\nCELL_TYPES 1\n12\n")),
              AllOf(HasSubstr("bad.vtk:17"), HasSubstr("not a tetrahedron")));
  EXPECT_THAT(errorOf(cubeVtk("CELLS 6 30\n4 0 1 3 7\n4 0 1 5 7\n")),
              AllOf(HasSubstr("bad.vtk"), HasSubstr("the file ends")));
  std::string nan = cubeVtk();
  nan.replace(nan.find(header_end) + header_end.size(), 5, "nan 0");
  EXPECT_THAT(errorOf(nan), AllOf(HasSubstr("bad.vtk:6"), HasSubstr("finite number")));
  std::string binary = cubeVtk();
  binary.replace(binary.find("ASCII"), 5, "BINARY");
  EXPECT_THAT(errorOf(binary), AllOf(HasSubstr("bad.vtk:3"), HasSubstr("only ASCII")));
  EXPECT_THAT(errorOf("solid cube\nendsolid\n"), HasSubstr("not a legacy VTK file"));
}

}  // namespace
