#include "ambf_like/world.hpp"

#include <BulletCollision/CollisionShapes/btEmptyShape.h>
#include <BulletCollision/Gimpact/btGImpactCollisionAlgorithm.h>
#include <BulletSoftBody/btSoftBody.h>
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <atomic>
#include <deque>
#include <map>
#include <set>
#include <stdexcept>

#include "ambf_like/bullet_conversions.hpp"
#include "ambf_like/dynamics/bullet_world.hpp"
#include "ambf_like/dynamics/collision_filter.hpp"
#include "ambf_like/dynamics/constraint_joint.hpp"
#include "ambf_like/dynamics/soft_body_step_solver.hpp"
#include "articulation.hpp"
#include "collision_shape_factory.hpp"
#include "constraint_factory.hpp"
#include "soft_body_factory.hpp"
#include "soft_body_sleep.hpp"
#include "world_impl.hpp"

namespace ambf_like {

namespace {

/// Hash buckets of the soft-body sparse SDF. Bullet's default, 2383, is sized for its 0.25 m
/// voxels; at millimetre voxels the peg-transfer scene holds 58,000 cells after 3 s and a lookup
/// walked up to 11 of them (611 steps/s; with this table 1.05 and 1,187 steps/s). A prime near
/// 2^18.
constexpr int kSdfHashBuckets = 262139;

/// Finds an item by qualified name, or by plain name when that is unique.
template <typename Items>
std::optional<std::size_t> findByName(const Items& items, std::string_view name) {
  std::optional<std::size_t> found;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (items[i]->qualifiedName() == name) return i;
    if (items[i]->name() == name) {
      if (found) return std::nullopt;
      found = i;
    }
  }
  return found;
}

template <typename Items>
std::size_t requireByName(const Items& items, std::string_view name, const char* kind) {
  if (auto index = findByName(items, name)) return *index;
  std::size_t matches = 0;
  for (const auto& item : items) matches += item->name() == name ? 1 : 0;
  throw std::out_of_range(
      std::string(kind) + " '" + std::string(name) + "' " +
      (matches > 1 ? "is ambiguous: use its namespace-qualified name" : "does not exist"));
}

}  // namespace

std::vector<detail::ArticulationPlan> World::Impl::planEach(const SceneSpec& scene) const {
  std::vector<detail::ArticulationPlan> each(scene.models.size());
  switch (settings.articulation) {
    case Articulation::Maximal:
      return each;
    case Articulation::Reduced:
      std::transform(scene.models.begin(), scene.models.end(), each.begin(),
                     detail::planArticulations);
      return each;
    case Articulation::Automatic:
      return detail::planAutomatically(scene.models);
  }
  return each;
}

World::Impl::Impl(const SceneSpec& scene, const WorldOptions& opts)
    : settings(scene.world),
      options(opts),
      plans(planEach(scene)),
      articulated(std::any_of(plans.begin(), plans.end(),
                              [](const auto& plan) { return !plan.trees.empty(); })),
      bullet(articulated),
      world(bullet.dynamics()) {
  static std::atomic<std::uint64_t> worlds{0};
  id = ++worlds;
  btGImpactCollisionAlgorithm::registerAlgorithm(&bullet.dispatcher());
  world.getPairCache()->setOverlapFilterCallback(&filter);
  world.setGravity(toBt(settings.gravity));
  world.getSolverInfo().m_numIterations = settings.solver_iterations.value_or(10);
  auto& info = bullet.softBodyInfo();
  info.m_gravity = toBt(settings.gravity);
  info.air_density = 1.2;
  info.m_sparsesdf.Initialize(kSdfHashBuckets);
  info.m_sparsesdf.setDefaultVoxelsz(settings.sdf_voxel_size.value_or(0.01));
  info.m_sparsesdf.Reset();
}

World::Impl::~Impl() {
  // Removing a collision object searches every overlapping pair for it: with the pairs gone
  // first, taking a 20,000-body chain apart is linear instead of some 40 s.
  struct EveryPair : btOverlapCallback {
    bool processOverlap(btBroadphasePair&) override { return true; }
  } every_pair;
  world.getBroadphase()->getOverlappingPairCache()->processAllOverlappingPairs(
      &every_pair, world.getDispatcher());
  while (world.getNumConstraints() > 0) {
    world.removeConstraint(world.getConstraint(world.getNumConstraints() - 1));
  }
  articulations.clear();
  for (auto& s : soft_bodies) bullet.removeSoftBody(s->bullet());
  for (auto& o : soft_proxies) world.removeCollisionObject(o.get());
  for (auto& b : bodies) {
    // An articulation's link bodies are mirrors that never entered the world.
    if (b->bullet().getBroadphaseHandle()) world.removeRigidBody(&b->bullet());
  }
}

RigidBody& World::Impl::addBody(const BodySpec& spec, const ModelSpec& model, int model_index,
                                MeshLibrary& meshes, Transform& com_in_body) {
  const auto shape = detail::buildBodyShape(spec, meshes, shapes);
  com_in_body = shape.com_in_body;
  collision_vertices += shape.vertex_count;
  collision_primitives += shape.primitive_count;

  btRigidBody::btRigidBodyConstructionInfo info(
      spec.mass, nullptr, shape.shape ? shape.shape : &no_geometry, toBt(shape.local_inertia));
  info.m_friction = spec.surface.static_friction;
  info.m_rollingFriction = spec.surface.rolling_friction;
  info.m_restitution = spec.surface.restitution;
  info.m_linearDamping = spec.surface.linear_damping;
  info.m_angularDamping = spec.surface.angular_damping;
  auto rigid = std::make_unique<btRigidBody>(info);
  rigid->setCenterOfMassTransform(toBt(spec.location * shape.com_in_body));
  // Moving bodies never sleep (the arms hold still under servo control); static ones keep the
  // sleeping state Bullet gives them, so they are never tested against sleeping soft bodies.
  if (spec.mass > 0.0) rigid->setActivationState(DISABLE_DEACTIVATION);

  auto groups = spec.collision.groups;
  std::sort(groups.begin(), groups.end());
  auto& tag = tags.emplace_back();
  tag.name = model.name_space + spec.name;
  tag.model = model_index;
  tag.model_ignores_inter_collision = model.ignore_inter_collision;
  tag.groups = std::move(groups);
  rigid->setUserPointer(&tag);
  if (shape.soft_proxy != nullptr) {
    auto& proxy = soft_proxies.emplace_back(std::make_unique<btCollisionObject>());
    proxy->setCollisionShape(shape.soft_proxy);
    proxy->setWorldTransform(rigid->getWorldTransform());
    proxy->setFriction(rigid->getFriction());
    proxy->setRollingFriction(rigid->getRollingFriction());
    proxy->setRestitution(rigid->getRestitution());
    proxy->setUserPointer(&tag);
    // Asleep, as Bullet puts static rigid bodies: sleeping soft bodies are then not tested
    // against it (Bullet collides a pair only if one of them is awake).
    proxy->setActivationState(ISLAND_SLEEPING);
    tag.soft_proxy = proxy.get();
    world.addCollisionObject(proxy.get(), btBroadphaseProxy::StaticFilter,
                             btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter);
    detail::keepBroadphaseBalanced(world);
  }
  if (const auto gravity = spec.gravity ? spec.gravity : model.gravity) {
    rigid->setFlags(rigid->getFlags() | BT_DISABLE_WORLD_GRAVITY);
    rigid->setGravity(toBt(*gravity));
  }
  bodies.push_back(std::make_unique<RigidBody>(spec, tag.name, std::move(rigid), shape.com_in_body,
                                               shape.vertex_count));
  return *bodies.back();
}

void World::Impl::addJoint(const ModelSpec& model, const JointSpec& spec,
                           std::unique_ptr<detail::JointDynamics> dynamics) {
  auto named = std::make_unique<detail::NamedJoint>();
  named->qualified = model.name_space + spec.name;
  named->joint = std::make_unique<Joint>(spec, std::move(dynamics));
  joints.push_back(std::move(named));
}

std::unique_ptr<detail::JointDynamics> World::Impl::constraintJoint(
    const JointSpec& spec, const std::map<std::string, detail::PlacedBody>& by_name) {
  const auto& parent = by_name.at(spec.parent);
  const auto& child = by_name.at(spec.child);
  const auto frames =
      detail::computeJointFrames(spec, parent.com_in_body, parent.body->spec().scale,
                                 child.com_in_body, child.body->spec().scale);
  auto constraint =
      detail::makeConstraint(spec, parent.body->bullet(), child.body->bullet(), frames);
  world.addConstraint(constraint.get(), spec.ignore_inter_collision);
  return std::make_unique<detail::ConstraintJoint>(
      spec, std::move(constraint), parent.body->bullet(), child.body->bullet(), frames.in_parent);
}

void World::Impl::addJoints(const ModelSpec& model, const std::vector<detail::JointTree>& trees,
                            const std::map<std::string, detail::PlacedBody>& by_name) {
  std::vector<detail::Articulation*> articulation_of(model.joints.size(), nullptr);
  for (const auto& tree : trees) {
    auto& articulation = *articulations.emplace_back(std::make_unique<detail::Articulation>(
        model, tree, by_name, bullet.articulations(), options.step_size));
    for (const std::size_t j : tree.joints) articulation_of[j] = &articulation;
  }
  for (std::size_t j = 0; j < model.joints.size(); ++j) {
    const JointSpec& spec = model.joints[j];
    addJoint(
        model, spec,
        articulation_of[j] ? articulation_of[j]->jointDynamics(j) : constraintJoint(spec, by_name));
  }
}

void World::Impl::addModel(const ModelSpec& model, int model_index, MeshLibrary& meshes) {
  const auto& plan = plans[static_cast<std::size_t>(model_index)];
  for (const auto& why : plan.left_out) {
    warnings.push_back(model.file.string() +
                       ": articulation: reduced: left in maximal coordinates: " + why);
  }
  std::set<std::string> links;  // bodies that become articulation links
  for (const auto& tree : plan.trees) {
    for (const std::size_t j : tree.joints) links.insert(model.joints[j].child);
  }
  std::map<std::string, detail::PlacedBody> by_name;
  for (const auto& spec : model.bodies) {
    Transform com_in_body;
    auto& body = addBody(spec, model, model_index, meshes, com_in_body);
    by_name[spec.name] = {&body, com_in_body};
    // An articulation's links collide through their own colliders; their bodies are mirrors.
    if (!links.contains(spec.name)) {
      world.addRigidBody(&body.bullet());
      detail::keepBroadphaseBalanced(world);
    }
  }
  for (const auto& spec : model.soft_bodies) {
    const bool coulomb = spec.contact_friction == SoftContactFriction::Coulomb;
    SourceRef where = spec.where;
    where.key_path += "/mesh";
    const auto mesh = meshes.load(spec.mesh, where);
    auto soft = detail::makeSoftBody(spec, *mesh, bullet.softBodyInfo());
    auto& tag = tags.emplace_back();
    tag.name = model.name_space + spec.name;
    tag.model = model_index;
    tag.model_ignores_inter_collision = model.ignore_inter_collision;
    tag.soft = true;
    soft->setUserPointer(&tag);
    bullet.addSoftBody(*soft, coulomb ? std::optional<int>(spec.substeps) : std::nullopt,
                       spec.material);
    soft_bodies.push_back(std::make_unique<SoftBody>(spec, tag.name, std::move(soft)));
  }
  addJoints(model, plan.trees, by_name);
  // A parent of this model by its name, or of any model loaded before by its qualified name.
  auto parentOf = [&](const std::string& parent, const SourceRef& where) -> RigidBody& {
    if (auto it = by_name.find(parent); it != by_name.end()) return *it->second.body;
    try {
      return *bodies[requireByName(bodies, parent, "body")];
    } catch (const std::out_of_range& e) {
      SourceRef at = where;
      at.key_path += "/parent";
      throw LoadError(at, std::string(e.what()) +
                              " (a parent of another model must be loaded "
                              "before this one)");
    }
  };
  for (const auto& spec : model.sensors) {
    sensors.push_back(std::make_unique<ProximitySensor>(spec, model.name_space + spec.name,
                                                        parentOf(spec.parent, spec.where)));
  }
  for (const auto& spec : model.actuators) {
    RigidBody& parent = parentOf(spec.parent, spec.where);
    // An articulation link's btRigidBody is a mirror outside the Bullet world.
    const bool in_world = parent.bullet().getBroadphaseHandle() != nullptr;
    actuators.push_back(std::make_unique<ConstraintActuator>(spec, model.name_space + spec.name,
                                                             parent, in_world, world));
  }
}

World::World(const SceneSpec& scene, MeshLibrary& meshes, WorldOptions options)
    : impl_(std::make_unique<Impl>(scene, options)) {
  // Below a microsecond a step only burns time (and a loop's period holds millions of them);
  // above 0.1 s nothing this simulator holds stays stable.
  if (!(options.step_size >= 1e-6 && options.step_size <= 0.1)) {
    throw std::invalid_argument("the step size must be 1e-6 to 0.1 s (got " +
                                std::to_string(options.step_size) + ")");
  }
  for (std::size_t m = 0; m < scene.models.size(); ++m) {
    impl_->addModel(scene.models[m], static_cast<int>(m), meshes);
  }
  if (!impl_->articulations.empty()) {
    impl_->bullet.setFreeMotionListener([impl = impl_.get()] {
      for (auto& a : impl->articulations) a->afterFreeMotion();
    });
  }
  std::vector<Eigen::Vector3d> scene_points;
  for (const auto& body : impl_->bodies) {
    scene_points.push_back(body->centerOfMassPose().translation());
  }
  for (const auto& soft : impl_->soft_bodies) {
    for (const Vec3& node : soft->nodePositions()) scene_points.push_back(node);
  }
  impl_->guard.emplace(scene_points, options.step_size, impl_->settings.gravity);
  impl_->letFreeBodiesSleep();
  if (scene.world.soft_body_sleep.enabled && !impl_->soft_bodies.empty()) {
    impl_->sleeper.emplace(scene.world.soft_body_sleep, impl_->world, impl_->soft_bodies.size());
  }
}

World::~World() = default;

void World::Impl::letFreeBodiesSleep() {
  const RigidBodySleep& sleep = settings.rigid_body_sleep;
  if (!sleep.enabled) return;
  std::set<const btRigidBody*> jointed;
  for (int i = 0; i < world.getNumConstraints(); ++i) {
    jointed.insert(&world.getConstraint(i)->getRigidBodyA());
    jointed.insert(&world.getConstraint(i)->getRigidBodyB());
  }
  for (auto& body : bodies) {
    btRigidBody& rigid = body->bullet();
    // Articulations' link bodies mirror their links and never enter the world.
    if (rigid.isStaticOrKinematicObject() || !rigid.getBroadphaseHandle()) continue;
    if (jointed.count(&rigid) > 0) continue;
    rigid.forceActivationState(ACTIVE_TAG);
    rigid.setSleepingThresholds(sleep.linear_speed, sleep.angular_speed);
  }
}

void World::step(std::uint64_t count) {
  for (std::uint64_t i = 0; i < count; ++i) step();
}

double World::time() const {
  return impl_->time;
}
std::uint64_t World::stepCount() const {
  return impl_->steps;
}
double World::stepSize() const {
  return impl_->options.step_size;
}
const WorldSpec& World::settings() const {
  return impl_->settings;
}

std::size_t World::jointCount() const {
  return impl_->joints.size();
}
Joint& World::joint(std::size_t index) {
  return *impl_->joints.at(index)->joint;
}
const Joint& World::joint(std::size_t index) const {
  return *impl_->joints.at(index)->joint;
}
Joint& World::joint(std::string_view name) {
  return *impl_->joints[requireByName(impl_->joints, name, "joint")]->joint;
}
std::optional<std::size_t> World::findJoint(std::string_view name) const {
  return findByName(impl_->joints, name);
}

std::size_t World::bodyCount() const {
  return impl_->bodies.size();
}
RigidBody& World::body(std::size_t index) {
  return *impl_->bodies.at(index);
}
const RigidBody& World::body(std::size_t index) const {
  return *impl_->bodies.at(index);
}
RigidBody& World::body(std::string_view name) {
  return *impl_->bodies[requireByName(impl_->bodies, name, "body")];
}
const RigidBody& World::body(std::string_view name) const {
  return *impl_->bodies[requireByName(impl_->bodies, name, "body")];
}

std::size_t World::sensorCount() const {
  return impl_->sensors.size();
}
ProximitySensor& World::sensor(std::size_t index) {
  return *impl_->sensors.at(index);
}
ProximitySensor& World::sensor(std::string_view name) {
  return *impl_->sensors[requireByName(impl_->sensors, name, "sensor")];
}
std::size_t World::actuatorCount() const {
  return impl_->actuators.size();
}
ConstraintActuator& World::actuator(std::size_t index) {
  return *impl_->actuators.at(index);
}
ConstraintActuator& World::actuator(std::string_view name) {
  return *impl_->actuators[requireByName(impl_->actuators, name, "actuator")];
}

std::size_t World::softBodyCount() const {
  return impl_->soft_bodies.size();
}
SoftBody& World::softBody(std::size_t index) {
  return *impl_->soft_bodies.at(index);
}
const SoftBody& World::softBody(std::size_t index) const {
  return *impl_->soft_bodies.at(index);
}
SoftBody& World::softBody(std::string_view name) {
  return *impl_->soft_bodies[requireByName(impl_->soft_bodies, name, "soft body")];
}
const SoftBody& World::softBody(std::string_view name) const {
  return *impl_->soft_bodies[requireByName(impl_->soft_bodies, name, "soft body")];
}

namespace {

/// The qualified name a collision object's filter tag carries.
std::string collisionName(const btCollisionObject* object) {
  const auto* tag = static_cast<const detail::CollisionTag*>(object->getUserPointer());
  return tag ? tag->name : std::string("?");
}

/// True when `object` is `body` (an articulation link's collider carries its body's tag), or
/// when no body is asked for.
bool isBody(const btCollisionObject* object, const void* body_tag) {
  return body_tag == nullptr || object->getUserPointer() == body_tag;
}

}  // namespace

std::vector<Contact> World::Impl::contactsWith(const void* body_tag) const {
  std::vector<Contact> out;
  const btCollisionDispatcher& dispatcher = bullet.dispatcher();
  for (int i = 0; i < dispatcher.getNumManifolds(); ++i) {
    const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(i);
    if (!isBody(manifold->getBody0(), body_tag) && !isBody(manifold->getBody1(), body_tag)) {
      continue;
    }
    for (int k = 0; k < manifold->getNumContacts(); ++k) {
      const auto& point = manifold->getContactPoint(k);
      const btVector3 friction = point.m_lateralFrictionDir1 * point.m_appliedImpulseLateral1 +
                                 point.m_lateralFrictionDir2 * point.m_appliedImpulseLateral2;
      out.push_back({collisionName(manifold->getBody0()), collisionName(manifold->getBody1()),
                     toEigen(point.getPositionWorldOnB()), toEigen(point.m_normalWorldOnB),
                     point.getDistance(), point.getAppliedImpulse(), toEigen(friction)});
    }
  }
  for (const auto& soft : soft_bodies) {
    for (int i = 0; i < soft->bullet().m_rcontacts.size(); ++i) {
      const auto& contact = soft->bullet().m_rcontacts[i];
      if (!isBody(contact.m_cti.m_colObj, body_tag)) continue;
      const btVector3& node = contact.m_node->m_x;
      const double distance = contact.m_cti.m_normal.dot(node) + contact.m_cti.m_offset;
      if (distance > 0.0) continue;  // an elastic body's node in the band beyond its margin
      out.push_back({soft->qualifiedName(), collisionName(contact.m_cti.m_colObj), toEigen(node),
                     toEigen(contact.m_cti.m_normal), distance, 0.0, Vec3::Zero(), true});
    }
  }
  return out;
}

std::vector<SoftContactForce> World::Impl::softContactForcesOn(const void* body_tag) const {
  const double h = options.step_size;
  std::vector<SoftContactForce> out;
  for (const auto& impulse : bullet.coulombImpulses()) {
    if (!isBody(impulse.rigid, body_tag)) continue;
    out.push_back({collisionName(impulse.soft), collisionName(impulse.rigid),
                   toEigen(impulse.position), toEigen(impulse.normal),
                   toEigen(impulse.normal_impulse) / h, toEigen(impulse.friction_impulse) / h});
  }
  return out;
}

std::vector<Contact> World::contacts() const {
  return impl_->contactsWith(nullptr);
}

std::vector<Contact> World::contacts(std::string_view body) const {
  return impl_->contactsWith(this->body(body).bullet().getUserPointer());
}

std::vector<SoftContactForce> World::softContactForces() const {
  return impl_->softContactForcesOn(nullptr);
}

std::vector<SoftContactForce> World::softContactForces(std::string_view rigid_body) const {
  return impl_->softContactForcesOn(body(rigid_body).bullet().getUserPointer());
}

ElasticSolveStats World::elasticSolveStats(const SoftBody& body) const {
  return impl_->bullet.elasticStats(body.bullet());
}

const StepGuard& World::guard() const {
  return *impl_->guard;
}

bool World::isFinite() const {
  return std::all_of(impl_->bodies.begin(), impl_->bodies.end(),
                     [](const auto& b) { return b->isFinite(); }) &&
         std::all_of(impl_->soft_bodies.begin(), impl_->soft_bodies.end(),
                     [](const auto& s) { return s->isFinite(); });
}

const std::vector<std::string>& World::warnings() const {
  return impl_->warnings;
}

std::size_t World::articulationCount() const {
  return impl_->articulations.size();
}

std::size_t World::collisionVertexCount() const {
  return impl_->collision_vertices;
}

std::size_t World::collisionPrimitiveCount() const {
  return impl_->collision_primitives;
}

}  // namespace ambf_like
