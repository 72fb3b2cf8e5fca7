// The loader applies AMBF's defaults and conventions: surfaces, poses, inertial offsets,
// controller output types, soft-body config, launch selection, world and model gravity.

#include <BulletSoftBody/btSoftBody.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "ambf_like/scene_loader.hpp"
#include "test_files.hpp"

namespace {

using ambf_like::ControlOutput;
using test_support::TempDir;

const ambf_like::ModelSpec& onlyModel(const ambf_like::LoadedScene& scene) {
  EXPECT_EQ(scene.spec.models.size(), 1u);
  return scene.spec.models.front();
}

TEST(AdfSemantics, BodyDefaultsAreAmbfs) {
  TempDir dir;
  const auto scene = ambf_like::loadModelFiles(
      {dir.write("m.yaml",
                 "bodies: [BODY b]\nBODY b: {mass: 1, collision shape: SPHERE,"
                 " collision geometry: {radius: 0.1}}\n")});
  const auto& body = onlyModel(scene).bodies.at(0);
  EXPECT_EQ(body.name, "b");  // from the identifier when `name` is absent
  EXPECT_EQ(body.surface.static_friction, 0.5);
  EXPECT_EQ(body.surface.rolling_friction, 0.01);
  EXPECT_EQ(body.surface.restitution, 0.1);
  EXPECT_EQ(body.surface.linear_damping, 0.04);
  EXPECT_EQ(body.surface.angular_damping, 0.1);
  EXPECT_EQ(body.collision.margin, 0.001);
  EXPECT_TRUE(body.collision.groups.empty());
  EXPECT_EQ(onlyModel(scene).name_space, "/ambf/env/");
  EXPECT_FALSE(onlyModel(scene).ignore_inter_collision);
  EXPECT_EQ(scene.spec.world.gravity, ambf_like::Vec3(0, 0, -9.81));
  EXPECT_EQ(scene.spec.world.max_iterations, 10);
}

TEST(AdfSemantics, OrientationIsRzRyRx) {
  TempDir dir;
  const auto scene = ambf_like::loadModelFiles(
      {dir.write("m.yaml",
                 "bodies: [BODY b]\nBODY b: {mass: 0, location: {position: {x: 1, y: 2, z: 3},"
                 " orientation: {r: 0.1, p: 0.2, y: 0.3}}}\n")});
  const auto& location = onlyModel(scene).bodies.at(0).location;
  const Eigen::Matrix3d expected = (Eigen::AngleAxisd(0.3, ambf_like::Vec3::UnitZ()) *
                                    Eigen::AngleAxisd(0.2, ambf_like::Vec3::UnitY()) *
                                    Eigen::AngleAxisd(0.1, ambf_like::Vec3::UnitX()))
                                       .toRotationMatrix();
  EXPECT_TRUE(location.linear().isApprox(expected, 1e-12));
  EXPECT_EQ(location.translation(), ambf_like::Vec3(1, 2, 3));
}

TEST(AdfSemantics, PrimitiveWithoutCollisionOffsetSitsAtTheInertialOffset) {
  TempDir dir;
  const auto file =
      dir.write("m.yaml",
                "bodies: [BODY ground, BODY ball]\n"
                "BODY ground: {mass: 0, collision shape: PLANE, collision geometry: {normal: {x: "
                "0, y: 0, z: 1}, offset: 0}}\n"
                "BODY ball: {mass: 1, collision shape: SPHERE, collision geometry: {radius: 0.1},"
                " inertial offset: {position: {x: 0, y: 0, z: 0.5}}, location: {position: {x: 0, "
                "y: 0, z: 0}}}\n");
  auto sim = test_support::simulate({file});
  sim->world->step(2000);
  // The sphere (centred on the inertial offset, legacy rule) rests on the plane, so the body
  // frame sits 0.5 m below the sphere's centre.
  EXPECT_NEAR(sim->world->body("ball").pose().translation().z(), 0.1 - 0.5, 2e-3);
}

TEST(AdfSemantics, MeshBodyWithoutInertialOffsetUsesTheVertexMean) {
  TempDir dir;
  dir.write("cube.obj",
            "v 1 1 1\nv 2 1 1\nv 2 2 1\nv 1 2 1\nv 1 1 2\nv 2 1 2\nv 2 2 2\nv 1 2 2\n"
            "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\n"
            "f 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n");
  const auto file =
      dir.write("m.yaml",
                "bodies: [BODY cube]\n"
                "BODY cube: {mass: 1, mesh: cube.obj, collision mesh type: CONVEX_HULL,"
                " location: {position: {x: 0, y: 0, z: 10}}}\n");
  auto sim = test_support::simulate({file});
  const auto& cube = sim->world->body("cube");
  EXPECT_TRUE(
      cube.centerOfMassPose().translation().isApprox(ambf_like::Vec3(1.5, 1.5, 11.5), 1e-12));
  EXPECT_TRUE(cube.pose().translation().isApprox(ambf_like::Vec3(0, 0, 10), 1e-12));
  EXPECT_EQ(cube.collisionVertexCount(), 8u);
}

TEST(AdfSemantics, ControllerOutputTypes) {
  TempDir dir;
  const auto scene = ambf_like::loadModelFiles({dir.write(
      "m.yaml",
      "bodies: [BODY a, BODY b, BODY c, BODY d]\n"
      "joints: [JOINT none, JOINT pid, JOINT typed]\n"
      "BODY a: {mass: 0}\nBODY b: {mass: 1, inertia: {ix: 1, iy: 1, iz: 1}}\n"
      "BODY c: {mass: 1, inertia: {ix: 1, iy: 1, iz: 1}}\nBODY d: {mass: 1, inertia: {ix: 1, iy: "
      "1, iz: 1}}\n"
      "JOINT none: {parent: BODY a, child: BODY b, type: hinge}\n"
      "JOINT pid: {parent: BODY a, child: BODY c, type: slider, controller: {P: 5, D: 0.5}}\n"
      "JOINT typed: {parent: BODY a, child: BODY d, controller: {P: 5, I: 1, D: 0.5},"
      " controller output type: VELOCITY, offset: 0.25}\n")});
  const auto& joints = onlyModel(scene).joints;
  EXPECT_EQ(joints[0].type, ambf_like::JointType::Revolute);
  EXPECT_EQ(joints[0].output, ControlOutput::Velocity);
  EXPECT_EQ(joints[0].controller.p, 10.0);
  EXPECT_EQ(joints[0].controller.d, 1.0);
  EXPECT_EQ(joints[0].max_motor_impulse, 0.1);
  EXPECT_EQ(joints[0].erp, 0.1);
  EXPECT_EQ(joints[0].cfm, 0.1);
  EXPECT_TRUE(joints[0].ignore_inter_collision);
  EXPECT_EQ(joints[1].type, ambf_like::JointType::Prismatic);
  EXPECT_EQ(joints[1].output, ControlOutput::Effort);
  EXPECT_EQ(joints[1].controller.i, 0.0);
  EXPECT_EQ(joints[2].output, ControlOutput::Velocity);
  EXPECT_EQ(joints[2].controller.i, 1.0);
  EXPECT_EQ(joints[2].child_offset, 0.25);
}

TEST(AdfSemantics, MultiAxisJointLimits) {
  TempDir dir;
  const auto scene = ambf_like::loadModelFiles(
      {dir.write("m.yaml",
                 "bodies: [BODY a, BODY b, BODY c]\njoints: [JOINT cone, JOINT six]\n"
                 "BODY a: {mass: 0}\nBODY b: {mass: 1, inertia: {ix: 1, iy: 1, iz: 1}}\n"
                 "BODY c: {mass: 1, inertia: {ix: 1, iy: 1, iz: 1}}\n"
                 "JOINT cone: {parent: BODY a, child: BODY b, type: cone twist, joint limits: {x: "
                 "0.1, y: 0.2, z: 0.3}}\n"
                 "JOINT six: {parent: BODY a, child: BODY c, type: six dof spring,"
                 " joint limits: {linear: {low: {x: -1, y: -2, z: -3}, high: {x: 1, y: 2, z: 3}},"
                 " angular: {low: {x: -0.1, y: -0.2, z: -0.3}, high: {x: 0.1, y: 0.2, z: 0.3}}},"
                 " stiffness: {linear: {x: 10, y: 20, z: 30}, angular: {x: 1, y: 2, z: 3}}}\n")});
  const auto& joints = onlyModel(scene).joints;
  EXPECT_EQ(joints[0].cone_twist_limits, ambf_like::Vec3(0.1, 0.2, 0.3));
  EXPECT_EQ(joints[1].six_dof.low, (ambf_like::SixAxis{-1, -2, -3, -0.1, -0.2, -0.3}));
  EXPECT_EQ(joints[1].six_dof.high, (ambf_like::SixAxis{1, 2, 3, 0.1, 0.2, 0.3}));
  EXPECT_EQ(joints[1].six_dof.stiffness, (ambf_like::SixAxis{10, 20, 30, 1, 2, 3}));
  EXPECT_EQ(joints[1].six_dof.damping[0], 0.7);  // AMBF default
}

TEST(AdfSemantics, SoftBodyConfigBlock) {
  TempDir dir;
  const auto scene = ambf_like::loadModelFiles(
      {dir.write("m.yaml",
                 "soft bodies: [BODY s]\n"
                 "BODY s:\n"
                 "  mass: 2\n"
                 "  mesh: " +
                     test_support::icosphereMesh().string() +
                     "\n"
                     "  config: {kLST: 0.2, kDP: 0.01, piterations: 6, bending constraint: 2,"
                     " clusters: 3, flags: 0x21, fixed nodes: [0, 4], margin: 0.02}\n")});
  const auto& soft = onlyModel(scene).soft_bodies.at(0);
  EXPECT_EQ(soft.config.kLST, 0.2);
  EXPECT_EQ(soft.config.kDP, 0.01);
  EXPECT_EQ(soft.config.kDF, 0.2);  // default
  EXPECT_EQ(soft.config.piterations, 6);
  EXPECT_EQ(soft.config.bending_constraint, 2);
  EXPECT_EQ(soft.config.clusters, 3);
  EXPECT_EQ(soft.config.collision_flags, 0x21);
  EXPECT_EQ(soft.config.fixed_nodes, (std::vector<int>{0, 4}));
  EXPECT_EQ(soft.margin, 0.02);  // honoured when the body has no `collision margin`
  EXPECT_FALSE(soft.randomize_constraints);
}

TEST(AdfSemantics, RandomizeConstraintsShufflesTheBendingLinksInAsAmbfDoes) {
  // AMBF shuffles a soft body's links once its config has made the bending ones: they end up
  // spread among the mesh's links. Not asked to, Bullet appends them after the mesh's links.
  TempDir dir;
  auto links = [&](bool randomize) {
    const auto model =
        dir.write("m.yaml", "soft bodies: [BODY s]\nBODY s:\n  mass: 1\n  mesh: " +
                                test_support::icosphereMesh().string() +
                                "\n  randomize constraints: " + (randomize ? "true" : "false") +
                                "\n  config: {bending constraint: 2}\n");
    auto sim = test_support::simulate({model});
    const btSoftBody& body = sim->world->softBody(0).bullet();
    int first_bending = body.m_links.size();
    int last_mesh_link = -1;
    for (int i = 0; i < body.m_links.size(); ++i) {
      if (body.m_links[i].m_bbending) {
        first_bending = std::min(first_bending, i);
      } else {
        last_mesh_link = i;
      }
    }
    EXPECT_LT(first_bending, body.m_links.size()) << "the config asks for bending links";
    return std::pair{first_bending, last_mesh_link};
  };
  const auto [first_bending, last_mesh_link] = links(true);
  EXPECT_LT(first_bending, last_mesh_link);
  const auto [first_bending_in_order, last_mesh_link_in_order] = links(false);
  EXPECT_GT(first_bending_in_order, last_mesh_link_in_order);
}

TEST(AdfSemantics, DuplicateKeysWarnAndTheFirstWins) {
  TempDir dir;
  const auto scene = ambf_like::loadModelFiles({dir.write(
      "m.yaml",
      "bodies: [BODY b]\nBODY b:\n  mass: 1\n  mass: 2\n  inertia: {ix: 1, iy: 1, iz: 1}\n")});
  EXPECT_EQ(onlyModel(scene).bodies.at(0).mass, 1.0);
  ASSERT_EQ(scene.warnings.size(), 1u);
  EXPECT_THAT(scene.warnings[0].str(), testing::HasSubstr(":4: BODY b/mass: duplicate key"));
}

TEST(AdfSemantics, LaunchFileSelectionWorldAndExtraFiles) {
  TempDir dir;
  for (const char* name : {"zero", "one", "two"}) {
    dir.write(std::string(name) + ".yaml", std::string("bodies: [BODY ") + name + "]\nBODY " +
                                               name + ": {mass: 0}\nnamespace: /" + name + "/\n");
  }
  dir.write("world.yaml",
            "gravity: {x: 0, y: 0, z: -1.62}\nmax iterations: 50\nnamespace: /moon/\n");
  const auto launch = dir.write("launch.yaml",
                                "world config: world.yaml\n"
                                "multibody configs:\n  - zero.yaml\n  - one.yaml\n  - two.yaml\n");
  ambf_like::LaunchSelection selection;
  selection.indices = {2, 0};
  selection.extra_files = {dir.path() / "one.yaml"};
  const auto scene = ambf_like::loadLaunchFile(launch, selection);
  ASSERT_EQ(scene.spec.models.size(), 3u);
  EXPECT_EQ(scene.spec.models[0].name_space, "/two/");
  EXPECT_EQ(scene.spec.models[1].name_space, "/zero/");
  EXPECT_EQ(scene.spec.models[2].name_space, "/one/");
  EXPECT_EQ(scene.spec.world.gravity.z(), -1.62);
  EXPECT_EQ(scene.spec.world.max_iterations, 50);
  EXPECT_EQ(ambf_like::loadLaunchFile(launch, {}).spec.models.size(), 3u);  // no -l: all entries
}

TEST(AdfSemantics, WorldFileCarriesThisSimulatorsOwnSettings) {
  TempDir dir;
  dir.write("m.yaml", "bodies: [BODY b]\nBODY b: {mass: 0}\n");
  dir.write("world.yaml", "ambf_like: {solver iterations: 25, soft body sdf voxel size: 0.002}\n");
  const auto launch =
      dir.write("launch.yaml", "world config: world.yaml\nmultibody configs:\n  - m.yaml\n");
  const auto scene = ambf_like::loadLaunchFile(launch, {});
  EXPECT_EQ(scene.spec.world.solver_iterations, 25);
  EXPECT_EQ(scene.spec.world.sdf_voxel_size, 0.002);
  dir.write("world.yaml", "ambf_like: {solver iteration: 25}\n");
  EXPECT_THAT(
      test_support::loadErrorOf([&] { ambf_like::loadLaunchFile(launch, {}, {.strict = true}); }),
      testing::HasSubstr("did you mean 'solver iterations'"));
  EXPECT_EQ(scene.spec.world.articulation, ambf_like::Articulation::Automatic);
  for (const auto& [word, mode] : std::vector<std::pair<std::string, ambf_like::Articulation>>{
           {"maximal", ambf_like::Articulation::Maximal},  // AMBF's way
           {"reduced", ambf_like::Articulation::Reduced},
           {"automatic", ambf_like::Articulation::Automatic}}) {
    dir.write("world.yaml", "ambf_like: {articulation: " + word + "}\n");
    EXPECT_EQ(ambf_like::loadLaunchFile(launch, {}).spec.world.articulation, mode) << word;
  }
  dir.write("world.yaml", "ambf_like:\n  articulation: sideways\n");
  const auto error = test_support::loadErrorOf([&] { ambf_like::loadLaunchFile(launch, {}); });
  EXPECT_THAT(error, testing::HasSubstr("world.yaml:2"));
  EXPECT_THAT(error, testing::HasSubstr("'automatic', 'maximal' or 'reduced', not 'sideways'"));
}

TEST(AdfSemantics, ModelAndBodyGravityOverrideTheWorld) {
  TempDir dir;
  const auto file = dir.write(
      "m.yaml",
      "bodies: [BODY model_g, BODY body_g]\ngravity: {x: 0, y: 0, z: -1}\n"
      "BODY model_g: {mass: 1, inertia: {ix: 1, iy: 1, iz: 1}, damping: {linear: 0, angular: 0}}\n"
      "BODY body_g: {mass: 1, inertia: {ix: 1, iy: 1, iz: 1}, damping: {linear: 0, angular: 0},"
      " gravity: {x: 2, y: 0, z: 0}}\n");
  auto sim = test_support::simulate({file});
  sim->world->step(1000);
  const double fall = 1e-6 * 1000 * 1001 / 2;  // semi-implicit Euler, 1 s at 1 ms, per m/s^2
  EXPECT_NEAR(sim->world->body("model_g").pose().translation().z(), -fall, 1e-9);
  EXPECT_NEAR(sim->world->body("body_g").pose().translation().x(), 2 * fall, 1e-9);
}

TEST(AdfSemantics, ChildOffsetSetsTheZeroAndAnglesFollowTheRightHandRule) {
  TempDir dir;
  // The child starts turned 0.3 rad about the hinge axis (x) relative to its parent.
  auto model = [&](const std::string& extra) {
    return dir.write("m.yaml",
                     "bodies: [BODY a, BODY b]\njoints: [JOINT j]\ngravity: {x: 0, y: 0, z: 0}\n"
                     "BODY a: {mass: 0}\n"
                     "BODY b: {mass: 1, inertia: {ix: 1, iy: 1, iz: 1},"
                     " location: {orientation: {r: 0.3, p: 0, y: 0}}}\n"
                     "JOINT j: {parent: BODY a, child: BODY b, parent axis: {x: 1, y: 0, z: 0},"
                     " child axis: {x: 1, y: 0, z: 0}, type: continuous" +
                         extra + "}\n");
  };
  EXPECT_NEAR(test_support::simulate({model("")})->world->joint("j").position(), 0.3, 1e-9);
  EXPECT_NEAR(test_support::simulate({model(", offset: 0.3")})->world->joint("j").position(), 0.0,
              1e-9);
  EXPECT_NEAR(test_support::simulate({model(", offset: 0.3, joint offset: 0.1")})
                  ->world->joint("j")
                  .position(),
              0.1, 1e-9);

  // Driven past +pi the continuous joint keeps counting instead of wrapping.
  auto sim = test_support::simulate({model(", max motor impulse: 10")});
  auto& joint = sim->world->joint("j");
  joint.commandVelocity(2.0);
  sim->world->step(3000);
  EXPECT_NEAR(joint.position(), 0.3 + 2.0 * 3.0, 0.02);
  const Eigen::AngleAxisd turned(sim->world->body("b").pose().linear());
  EXPECT_NEAR(std::remainder(turned.angle() * turned.axis().x() - joint.position(), 2 * M_PI), 0.0,
              1e-3);
}

}  // namespace

TEST(AdfSemantics, AModelLoadedTwiceIsRenamedAsAmbfRenamesIt) {
  TempDir dir;
  const auto file = dir.write("pair.yaml", R"(bodies: [BODY base, BODY box]
joints: [JOINT hinge]
namespace: /ambf/env/pair/
BODY base:
  name: base
  mass: 0
  collision shape: BOX
  collision geometry: {x: 0.1, y: 0.1, z: 0.1}
BODY box:
  name: box
  mass: 1
  collision shape: BOX
  collision geometry: {x: 0.1, y: 0.1, z: 0.1}
JOINT hinge:
  name: hinge
  parent: BODY base
  child: BODY box
  type: revolute
)");
  const auto scene = ambf_like::loadModelFiles({file, file});
  ASSERT_EQ(scene.spec.models.size(), 2u);
  const auto& copy = scene.spec.models[1];
  EXPECT_EQ(copy.bodies[0].name, "base1");
  EXPECT_EQ(copy.bodies[1].name, "box1");
  EXPECT_EQ(copy.joints[0].name, "hinge1");
  EXPECT_EQ(copy.joints[0].parent, "base1");
  EXPECT_EQ(copy.joints[0].child, "box1");
  EXPECT_EQ(scene.spec.models[0].bodies[1].name, "box") << "the first keeps its names";
  ASSERT_EQ(scene.warnings.size(), 3u);
  EXPECT_THAT(scene.warnings[1].str(),
              testing::HasSubstr("pair.yaml:10: BODY box: body '/ambf/env/pair/box' has the name "
                                 "of one loaded before it: renamed 'box1'"));
  // A third copy counts on.
  const auto three = ambf_like::loadModelFiles({file, file, file});
  EXPECT_EQ(three.spec.models[2].bodies[1].name, "box2");
}
