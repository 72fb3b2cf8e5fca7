#pragma once
// Plain description of one soft body (Bullet btSoftBody built from a mesh) as written in an ADF.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "ambf_like/load_error.hpp"
#include "ambf_like/transform.hpp"

namespace ambf_like {

/// The ADF `config:` block: btSoftBody::Config and material values (AMBF defaults).
struct SoftBodyConfig {
  double kVCF = 1, kDP = 0, kDG = 0, kLF = 0, kPR = 0, kVC = 0, kDF = 0.2, kMT = 0;
  double kCHR = 1, kKHR = 0.1, kSHR = 1, kAHR = 0.7;
  double kSRHR_CL = 0.1, kSKHR_CL = 1, kSSHR_CL = 0.5;
  double kSR_SPLT_CL = 0.5, kSK_SPLT_CL = 0.5, kSS_SPLT_CL = 0.5;
  double maxvolume = 1, timescale = 1;
  int viterations = 0, piterations = 1, diterations = 0, citerations = 4;
  double kLST = 1, kAST = 1, kVST = 1;
  int collision_flags = 0x1;   ///< btSoftBody::fCollision bits (SDF_RS by default)
  int bending_constraint = 0;  ///< bending constraint distance; 0 = none
  int clusters = 0;            ///< 0 = no clusters
  std::vector<int> fixed_nodes;
};

/// How a soft body's nodes take friction from rigid bodies.
enum class SoftContactFriction {
  Bullet,   ///< Bullet's rigid-contact projection, as AMBF has it (sticks regardless of load)
  Coulomb,  ///< |friction impulse| <= mu x normal impulse per node (SoftBodyStepSolver)
};

/// What a soft body is made of: an isotropic hyperelastic (Neo-Hookean) solid. Its tetrahedra,
/// not Bullet's links, then answer a deformation, with the same force whatever the step.
struct SoftMaterial {
  double youngs_modulus = 0.0;  ///< E, Pa
  double poissons_ratio = 0.0;  ///< nu, in (0, 0.5)
  double density = 0.0;         ///< kg/m^3; 0: the body's `mass` spread by volume instead

  /// Lame's shear modulus mu = E / (2 (1 + nu)).
  double shearModulus() const { return youngs_modulus / (2.0 * (1.0 + poissons_ratio)); }
  /// Lame's first parameter lambda = E nu / ((1 + nu)(1 - 2 nu)).
  double lameLambda() const {
    return youngs_modulus * poissons_ratio /
           ((1.0 + poissons_ratio) * (1.0 - 2.0 * poissons_ratio));
  }
};

/// A soft body: the mesh it is built from, mass, pose, margin and material/solver config.
struct SoftBodySpec {
  std::string name;
  std::filesystem::path mesh;  ///< resolved against the low resolution path
  double mass = 1.0;
  Transform location = Transform::Identity();
  double scale = 1.0;
  double margin = 0.001;  ///< set explicitly: Bullet's own default is 0.25 m
  bool randomize_constraints = false;
  SoftContactFriction contact_friction = SoftContactFriction::Bullet;  ///< `contact friction`
  int substeps = 1;  ///< `substeps` per world step (Coulomb contacts only); at least this many
  std::optional<SoftMaterial> material;  ///< `material`: elasticity from a solid's tetrahedra
  SoftBodyConfig config;
  SourceRef where;
};

}  // namespace ambf_like
