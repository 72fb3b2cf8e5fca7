#include <sstream>

#include "adf_readers.hpp"

namespace ambf_like::detail {

namespace {

/// Reads `key` into `value` if present, checking it lies in [low, high].
void readBounded(const YamlView& config, const char* key, double low, double high, double& value) {
  auto node = config.find(key);
  if (!node) return;
  value = node->asDouble();
  if (value < low || value > high) {
    std::ostringstream range;
    range << key << " must be in [" << low << ", " << high << "]";
    node->fail(range.str());
  }
}

/// Reads `key` into `value` if present, checking it lies in [minimum, maximum]: beyond the
/// maximum one step would take seconds or more.
void readCount(const YamlView& config, const char* key, int minimum, int maximum, int& value) {
  auto node = config.find(key);
  if (!node) return;
  value = node->asInt();
  if (value < minimum || value > maximum) {
    node->fail(std::string(key) + " must be " + std::to_string(minimum) + " to " +
               std::to_string(maximum));
  }
}

constexpr int kMaxIterations = 1000;

constexpr double kInf = 1e30;

/// Bullet's classic soft world treats the rigid (0x0f) and soft (0xf0) parts of the flags as two
/// switches, not bit sets: any other combination silently turns that kind of contact off.
void checkCollisionFlags(const YamlView& node, int flags, int clusters) {
  const int rigid = flags & 0x0f;
  const int soft = flags & 0xf0;
  if (flags < 0 || (flags & ~0xff) != 0 || rigid == 0x4) {
    node.fail("flags " + std::to_string(flags) +
              ": bits beyond SDF_RS/CL_RS/VF_SS/CL_SS belong to Bullet's deformable-body "
              "pipeline, which this simulator does not use");
  }
  if (rigid != 0 && rigid != 0x1 && rigid != 0x2) {
    node.fail("flags " + std::to_string(flags) +
              ": rigid contact is one mode, SDF_RS (0x1) or CL_RS (0x2); Bullet ignores both when "
              "they are combined");
  }
  if (soft != 0 && soft != 0x10 && soft != 0x20) {
    node.fail("flags " + std::to_string(flags) +
              ": soft-soft contact is one mode, VF_SS (0x10) or CL_SS (0x20); with any other "
              "combination (CL_SELF 0x40 included) Bullet 3.24 uses none");
  }
  if ((rigid == 0x2 || soft == 0x20) && clusters == 0) {
    node.fail("flags " + std::to_string(flags) +
              ": cluster collision (CL_RS, CL_SS) needs 'clusters'");
  }
}

/// The keys of a soft body's `config:` block.
// clang-format off
constexpr std::string_view kConfigKeys[] = {
    "kLST", "kAST", "kVST", "kVCF", "kDP", "kDG", "kLF", "kPR", "kVC", "kDF", "kMT", "kCHR",
    "kKHR", "kSHR", "kAHR", "kSRHR_CL", "kSKHR_CL", "kSSHR_CL", "kSR_SPLT_CL", "kSK_SPLT_CL",
    "kSS_SPLT_CL", "maxvolume", "timescale", "viterations", "piterations", "diterations",
    "citerations", "flags", "bending constraint", "clusters", "fixed nodes", "margin", "cutting"};
// clang-format on

SoftBodyConfig readConfig(const YamlView& node, LoadContext& context) {
  node.checkKeys(kConfigKeys, context.keyCheck());
  SoftBodyConfig c;
  readBounded(node, "kLST", 0, 1, c.kLST);
  readBounded(node, "kAST", 0, 1, c.kAST);
  readBounded(node, "kVST", 0, 1, c.kVST);
  readBounded(node, "kVCF", 0, kInf, c.kVCF);
  readBounded(node, "kDP", 0, 1, c.kDP);
  readBounded(node, "kDG", 0, kInf, c.kDG);
  readBounded(node, "kLF", 0, kInf, c.kLF);
  readBounded(node, "kPR", -kInf, kInf, c.kPR);
  readBounded(node, "kVC", 0, kInf, c.kVC);
  readBounded(node, "kDF", 0, 1, c.kDF);
  readBounded(node, "kMT", 0, 1, c.kMT);
  readBounded(node, "kCHR", 0, 1, c.kCHR);
  readBounded(node, "kKHR", 0, 1, c.kKHR);
  readBounded(node, "kSHR", 0, 1, c.kSHR);
  readBounded(node, "kAHR", 0, 1, c.kAHR);
  readBounded(node, "kSRHR_CL", 0, 1, c.kSRHR_CL);
  readBounded(node, "kSKHR_CL", 0, 1, c.kSKHR_CL);
  readBounded(node, "kSSHR_CL", 0, 1, c.kSSHR_CL);
  readBounded(node, "kSR_SPLT_CL", 0, 1, c.kSR_SPLT_CL);
  readBounded(node, "kSK_SPLT_CL", 0, 1, c.kSK_SPLT_CL);
  readBounded(node, "kSS_SPLT_CL", 0, 1, c.kSS_SPLT_CL);
  readBounded(node, "maxvolume", 0, kInf, c.maxvolume);
  readBounded(node, "timescale", 0, kInf, c.timescale);
  readCount(node, "viterations", 0, kMaxIterations, c.viterations);
  readCount(node, "piterations", 1, kMaxIterations, c.piterations);
  readCount(node, "diterations", 0, kMaxIterations, c.diterations);
  readCount(node, "citerations", 0, kMaxIterations, c.citerations);
  readCount(node, "bending constraint", 0, 16, c.bending_constraint);
  readCount(node, "clusters", 0, 100000, c.clusters);
  if (auto flags = node.find("flags")) {
    c.collision_flags = flags->asInt();
    checkCollisionFlags(*flags, c.collision_flags, c.clusters);
  }
  if (auto fixed = node.find("fixed nodes")) {
    for (const auto& index : fixed->elements()) {
      const int value = index.asInt();
      if (value < 0) index.fail("node index must not be negative");
      c.fixed_nodes.push_back(value);
    }
  }
  return c;
}

/// Every soft-body key of ADF 1.0 outside `config`.
// clang-format off
constexpr std::string_view kSoftBodyKeys[] = {
    "name", "namespace", "mesh", "mass", "location", "scale", "collision margin",
    "randomize constraints", "config", "inertial offset", "color", "color rgba",
    "color components", "visible", "shaders", "plugins", "passive", "publish frequency",
    "high resolution path", "low resolution path", "linear gain", "angular gain", "use material",
    "redundant", "detached", "contact friction", "substeps", "material"};
// clang-format on

/// A required, strictly positive and physically bounded number of the `material:` block.
double readMaterialValue(const YamlView& material, const char* key, double low, double high,
                         const char* unit) {
  const YamlView value = material[key];
  const double number = value.asDouble();
  if (!(number > low && number < high)) {
    std::ostringstream range;
    range << key << " must lie in (" << low << ", " << high << ") " << unit << ", not " << number;
    value.fail(range.str());
  }
  return number;
}

/// The `material:` block: Young's modulus and Poisson's ratio (required), density (or the body's
/// `mass`, one of the two).
SoftMaterial readMaterial(const YamlView& node, const YamlView& material, LoadContext& context) {
  material.checkKeys({"young's modulus", "poisson's ratio", "density"}, context.keyCheck());
  SoftMaterial m;
  // From a gel (1 kPa) to a stiff rubber's tenfold (1 GPa): beyond that a soft body is the
  // wrong model.
  m.youngs_modulus = readMaterialValue(material, "young's modulus", 0.0, 1e9, "Pa");
  m.poissons_ratio = readMaterialValue(material, "poisson's ratio", 0.0, 0.5, "");
  if (material.has("density")) {
    m.density = readMaterialValue(material, "density", 0.0, 1e5, "kg/m^3");
    if (node.has("mass")) {
      node["mass"].fail("give a soft body's 'mass' or its material's 'density', not both");
    }
  } else if (!node.has("mass")) {
    material.fail("a material needs a 'density' (or the body a 'mass')");
  }
  return m;
}

}  // namespace

SoftBodySpec readSoftBody(const YamlView& node, const std::string& identifier,
                          const MeshDirectories& dirs, LoadContext& context) {
  node.checkKeys(kSoftBodyKeys, context.keyCheck());
  noteNotSimulated(node, context);
  SoftBodySpec soft;
  soft.where = node.where();
  soft.name = node.has("name") ? node["name"].asString() : stripPrefix(identifier);
  if (auto material = node.find("material")) soft.material = readMaterial(node, *material, context);
  if (!soft.material || soft.material->density == 0.0) {
    soft.mass = node["mass"].asDouble();
    if (!(soft.mass > 0.0 && soft.mass < 1e6)) {
      node["mass"].fail("a soft body needs a mass greater than zero (and below 1e6 kg)");
    }
  }
  if (auto v = node.find("location")) soft.location = v->asPose();
  if (auto v = node.find("scale")) {
    soft.scale = v->asDouble();
    if (!(soft.scale >= 1e-6 && soft.scale <= 1e6)) v->fail("scale must be 1e-6 to 1e6");
  }
  soft.randomize_constraints = node.getBool("randomize constraints", false);
  if (auto friction = node.find("contact friction")) {
    const std::string model = friction->asString();
    if (model == "coulomb") {
      soft.contact_friction = SoftContactFriction::Coulomb;
    } else if (model != "bullet") {
      friction->fail("contact friction must be 'bullet' (AMBF's) or 'coulomb', not '" + model +
                     "'");
    }
  }
  if (soft.material) {
    // A material's forces are the solver's own contacts' business (SoftBodyStepSolver).
    if (auto friction = node.find("contact friction");
        friction && soft.contact_friction != SoftContactFriction::Coulomb) {
      friction->fail("a soft body with a material takes 'contact friction: coulomb'");
    }
    soft.contact_friction = SoftContactFriction::Coulomb;
  }
  if (auto substeps = node.find("substeps")) {
    soft.substeps = substeps->asInt();
    if (soft.substeps < 1 || soft.substeps > 1000) substeps->fail("substeps must be 1 to 1000");
    if (soft.contact_friction != SoftContactFriction::Coulomb && soft.substeps > 1) {
      substeps->fail("substeps are taken by soft bodies with 'contact friction: coulomb' only");
    }
  }
  if (auto config = node.find("config")) soft.config = readConfig(*config, context);

  const auto margin = node.find("collision margin");
  const auto config_margin = node.find("config") ? node["config"].find("margin") : std::nullopt;
  if (margin) {
    soft.margin = margin->asDouble();
    if (config_margin) {
      context.warn(config_margin->where(), "'collision margin' of the body is used instead");
    }
  } else if (config_margin) {
    soft.margin =
        config_margin->asDouble();  // AMBF ignores this key (a known defect); we honour it
  }
  if (soft.margin < 0.0) node.fail("collision margin must not be negative");

  const MeshDirectories local = meshDirectoriesOf(node, dirs);
  const auto mesh_node = node["mesh"];
  std::string tried;
  auto mesh = findMesh(mesh_node.asString(), {local.low_res, local.high_res}, tried);
  if (!mesh) {
    // A soft body is nothing but its mesh: it cannot be skipped into existence.
    mesh_node.fail("soft body '" + soft.name + "': mesh file '" + mesh_node.asString() +
                   "' not found (looked for " + tried + ")");
  }
  soft.mesh = *mesh;
  return soft;
}

}  // namespace ambf_like::detail
