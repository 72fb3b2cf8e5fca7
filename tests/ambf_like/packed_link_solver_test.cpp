// The packed link solve is Bullet's own position solve, bit for bit, on the bodies it takes, also
// once their links' constants change; the others stay with Bullet.

#include "ambf_like/dynamics/packed_link_solver.hpp"

#include <BulletSoftBody/btSoftBody.h>
#include <BulletSoftBody/btSoftBodyHelpers.h>
#include <gtest/gtest.h>

#include <memory>

namespace {

using ambf_like::detail::PackedLinkSolver;

/// A 0.2 m square cloth in the xy plane, pinned at two corners, set up as AMBF's cloth.yaml sets
/// up its cloth: soft links, bending links two apart, everything shuffled, six iterations.
std::unique_ptr<btSoftBody> hangingCloth(btSoftBodyWorldInfo& info) {
  const btScalar s = 0.1;
  std::unique_ptr<btSoftBody> cloth(
      btSoftBodyHelpers::CreatePatch(info, btVector3(-s, -s, 0), btVector3(s, -s, 0),
                                     btVector3(-s, s, 0), btVector3(s, s, 0), 15, 15, 0, true));
  cloth->m_materials[0]->m_kLST = 0.05;
  cloth->m_cfg.kDP = 0.001;
  cloth->m_cfg.piterations = 6;
  cloth->generateBendingConstraints(2);
  cloth->randomizeConstraints();
  cloth->setTotalMass(0.1, true);
  cloth->setMass(0, 0.0);  // the two corners along -y
  cloth->setMass(14, 0.0);
  cloth->getCollisionShape()->setMargin(0.001);
  return cloth;
}

TEST(PackedLinkSolver, MovesEveryNodeExactlyAsBulletsOwnSolveDoes) {
  btSoftBodyWorldInfo info;
  info.m_gravity = btVector3(0, 0, -9.81);
  auto by_bullet = hangingCloth(info);
  auto packed = hangingCloth(info);
  PackedLinkSolver solver;
  const btScalar start_z = packed->m_nodes[packed->m_nodes.size() - 1].m_x.z();
  for (int step = 0; step < 500; ++step) {
    if (step == 250) {  // stiffer midway: Bullet refreshes the links' constants
      for (btSoftBody* cloth : {by_bullet.get(), packed.get()}) {
        cloth->m_materials[0]->m_kLST = 0.2;
        cloth->m_bUpdateRtCst = true;
      }
    }
    if (packed->m_bUpdateRtCst) solver.forget(*packed);  // as SoftBodyStepSolver does
    by_bullet->predictMotion(0.001);
    packed->predictMotion(0.001);
    ASSERT_TRUE(PackedLinkSolver::handles(*packed));
    by_bullet->solveConstraints();
    solver.solve(*packed);
    by_bullet->integrateMotion();
    packed->integrateMotion();
  }
  // The free corner has swung down (the test is not of a cloth at rest)...
  EXPECT_LT(packed->m_nodes[packed->m_nodes.size() - 1].m_x.z(), start_z - 0.05);
  // ... and every node is where Bullet put it, at the velocity Bullet gave it: the same bits.
  for (int i = 0; i < packed->m_nodes.size(); ++i) {
    for (int axis = 0; axis < 3; ++axis) {
      ASSERT_EQ(packed->m_nodes[i].m_x[axis], by_bullet->m_nodes[i].m_x[axis]) << "node " << i;
      ASSERT_EQ(packed->m_nodes[i].m_v[axis], by_bullet->m_nodes[i].m_v[axis]) << "node " << i;
    }
  }
}

TEST(PackedLinkSolver, LeavesToBulletTheBodiesWhoseStepIsMoreThanLinks) {
  btSoftBodyWorldInfo info;
  auto cloth = hangingCloth(info);
  EXPECT_TRUE(PackedLinkSolver::handles(*cloth));
  cloth->m_cfg.viterations = 1;  // velocity iterations
  EXPECT_FALSE(PackedLinkSolver::handles(*cloth));
  cloth->m_cfg.viterations = 0;
  cloth->m_cfg.diterations = 1;  // drift iterations
  EXPECT_FALSE(PackedLinkSolver::handles(*cloth));
  cloth->m_cfg.diterations = 0;
  cloth->m_cfg.piterations = 0;  // Bullet then leaves the velocities as they are
  EXPECT_FALSE(PackedLinkSolver::handles(*cloth));
  cloth->m_cfg.piterations = 6;
  btSoftBody::Anchor anchor;
  anchor.m_node = &cloth->m_nodes[0];
  cloth->m_anchors.push_back(anchor);  // anchors are solved between the links' iterations
  EXPECT_FALSE(PackedLinkSolver::handles(*cloth));
}

}  // namespace
