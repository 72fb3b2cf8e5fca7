// Fuzz target: long and wide articulations. The input's bytes choose a tree of up to 20,000
// links (a chain, a star, or anything between), each joint's type, axis, origin and limits, each
// link's mass, inertia and box, and the coordinates it is simulated in; the tree is written as a
// URDF, loaded, built and stepped. A LoadError is the right answer to what the loader refuses,
// and the step guard's SimulationDiverged (naming the body, step and speed) to a world that blows
// up; a crash, a hang (libFuzzer's timeout) or memory past the limit is a finding. The first tree
// it found to diverge (fuzz/regressions/articulations/diverges-at-step-2: a 1 mg link on a joint
// damped by 5 N m s, flung at 22 km/s at step 2 by the explicit damper) now runs finite: a joint's
// damping is integrated exactly on its axis inertia (Joint::dampingEffort). Still accepted and
// stopped by the guard at step 1 (impossible-inertia-diverges-at-step-1): links whose principal
// moments break the triangle inequality (2.5 kg m^2 against 3e-9 + 1e-9), which no body has;
// AMBF takes such files, so whether to refuse them is open (issue 66).

#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>

#include "ambf_like/mesh.hpp"
#include "ambf_like/scene_loader.hpp"
#include "ambf_like/step_guard.hpp"
#include "ambf_like/world.hpp"
#include "fuzz_file.hpp"

namespace {

constexpr int kMostLinks = 20000;
constexpr int kSteps = 2;

/// Reads the input as a tree's numbers: ordinary values, and at edges a file can reach (zero,
/// the range's ends, negative) at a rate the input picks once per tree (never, 1 in 1000, 1 in
/// 30, 1 in 4), so that large trees of sound links are as common as small hostile ones.
class Numbers {
 public:
  explicit Numbers(FuzzedDataProvider& in)
      : in_(in), edge_odds_(kEdgeOdds[in.ConsumeIntegralInRange<int>(0, 3)]) {}

  FuzzedDataProvider& input() { return in_; }

  /// Whether this choice goes to an edge.
  bool edge() { return edge_odds_ != 0 && in_.ConsumeIntegralInRange<int>(1, edge_odds_) == 1; }

  /// Within [low, high] (`low` once the input runs out), or at an edge.
  double pick(double low, double high) {
    if (!edge()) return in_.ConsumeFloatingPointInRange<double>(low, high);
    switch (in_.ConsumeIntegralInRange<int>(0, 3)) {
      case 0:
        return 0.0;
      case 1:
        return low;
      case 2:
        return high;
      default:
        return -high;
    }
  }

  std::string vector3(double low, double high) {
    std::ostringstream out;
    out << pick(low, high) << ' ' << pick(low, high) << ' ' << pick(low, high);
    return out.str();
  }

 private:
  static constexpr int kEdgeOdds[] = {0, 1000, 30, 4};
  FuzzedDataProvider& in_;
  int edge_odds_;
};

/// One link: a box with its own mass and inertia.
void writeLink(std::ostringstream& urdf, Numbers& n, int index) {
  urdf << "<link name=\"l" << index << "\"><inertial><origin xyz=\"" << n.vector3(1e-4, 0.5)
       << "\"/><mass value=\"" << n.pick(1e-6, 1e3) << "\"/><inertia ixx=\"" << n.pick(1e-9, 10.0)
       << "\" iyy=\"" << n.pick(1e-9, 10.0) << "\" izz=\"" << n.pick(1e-9, 10.0)
       << "\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial>";
  if (n.input().ConsumeBool()) {
    urdf << "<collision><geometry><box size=\"" << n.vector3(1e-3, 0.2)
         << "\"/></geometry></collision>";
  }
  urdf << "</link>\n";
}

/// The joint that hangs link `child` from link `parent`: one of the four types the loader
/// takes, or at an edge one it refuses.
void writeJoint(std::ostringstream& urdf, Numbers& n, int parent, int child) {
  static constexpr const char* kTypes[] = {"revolute", "continuous", "prismatic", "fixed"};
  const char* type = n.edge() ? (n.input().ConsumeBool() ? "floating" : "planar")
                              : kTypes[n.input().ConsumeIntegralInRange<int>(0, 3)];
  urdf << "<joint name=\"j" << child << "\" type=\"" << type << "\"><parent link=\"l" << parent
       << "\"/><child link=\"l" << child << "\"/><origin xyz=\"" << n.vector3(1e-3, 1.0)
       << "\" rpy=\"" << n.vector3(0.1, 3.2) << "\"/><axis xyz=\"" << n.vector3(0.1, 1.0) << "\"/>";
  if (!n.edge()) {  // URDF asks it of revolute and prismatic joints
    urdf << "<limit lower=\"" << -n.pick(0.1, 3.0) << "\" upper=\"" << n.pick(0.1, 3.0)
         << "\" effort=\"" << n.pick(1.0, 100.0) << "\" velocity=\"" << n.pick(0.1, 10.0) << "\"/>";
  }
  if (n.input().ConsumeBool()) {
    urdf << "<dynamics damping=\"" << n.pick(1e-3, 10.0) << "\" friction=\"" << n.pick(1e-3, 10.0)
         << "\"/>";
  }
  urdf << "</joint>\n";
}

/// The tree: each link after the first hangs from one of the `width` links before it (1: a
/// chain; all of them: a star). Both spread evenly in their logarithms: most trees small and
/// quick, some of 20,000 links.
std::string generate(FuzzedDataProvider& in) {
  const auto links =
      static_cast<int>(std::lround(std::pow(kMostLinks, in.ConsumeProbability<double>())));
  const auto width =
      static_cast<int>(std::lround(std::pow(links, in.ConsumeProbability<double>())));
  Numbers n(in);
  std::ostringstream urdf;
  urdf << "<?xml version=\"1.0\"?>\n<robot name=\"generated\">\n";
  for (int i = 0; i < links; ++i) {
    writeLink(urdf, n, i);
    if (i > 0) {
      writeJoint(urdf, n, i - 1 - in.ConsumeIntegralInRange<int>(0, std::min(i, width) - 1), i);
    }
  }
  urdf << "</robot>\n";
  return urdf.str();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  const auto coordinates =
      static_cast<ambf_like::Articulation>(in.ConsumeIntegralInRange<int>(0, 2));
  const std::string urdf = generate(in);
  const auto file = fuzz::asFile(urdf, "generated.urdf");
  ambf_like::LoadedScene scene;
  try {
    scene = ambf_like::loadModelFiles({file});
  } catch (const ambf_like::LoadError&) {
    return 0;
  }
  scene.spec.world.articulation = coordinates;
  ambf_like::MeshLibrary meshes;
  try {
    ambf_like::World world(scene.spec, meshes);
    world.step(kSteps);
  } catch (const ambf_like::SimulationDiverged&) {
  }
  return 0;
}
