// World::saveState and World::restoreState: a World's state between steps, and the canonical
// rebuild of its collision caches that makes a restored run repeat the saved one bit for bit.

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletSoftBody/btSoftBody.h>
#include <btBulletDynamicsCommon.h>

#include <map>
#include <stdexcept>
#include <utility>

#include "ambf_like/dynamics/coulomb_contact_solver.hpp"
#include "world_impl.hpp"

namespace ambf_like {

namespace {

/// A rigid body's motion.
struct RigidState {
  btTransform pose, interpolation_pose;
  btVector3 linear, angular, interpolation_linear, interpolation_angular;
  int activation = 0;
  btScalar deactivation_time = 0, hit_fraction = 1;
};

/// A soft body's arrays as Bullet keeps them, and the volumes of its trees' leaves.
struct SoftState {
  btAlignedObjectArray<btSoftBody::Node> nodes;
  btAlignedObjectArray<btSoftBody::Face> faces;
  btAlignedObjectArray<btSoftBody::Link> links;
  btAlignedObjectArray<btSoftBody::Tetra> tetras;
  btAlignedObjectArray<btSoftBody::Anchor> anchors;
  btAlignedObjectArray<btSoftBody::RContact> rigid_contacts;
  btAlignedObjectArray<btSoftBody::SContact> soft_contacts;
  btSoftBody::Pose pose;
  btSoftBody::SolverState solver;
  btVector3 bounds[2];
  btScalar time_accumulated = 0;
  bool update_rest_constants = false;
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

RigidState rigidStateOf(const btRigidBody& b) {
  return {b.getWorldTransform(),
          b.getInterpolationWorldTransform(),
          b.getLinearVelocity(),
          b.getAngularVelocity(),
          b.getInterpolationLinearVelocity(),
          b.getInterpolationAngularVelocity(),
          b.getActivationState(),
          b.getDeactivationTime(),
          b.getHitFraction()};
}

void restoreRigid(btRigidBody& b, const RigidState& s) {
  b.setCenterOfMassTransform(s.pose);  // and the inertia tensor in the world frame
  b.setInterpolationWorldTransform(s.interpolation_pose);
  b.setLinearVelocity(s.linear);
  b.setAngularVelocity(s.angular);
  b.setInterpolationLinearVelocity(s.interpolation_linear);
  b.setInterpolationAngularVelocity(s.interpolation_angular);
  b.forceActivationState(s.activation);
  b.setDeactivationTime(s.deactivation_time);
  b.setHitFraction(s.hit_fraction);
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

SoftState softStateOf(const btSoftBody& b) {
  SoftState s;
  s.nodes = b.m_nodes;
  s.faces = b.m_faces;
  s.links = b.m_links;
  s.tetras = b.m_tetras;
  s.anchors = b.m_anchors;
  s.rigid_contacts = b.m_rcontacts;
  s.soft_contacts = b.m_scontacts;
  s.pose = b.m_pose;
  s.solver = b.m_sst;
  s.bounds[0] = b.m_bounds[0];
  s.bounds[1] = b.m_bounds[1];
  s.time_accumulated = b.m_timeacc;
  s.update_rest_constants = b.m_bUpdateRtCst;
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
  if (b.m_nodes.size() != s.nodes.size() || b.m_faces.size() != s.faces.size() ||
      b.m_links.size() != s.links.size() || b.m_tetras.size() != s.tetras.size()) {
    throw std::invalid_argument("a world state of another soft body");
  }
  // Same sizes: the arrays keep their storage, so the pointers between them stay valid.
  b.m_nodes = s.nodes;
  b.m_faces = s.faces;
  b.m_links = s.links;
  b.m_tetras = s.tetras;
  b.m_anchors = s.anchors;
  b.m_rcontacts = s.rigid_contacts;
  b.m_scontacts = s.soft_contacts;
  b.m_pose = s.pose;
  b.m_sst = s.solver;
  b.m_bounds[0] = s.bounds[0];
  b.m_bounds[1] = s.bounds[1];
  b.m_timeacc = s.time_accumulated;
  b.m_bUpdateRtCst = s.update_rest_constants;
  b.setWorldTransform(s.transform);
  b.forceActivationState(s.activation);
  b.setDeactivationTime(s.deactivation_time);
  rebuildTree(b.m_ndbvt, b.m_nodes, s.node_leaves);
  rebuildTree(b.m_fdbvt, b.m_faces, s.face_leaves);
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
  std::vector<SoftState> soft;
  std::vector<ManifoldState> manifolds;
  std::shared_ptr<const detail::CoulombContactSolver::State> soft_solver;
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

}  // namespace

std::shared_ptr<const WorldState> World::saveState() {
  Impl& w = *impl_;
  if (!w.articulations.empty()) {
    throw std::logic_error(
        "World::saveState: a world with articulations (reduced coordinates) is not captured; "
        "give its models 'articulation: maximal'");
  }
  auto state = std::make_shared<WorldState>();
  state->world = w.id;
  state->time = w.time;
  state->steps = w.steps;
  for (const auto& b : w.bodies) state->rigid.push_back(rigidStateOf(b->bullet()));
  for (const auto& j : w.joints) state->joints.push_back(j->joint->state());
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
  restoreState(*state);  // the canonical caches, for this run as for every restored one
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
  // The soft bodies' arrays before the narrowphase below, whose contacts they then replace.
  for (std::size_t i = 0; i < w.soft_bodies.size(); ++i) {
    restoreSoft(w.soft_bodies[i]->bullet(), state.soft[i]);
  }
  rebuildCollisionCaches(w.world);
  restoreManifolds(*w.world.getDispatcher(), state.manifolds);
  for (std::size_t i = 0; i < w.soft_bodies.size(); ++i) {
    btSoftBody& b = w.soft_bodies[i]->bullet();
    b.m_rcontacts = state.soft[i].rigid_contacts;
    b.m_scontacts = state.soft[i].soft_contacts;
  }
  w.bullet.softBodySolver().restore(*state.soft_solver);
  if (w.sleeper) w.sleeper->restore(state.sleep);
  for (std::size_t i = 0; i < w.sensors.size(); ++i) w.sensors[i]->restore(state.sensors[i]);
}

}  // namespace ambf_like
