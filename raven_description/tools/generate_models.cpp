// raven_model_generator: writes this project's Raven-II model files from the physical profile:
// the simplified arms (committed under raven_description/models) or the dense variant.

#include <CLI/CLI.hpp>
#include <fstream>
#include <iostream>

#include "adf_writer.hpp"
#include "arm_design.hpp"
#include "grasp_assist_scene.hpp"
#include "peg_scene.hpp"

namespace {

void writeText(const std::filesystem::path& file, const std::string& text) {
  std::filesystem::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

}  // namespace

int main(int argc, char** argv) {
  std::filesystem::path out;
  bool dense = false;
  CLI::App app{"Writes the Raven-II model files (ADF) generated from the physical profile"};
  app.add_option("--out", out, "output folder (e.g. raven_description/models)")->required();
  app.add_flag("--dense", dense, "write the dense-collision variant instead (about 200k vertices)");
  CLI11_PARSE(app, argc, argv);

  using namespace raven::model;
  const auto profile = raven::builtinProfile("physical");
  const auto collision = dense ? Collision::Dense : Collision::Simplified;
  const auto robot_dir = out / "raven2";
  std::size_t vertices = 0;
  for (auto arm : raven::kArms) {
    const auto name = std::string(raven::armName(arm));
    vertices += writeModel(designArm(profile, arm), collision,
                           robot_dir / ("raven2_" + name + ".yaml"), robot_dir / "meshes");
  }
  // The arms alone are articulations (reduced coordinates): their joints need no solver rows,
  // a step costs 2.4x less than with AMBF's constraints, and a loaded arm settles on its
  // kinematics within a micrometre (0.09 mm with constraints at Bullet's 10 iterations).
  // Contacts and joint limits still take Bullet's default 10 iterations, as in AMBF.
  writeText(robot_dir / "world.yaml",
            "# The Raven-II's world: its base frame {B} with gravity along -z.\n"
            "namespace: /raven2/\n"
            "max iterations: 10\n"
            "gravity: {x: 0.0, y: 0.0, z: -9.81}\n"
            "ambf_like:\n"
            "  solver iterations: 10  # AMBF's (Bullet's default), for contacts and limits\n"
            "  articulation: reduced  # each arm one Featherstone multibody (AMBF: maximal)\n");
  writeText(robot_dir / "launch.yaml",
            "# Both Raven-II arms.\n"
            "world config: world.yaml\n"
            "multibody configs:\n  - raven2_left.yaml   #0\n  - raven2_right.yaml  #1\n");
  // The same board and rings beside either arm variant (the benchmarks compare the two).
  writePegScene(PegSceneDesign{}, out / "peg_transfer");
  // Touching: the ring's margin and the jaw's (0.5 + 0.2 mm) and a little.
  writeGraspAssist(profile, ArmDesign{}, 0.001, out / "peg_transfer" / "grasp_assist.yaml");
  writeText(out / "peg_transfer" / "world.yaml",
            "# The peg-transfer world: {B}, gravity along -z, and this simulator's settings.\n"
            "namespace: /peg_transfer/\n"
            "max iterations: 10\n"
            "gravity: {x: 0.0, y: 0.0, z: -9.81}\n"
            "ambf_like:\n"
            "  solver iterations: 20  # the ring grasps are checked at 20 (the 20-seed batch)\n"
            "  soft body sdf voxel size: 0.002  # the posts are 5 mm thick\n");
  writeText(out / "peg_transfer" / "launch.yaml",
            "# The peg-transfer scene: both arms, the board and six soft rings.\n"
            "world config: world.yaml\n"
            "multibody configs:\n  - ../raven2/raven2_left.yaml   #0\n"
            "  - ../raven2/raven2_right.yaml  #1\n  - peg_board.yaml               #2\n"
            "  - rings.yaml                   #3\n");
  std::cout << (dense ? "dense" : "simplified") << " Raven-II written to " << robot_dir << ": "
            << vertices << " collision mesh vertices\n";
  return 0;
}
