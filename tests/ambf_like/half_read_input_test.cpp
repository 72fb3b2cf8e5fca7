// Input the parsers take without refusing it, yet read wrongly or not at all: urdfdom's errors
// that still return a model, dimensions and axes urdfdom accepts, and paths that are not files
// (a pipe, a device, a loop of symbolic links). Each must be a clear error, never a changed robot
// or a reader that blocks.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include "ambf_like/scene_loader.hpp"
#include "test_files.hpp"

namespace {

using test_support::loadErrorOf;
using test_support::TempDir;
using testing::AllOf;
using testing::HasSubstr;

std::string strictLoadError(const std::filesystem::path& file) {
  return loadErrorOf([&] { ambf_like::loadModelFiles({file}, std::nullopt, {.strict = true}); });
}

/// A base and one link `l` on joint `j`: the link's mass, the base's collision geometry, and
/// the joint's type and axis element.
std::string urdf(const std::string& mass, const std::string& base_geometry,
                 const std::string& joint_type = "revolute",
                 const std::string& axis = "<axis xyz='0 1 0'/>") {
  return "<?xml version='1.0'?>\n<robot name='r'>\n"
         "<link name='base'><collision><geometry>" +
         base_geometry +
         "</geometry></collision></link>\n"  // line 3
         "<link name='l'><inertial><mass value='" +
         mass +
         "'/>\n"  // line 4
         "<inertia ixx='1e-3' iyy='1e-3' izz='1e-3' ixy='0' ixz='0' iyz='0'/></inertial></link>\n"
         "<joint name='j' type='" +
         joint_type + "'>\n" + axis +  // the joint on line 6, its axis on 7
         "<parent link='base'/><child link='l'/>"
         "<limit lower='-1' upper='1' effort='1' velocity='1'/></joint>\n</robot>\n";
}

const std::string kBox = "<box size='0.1 0.1 0.1'/>";

TEST(HalfReadInput, TheUrdfBelowLoads) {
  TempDir dir;
  EXPECT_EQ(strictLoadError(dir.write("good.urdf", urdf("1", kBox))), "");
  EXPECT_EQ(strictLoadError(dir.write("fixed.urdf", urdf("1", kBox, "fixed", ""))), "");
}

TEST(HalfReadInput, AnElementUrdfdomCouldNotReadIsAnErrorNotALeftOutPart) {
  // urdfdom logs an error and still returns the model: a link whose mass it could not read
  // without one (so the link was a static body), a collision it could not read left out.
  TempDir dir;
  EXPECT_THAT(strictLoadError(dir.write("mass.urdf", urdf("nan", kBox))),
              AllOf(HasSubstr("mass.urdf:4"), HasSubstr("not a valid URDF"),
                    HasSubstr("mass [nan] is not a float")));
  EXPECT_THAT(strictLoadError(dir.write("box.urdf", urdf("1", "<box size='0.1 nan 0.1'/>"))),
              AllOf(HasSubstr("box.urdf:3"), HasSubstr("collision element for Link [base]")));
}

TEST(HalfReadInput, APrimitiveWithoutASizeIsRefusedByPath) {
  // urdfdom reads any number; Bullet would take a negative or zero extent as it comes.
  TempDir dir;
  EXPECT_THAT(strictLoadError(dir.write("box.urdf", urdf("1", "<box size='-1 0 0.1'/>"))),
              AllOf(HasSubstr("box.urdf:3"), HasSubstr("link[base]/collision[0]/box size"),
                    HasSubstr("greater than zero")));
  EXPECT_THAT(
      strictLoadError(dir.write("ball.urdf", urdf("1", "<sphere radius='0'/>"))),
      AllOf(HasSubstr("link[base]/collision[0]/sphere radius"), HasSubstr("greater than zero")));
  EXPECT_THAT(
      strictLoadError(dir.write("can.urdf", urdf("1", "<cylinder radius='0.1' length='-0.2'/>"))),
      AllOf(HasSubstr("link[base]/collision[0]/cylinder"), HasSubstr("greater than zero")));
  EXPECT_THAT(strictLoadError(dir.write("vast.urdf", urdf("1", "<box size='1e300 1 1'/>"))),
              HasSubstr("at most"));
}

TEST(HalfReadInput, AMovingJointWithAZeroAxisIsRefused) {
  // It used to turn about x, URDF's default for a joint that gives no <axis> at all.
  TempDir dir;
  EXPECT_THAT(
      strictLoadError(dir.write("axis.urdf", urdf("1", kBox, "revolute", "<axis xyz='0 0 0'/>"))),
      AllOf(HasSubstr("axis.urdf:7"), HasSubstr("joint[j]/axis"), HasSubstr("must not be zero")));
  EXPECT_EQ(strictLoadError(dir.write("default.urdf", urdf("1", kBox, "revolute", ""))), "");
}

TEST(HalfReadInput, APipeOrADeviceAsAModelFileIsRefusedWithoutReadingIt) {
  // Read as a file, a pipe blocks until a writer comes and /dev/zero never ends.
  TempDir dir;
  for (const char* name : {"pipe.urdf", "pipe.yaml"}) {
    const auto pipe = dir.path() / name;
    ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
    EXPECT_THAT(strictLoadError(pipe), AllOf(HasSubstr(name), HasSubstr("not a regular file")));
  }
  const auto zero = dir.path() / "zero.urdf";
  std::filesystem::create_symlink("/dev/zero", zero);
  EXPECT_THAT(strictLoadError(zero), HasSubstr("not a regular file"));
}

TEST(HalfReadInput, AMeshsSideFileThatIsAPipeOrADeviceIsNotOpened) {
  // assimp opens an OBJ's material library itself: a pipe there blocked the loader for good.
  // The mesh loads; its materials, which nothing here uses, are left out.
  TempDir dir;
  ASSERT_EQ(::mkfifo((dir.path() / "pipe.mtl").c_str(), 0600), 0);
  std::filesystem::create_symlink("/dev/zero", dir.path() / "zero.mtl");
  const std::string tetrahedron =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  for (const char* library : {"pipe.mtl", "zero.mtl"}) {
    dir.write("tet.obj", std::string("mtllib ") + library + "\n" + tetrahedron);
    const auto model =
        dir.write("m.yaml", "bodies: [BODY b]\nBODY b: {name: b, mass: 1, mesh: tet.obj}\n");
    std::unique_ptr<test_support::Simulation> built;
    EXPECT_EQ(loadErrorOf([&] { built = test_support::simulate({model}); }), "") << library;
    ASSERT_NE(built, nullptr);
  }
}

TEST(HalfReadInput, AMeshBehindALoopOfLinksNamesTheFileThatUsesIt) {
  // std::filesystem threw its own error there, naming neither the model file nor its line.
  TempDir dir;
  std::filesystem::create_symlink("b.stl", dir.path() / "a.stl");
  std::filesystem::create_symlink("a.stl", dir.path() / "b.stl");
  const auto model = dir.write("m.yaml",
                               "bodies: [BODY part]\n"
                               "BODY part: {name: part, mass: 0, mesh: a.stl}\n");
  EXPECT_THAT(strictLoadError(model), AllOf(HasSubstr("m.yaml:2"), HasSubstr("a.stl")));
  const auto robot = dir.write("r.urdf", urdf("1", "<mesh filename='a.stl'/>"));
  EXPECT_THAT(strictLoadError(robot), AllOf(HasSubstr("r.urdf:3"), HasSubstr("symbolic links")));
}

}  // namespace
