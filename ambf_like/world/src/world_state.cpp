// World::saveState and World::restoreState: a World's state between steps, and the canonical
// rebuild of its collision caches, run by both, that makes a restored run repeat the saved one
// bit for bit.

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletSoftBody/btSoftBody.h>
#include <btBulletDynamicsCommon.h>

#include <map>
#include <stdexcept>
#include <utility>

#include "ambf_like/dynamics/soft_body_step_solver.hpp"
#include "collision_object_motion.hpp"
#include "world_impl.hpp"

namespace ambf_like {

// What WorldState holds of each object (named, not anonymous: WorldState's members are of them).
namespace detail {

/// A rigid body's motion.
struct RigidState {
  detail::CollisionObjectMotion object;
  btVector3 linear, angular;
};

/// A soft body's members its next steps depend on, named as Bullet names them (copyMembers
/// copies them either way), and the volumes of its trees' leaves.
struct SoftState {
  btAlignedObjectArray<btSoftBody::Node> m_nodes;
  btAlignedObjectArray<btSoftBody::Face> m_faces;
  btAlignedObjectArray<btSoftBody::Link> m_links;
  btAlignedObjectArray<btSoftBody::Tetra> m_tetras;
  btAlignedObjectArray<btSoftBody::Anchor> m_anchors;
  btAlignedObjectArray<btSoftBody::RContact> m_rcontacts;
  btAlignedObjectArray<btSoftBody::SContact> m_scontacts;
  btSoftBody::Pose m_pose;
  btSoftBody::SolverState m_sst;
  btVector3 m_bounds[2];
  btScalar m_timeacc = 0;
  bool m_bUpdateRtCst = false;
  btTransform transform;
  int activation = 0;
  btScalar deactivation_time = 0;
  std::vector<std::optional<btDbvtVolume>> node_leaves, face_leaves;  ///< none: no leaf
};

/// A contact manifold between two collision objects, with its points (their impulses are the
/// next step's warm start).
struct ManifoldState {
  const btCollisionObject* body0;
  const btCollisionObject* body1;
  std::vector<btManifoldPoint> points;
};

}  // namespace detail

namespace {

using detail::ManifoldState;
using detail::RigidState;
using detail::SoftState;

RigidState rigidStateOf(const btRigidBody& b) {
  return {detail::motionOf(b), b.getLinearVelocity(), b.getAngularVelocity()};
}

void restoreRigid(btRigidBody& b, const RigidState& s) {
  b.setCenterOfMassTransform(s.object.pose);  // and the inertia tensor in the world frame
  detail::restoreMotion(b, s.object);
  b.setLinearVelocity(s.linear);
  b.setAngularVelocity(s.angular);
  b.clearForces();
}

template <typename Items>
std::vector<std::optional<btDbvtVolume>> leavesOf(const Items& items) {
  std::vector<std::optional<btDbvtVolume>> out(static_cast<std::size_t>(items.size()));
  for (int i = 0; i < items.size(); ++i) {
    if (items[i].m_leaf) out[static_cast<std::size_t>(i)] = items[i].m_leaf->volume;
  }
  return out;
}

/// Copies the members a SoftState keeps between it and a btSoftBody, the contacts aside (a
/// restore puts them back after its narrowphase, which makes its own).
template <typename To, typename From>
void copyMembers(To& to, const From& from) {
  to.m_nodes = from.m_nodes;
  to.m_faces = from.m_faces;
  to.m_links = from.m_links;
  to.m_tetras = from.m_tetras;
  to.m_anchors = from.m_anchors;
  to.m_pose = from.m_pose;
  to.m_sst = from.m_sst;
  to.m_bounds[0] = from.m_bounds[0];
  to.m_bounds[1] = from.m_bounds[1];
  to.m_timeacc = from.m_timeacc;
  to.m_bUpdateRtCst = from.m_bUpdateRtCst;
}

SoftState softStateOf(const btSoftBody& b) {
  SoftState s;
  copyMembers(s, b);
  s.m_rcontacts = b.m_rcontacts;
  s.m_scontacts = b.m_scontacts;
  s.transform = b.getWorldTransform();
  s.activation = b.getActivationState();
  s.deactivation_time = b.getDeactivationTime();
  s.node_leaves = leavesOf(b.m_nodes);
  s.face_leaves = leavesOf(b.m_faces);
  return s;
}

/// Rebuilds a tree from its leaves' volumes, inserted in item order.
template <typename Items>
void rebuildTree(btDbvt& tree, Items& items,
                 const std::vector<std::optional<btDbvtVolume>>& leaves) {
  tree.clear();
  for (int i = 0; i < items.size(); ++i) {
    const auto& leaf = leaves[static_cast<std::size_t>(i)];
    items[i].m_leaf = leaf ? tree.insert(*leaf, &items[i]) : nullptr;
  }
}

void restoreSoft(btSoftBody& b, const SoftState& s) {
  if (b.m_nodes.size() != s.m_nodes.size() || b.m_faces.size() != s.m_faces.size() ||
      b.m_links.size() != s.m_links.size() || b.m_tetras.size() != s.m_tetras.size()) {
    throw std::invalid_argument("a world state of another soft body");
  }
  // Same sizes: the arrays keep their storage, so the pointers between them stay valid.
  copyMembers(b, s);
  b.setWorldTransform(s.transform);
  b.forceActivationState(s.activation);
  b.setDeactivationTime(s.deactivation_time);
}

}  // namespace

/// Everything World::saveState captures.
class WorldState {
 public:
  std::uint64_t world = 0;  ///< the id of the world it came from
  double time = 0.0;
  std::uint64_t steps = 0;
  std::vector<RigidState> rigid;
  std::vector<Joint::State> joints;
  std::vector<detail::Articulation::State> articulations;
  /// The joint limits in the world, in the solver's order.
  std::vector<btMultiBodyConstraint*> limits;
  std::vector<SoftState> soft;
  std::vector<ManifoldState> manifolds;
  std::shared_ptr<const detail::SoftBodyStepSolver::State> soft_solver;
  std::vector<detail::SoftBodySleeper::Rest> sleep;
  std::vector<ConstraintActuator::Hold> holds;
  std::vector<ProximitySensor::State> sensors;
};

namespace {

/// Destroys every broadphase proxy and creates them again in the world's object order on an
/// emptied broadphase (btDbvtBroadphase::resetPool), then runs the narrowphase once, so the pairs,
/// the collision algorithms and their manifolds exist in one order whatever the history.
void rebuildCollisionCaches(btDiscreteDynamicsWorld& world) {
  auto& broadphase = static_cast<btDbvtBroadphase&>(*world.getBroadphase());
  btDispatcher& dispatcher = *world.getDispatcher();
  btCollisionObjectArray& objects = world.getCollisionObjectArray();
  struct Filter {
    int group, mask;
  };
  std::vector<Filter> filters(static_cast<std::size_t>(objects.size()));
  for (int i = 0; i < objects.size(); ++i) {
    btBroadphaseProxy* proxy = objects[i]->getBroadphaseHandle();
    filters[static_cast<std::size_t>(i)] = {proxy->m_collisionFilterGroup,
                                            proxy->m_collisionFilterMask};
    broadphase.destroyProxy(proxy, &dispatcher);
    objects[i]->setBroadphaseHandle(nullptr);
  }
  broadphase.resetPool(&dispatcher);
  for (int i = 0; i < objects.size(); ++i) {
    btCollisionObject& o = *objects[i];
    btVector3 low, high;
    o.getCollisionShape()->getAabb(o.getWorldTransform(), low, high);
    const Filter& f = filters[static_cast<std::size_t>(i)];
    o.setBroadphaseHandle(broadphase.createProxy(low, high, o.getCollisionShape()->getShapeType(),
                                                 &o, f.group, f.mask, &dispatcher));
  }
  world.updateAabbs();
  world.computeOverlappingPairs();
  dispatcher.dispatchAllCollisionPairs(broadphase.getOverlappingPairCache(),
                                       world.getDispatchInfo(), &dispatcher);
}

/// The articulations' constraints in the world, in its order (empty: no articulations).
std::vector<btMultiBodyConstraint*> multiBodyConstraintsOf(detail::BulletWorld& bullet,
                                                           bool articulated) {
  std::vector<btMultiBodyConstraint*> out;
  if (!articulated) return out;
  btMultiBodyDynamicsWorld& world = bullet.articulations();
  for (int i = 0; i < world.getNumMultiBodyConstraints(); ++i) {
    out.push_back(world.getMultiBodyConstraint(i));
  }
  return out;
}

/// Puts the saved points into the manifolds the narrowphase just made (matched by their bodies,
/// in order), and empties those it made anew.
void restoreManifolds(btDispatcher& dispatcher, const std::vector<ManifoldState>& saved) {
  std::map<std::pair<const void*, const void*>, std::vector<const ManifoldState*>> by_pair;
  for (const auto& m : saved) by_pair[{m.body0, m.body1}].push_back(&m);
  std::map<std::pair<const void*, const void*>, std::size_t> used;
  for (int i = 0; i < dispatcher.getNumManifolds(); ++i) {
    btPersistentManifold& live = *dispatcher.getManifoldByIndexInternal(i);
    live.clearManifold();
    const std::pair<const void*, const void*> pair{live.getBody0(), live.getBody1()};
    const auto it = by_pair.find(pair);
    const std::size_t k = used[pair]++;
    if (it == by_pair.end() || k >= it->second.size()) continue;
    for (const btManifoldPoint& point : it->second[k]->points) live.addManifoldPoint(point);
  }
}

/// Rebuilds the collision caches from what `state` holds, in one order whatever the history: the
/// soft bodies' trees, the broadphase, the narrowphase's manifolds with the saved points, the
/// soft bodies' contacts.
void rebuildCaches(btDiscreteDynamicsWorld& world,
                   const std::vector<std::unique_ptr<SoftBody>>& soft_bodies,
                   const WorldState& state) {
  for (std::size_t i = 0; i < soft_bodies.size(); ++i) {
    btSoftBody& b = soft_bodies[i]->bullet();
    rebuildTree(b.m_ndbvt, b.m_nodes, state.soft[i].node_leaves);
    rebuildTree(b.m_fdbvt, b.m_faces, state.soft[i].face_leaves);
  }
  rebuildCollisionCaches(world);
  restoreManifolds(*world.getDispatcher(), state.manifolds);
  for (std::size_t i = 0; i < soft_bodies.size(); ++i) {  // the narrowphase made its own
    btSoftBody& b = soft_bodies[i]->bullet();
    b.m_rcontacts = state.soft[i].m_rcontacts;
    b.m_scontacts = state.soft[i].m_scontacts;
  }
}

}  // namespace

std::shared_ptr<const WorldState> World::saveState() {
  Impl& w = *impl_;
  auto state = std::make_shared<WorldState>();
  state->world = w.id;
  state->time = w.time;
  state->steps = w.steps;
  for (const auto& b : w.bodies) state->rigid.push_back(rigidStateOf(b->bullet()));
  for (const auto& j : w.joints) state->joints.push_back(j->joint->state());
  for (const auto& a : w.articulations) state->articulations.push_back(a->state());
  state->limits = multiBodyConstraintsOf(w.bullet, w.articulated);
  for (const auto& s : w.soft_bodies) state->soft.push_back(softStateOf(s->bullet()));
  btDispatcher& dispatcher = *w.world.getDispatcher();
  for (int i = 0; i < dispatcher.getNumManifolds(); ++i) {
    const btPersistentManifold& m = *dispatcher.getManifoldByIndexInternal(i);
    ManifoldState& saved =
        state->manifolds.emplace_back(ManifoldState{m.getBody0(), m.getBody1(), {}});
    for (int k = 0; k < m.getNumContacts(); ++k) saved.points.push_back(m.getContactPoint(k));
  }
  state->soft_solver = w.bullet.softBodySolver().state();
  if (w.sleeper) state->sleep = w.sleeper->state();
  for (const auto& a : w.actuators) state->holds.push_back(a->hold());
  for (const auto& s : w.sensors) state->sensors.push_back(s->state());
  rebuildCaches(w.world, w.soft_bodies, *state);  // as every restore of it will
  return state;
}

void World::restoreState(const WorldState& state) {
  Impl& w = *impl_;
  if (state.world != w.id) {
    throw std::invalid_argument("World::restoreState: a state saved by another world");
  }
  for (std::size_t i = 0; i < w.actuators.size(); ++i) {
    if (!w.actuators[i]->hold().sameAs(state.holds[i])) {
      throw std::logic_error("World::restoreState: actuator '" + w.actuators[i]->qualifiedName() +
                             "' holds otherwise than when the state was saved (restoring across "
                             "an attach or a release is not supported)");
    }
  }
  w.time = state.time;
  w.steps = state.steps;
  for (std::size_t i = 0; i < w.bodies.size(); ++i) {
    restoreRigid(w.bodies[i]->bullet(), state.rigid[i]);
  }
  for (std::size_t i = 0; i < w.joints.size(); ++i) w.joints[i]->joint->restore(state.joints[i]);
  for (std::size_t i = 0; i < w.articulations.size(); ++i) {
    w.articulations[i]->restore(state.articulations[i]);
  }
  if (w.articulated) {  // the limits in the world, in the saved order
    btMultiBodyDynamicsWorld& world = w.bullet.articulations();
    for (btMultiBodyConstraint* c : multiBodyConstraintsOf(w.bullet, true)) {
      world.removeMultiBodyConstraint(c);
    }
    for (btMultiBodyConstraint* c : state.limits) world.addMultiBodyConstraint(c);
  }
  for (std::size_t i = 0; i < w.soft_bodies.size(); ++i) {
    restoreSoft(w.soft_bodies[i]->bullet(), state.soft[i]);
  }
  rebuildCaches(w.world, w.soft_bodies, state);
  w.bullet.softBodySolver().restore(*state.soft_solver);
  if (w.sleeper) w.sleeper->restore(state.sleep);
  for (std::size_t i = 0; i < w.sensors.size(); ++i) w.sensors[i]->restore(state.sensors[i]);
}

}  // namespace ambf_like
