// Keeping a soft body's face tree and normals only where something reads them changes no node's
// motion: a lone cloth and two cloths that collide move to the same bits as with Bullet's solver.

#include "ambf_like/dynamics/soft_body_upkeep.hpp"

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h>
#include <BulletSoftBody/btDefaultSoftBodySolver.h>
#include <BulletSoftBody/btSoftBodyHelpers.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "ambf_like/dynamics/soft_body_step_solver.hpp"

namespace {

using ambf_like::detail::faceTreeIsRead;
using ambf_like::detail::normalsAreRead;
using ambf_like::detail::SoftBodyStepSolver;
using Collision = btSoftBody::fCollision;

/// A Bullet soft-rigid world around the given soft-body solver.
class SoftWorld {
 public:
  explicit SoftWorld(std::unique_ptr<btSoftBodySolver> solver)
      : dispatcher_(&configuration_),
        solver_(std::move(solver)),
        world_(&dispatcher_, &broadphase_, &constraints_, &configuration_, solver_.get()) {
    world_.setGravity(btVector3(0, 0, -9.81));
    world_.getWorldInfo().m_gravity = btVector3(0, 0, -9.81);
    world_.getWorldInfo().m_sparsesdf.Initialize();
  }
  ~SoftWorld() {
    for (auto& body : bodies_) world_.removeSoftBody(body.get());
  }
  SoftWorld(const SoftWorld&) = delete;
  SoftWorld& operator=(const SoftWorld&) = delete;

  /// A 0.2 m square cloth set up as AMBF's cloth.yaml (soft links, bending links two apart,
  /// shuffled, six iterations, soft-soft vertex-face contacts only), at height `z`, pinned at the
  /// two corners of its `pinned_y` edge.
  btSoftBody& addCloth(btScalar z, btScalar pinned_y) {
    const btScalar s = 0.1;
    bodies_.emplace_back(btSoftBodyHelpers::CreatePatch(world_.getWorldInfo(), btVector3(-s, -s, z),
                                                        btVector3(s, -s, z), btVector3(-s, s, z),
                                                        btVector3(s, s, z), 15, 15, 0, true));
    btSoftBody& cloth = *bodies_.back();
    cloth.m_materials[0]->m_kLST = 0.05;
    cloth.m_cfg.kDP = 0.001;
    cloth.m_cfg.piterations = 6;
    cloth.m_cfg.collisions = Collision::VF_SS;
    cloth.generateBendingConstraints(2);
    cloth.randomizeConstraints();
    cloth.setTotalMass(0.1, true);
    const int row = pinned_y < 0 ? 0 : 14 * 15;
    cloth.setMass(row, 0.0);
    cloth.setMass(row + 14, 0.0);
    cloth.getCollisionShape()->setMargin(0.005);
    world_.addSoftBody(&cloth);
    return cloth;
  }
  void step(int steps) {
    for (int i = 0; i < steps; ++i) world_.stepSimulation(0.001, 0);
  }
  const btSoftBody& body(std::size_t i) const { return *bodies_[i]; }

 private:
  btSoftBodyRigidBodyCollisionConfiguration configuration_;
  btCollisionDispatcher dispatcher_;
  btDbvtBroadphase broadphase_;
  btSequentialImpulseConstraintSolver constraints_;
  std::unique_ptr<btSoftBodySolver> solver_;
  btSoftRigidDynamicsWorld world_;
  std::vector<std::unique_ptr<btSoftBody>> bodies_;
};

void expectSameNodes(const btSoftBody& ours, const btSoftBody& bullets) {
  ASSERT_EQ(ours.m_nodes.size(), bullets.m_nodes.size());
  for (int i = 0; i < ours.m_nodes.size(); ++i) {
    for (int axis = 0; axis < 3; ++axis) {
      ASSERT_EQ(ours.m_nodes[i].m_x[axis], bullets.m_nodes[i].m_x[axis]) << "node " << i;
      ASSERT_EQ(ours.m_nodes[i].m_v[axis], bullets.m_nodes[i].m_v[axis]) << "node " << i;
    }
  }
}

TEST(SoftBodyUpkeep, ALoneClothKeepsNoFaceTreeAndMovesExactlyAsWithBulletsSolver) {
  SoftWorld ours(std::make_unique<SoftBodyStepSolver>());
  SoftWorld bullets(std::make_unique<btDefaultSoftBodySolver>());
  ours.addCloth(0.0, -1);
  bullets.addCloth(0.0, -1);
  ours.step(500);
  bullets.step(500);
  EXPECT_FALSE(bullets.body(0).m_fdbvt.empty());  // Bullet refits it every step...
  EXPECT_TRUE(ours.body(0).m_fdbvt.empty());      // ... for no reader
  const btScalar free_corner_z = ours.body(0).m_nodes[14 * 15 + 14].m_x.z();
  EXPECT_LT(free_corner_z, -0.05);  // it has swung down: not a test of a cloth at rest
  expectSameNodes(ours.body(0), bullets.body(0));
}

TEST(SoftBodyUpkeep, TwoClothsThatCollideKeepTheirTreesAndMoveExactlyAsWithBulletsSolver) {
  SoftWorld ours(std::make_unique<SoftBodyStepSolver>());
  SoftWorld bullets(std::make_unique<btDefaultSoftBodySolver>());
  for (SoftWorld* world : {&ours, &bullets}) {
    world->addCloth(0.0, -1);   // swings down from its -y edge...
    world->addCloth(0.02, +1);  // ... and this one from its +y edge, through it
  }
  int steps_in_contact = 0;
  for (int step = 0; step < 400; ++step) {
    ours.step(1);
    bullets.step(1);
    steps_in_contact += ours.body(0).m_scontacts.size() + ours.body(1).m_scontacts.size() > 0;
  }
  EXPECT_GT(steps_in_contact, 10);
  EXPECT_FALSE(ours.body(0).m_fdbvt.empty());
  EXPECT_FALSE(ours.body(1).m_fdbvt.empty());
  expectSameNodes(ours.body(0), bullets.body(0));
  expectSameNodes(ours.body(1), bullets.body(1));
}

TEST(SoftBodyUpkeep, AFaceTreeIsBuiltAgainWhenASecondBodyCouldReadIt) {
  SoftWorld ours(std::make_unique<SoftBodyStepSolver>());
  const btSoftBody& first = ours.addCloth(0.0, -1);
  ours.step(10);
  EXPECT_TRUE(first.m_fdbvt.empty());
  ours.addCloth(0.5, -1);
  ours.step(1);
  EXPECT_FALSE(first.m_fdbvt.empty());
}

TEST(SoftBodyUpkeep, SaysWhatReadsNormalsAndFaceTrees) {
  SoftWorld world(std::make_unique<btDefaultSoftBodySolver>());
  btSoftBody& cloth = world.addCloth(0.0, -1);
  btAlignedObjectArray<btSoftBody*> alone;
  alone.push_back(&cloth);
  EXPECT_FALSE(normalsAreRead(cloth));
  EXPECT_FALSE(faceTreeIsRead(cloth, alone));
  cloth.m_cfg.kLF = 0.1;  // aerodynamic lift reads the normals
  EXPECT_TRUE(normalsAreRead(cloth));
  cloth.m_cfg.kLF = 0;
  cloth.m_cfg.kPR = -1;  // so does pressure, of either sign
  EXPECT_TRUE(normalsAreRead(cloth));
  cloth.m_cfg.kPR = 0;
  btSoftBody& other = world.addCloth(0.5, -1);
  btAlignedObjectArray<btSoftBody*> both = alone;
  both.push_back(&other);
  EXPECT_TRUE(faceTreeIsRead(cloth, both));
  // Bullet dispatches on the modes the two share: both VF_SS and CL_SS is neither.
  cloth.m_cfg.collisions = other.m_cfg.collisions = Collision::VF_SS | Collision::CL_SS;
  EXPECT_FALSE(faceTreeIsRead(cloth, both));
  cloth.m_cfg.collisions |= Collision::SDF_RDF;  // reads its own faces
  EXPECT_TRUE(faceTreeIsRead(cloth, both));
  EXPECT_TRUE(normalsAreRead(cloth));
}

}  // namespace
