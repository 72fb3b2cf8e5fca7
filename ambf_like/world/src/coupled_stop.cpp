#include "ambf_like/coupled_stop.hpp"

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>

#include <cmath>
#include <stdexcept>

#include "ambf_like/dynamics/coupled_limit_constraint.hpp"
#include "ambf_like/dynamics/limit_row.hpp"
#include "ambf_like/world.hpp"
#include "world_impl.hpp"

namespace ambf_like {

CoupledStop::CoupledStop(CoupledStopSpec spec,
                         std::unique_ptr<detail::CoupledLimitConstraint> constraint,
                         btMultiBodyDynamicsWorld& world, double step)
    : spec_(std::move(spec)), constraint_(std::move(constraint)), world_(world), step_(step) {}

CoupledStop::~CoupledStop() {
  if (engaged()) world_.removeMultiBodyConstraint(constraint_.get());
}

bool CoupledStop::engaged() const {
  for (int i = 0; i < world_.getNumMultiBodyConstraints(); ++i) {
    if (world_.getMultiBodyConstraint(i) == constraint_.get()) return true;
  }
  return false;
}

void CoupledStop::watch(double dt) {
  const bool near = constraint_->near(dt, detail::kLimitWatchBand);
  if (near == engaged()) return;
  if (near) {
    world_.addMultiBodyConstraint(constraint_.get());
  } else {
    world_.removeMultiBodyConstraint(constraint_.get());
  }
}

double CoupledStop::force() const {
  return engaged() ? constraint_->getAppliedImpulse(0) / step_ : 0.0;
}

double CoupledStop::gap() const {
  return constraint_->gap();
}

void CoupledStop::setLower(double lower) {
  if (!std::isfinite(lower)) throw std::invalid_argument("coupled stop: lower not finite");
  constraint_->shiftLower(lower - spec_.lower);
  spec_.lower = lower;
}

void CoupledStop::setCompliance(double compliance) {
  if (!std::isfinite(compliance) || compliance < 0.0) {
    throw std::invalid_argument("coupled stop: compliance " + std::to_string(compliance) +
                                " is not finite and >= 0");
  }
  constraint_->setCompliance(compliance);
}

namespace {

/// The multibody link whose joint is degree of freedom `dof` of `multibody`.
int linkOfDof(const btMultiBody& multibody, int dof) {
  for (int link = 0; link < multibody.getNumLinks(); ++link) {
    if (multibody.getLink(link).m_dofOffset == dof && multibody.getLink(link).m_dofCount == 1) {
      return link;
    }
  }
  throw std::logic_error("coupled stop: no link has degree of freedom " + std::to_string(dof));
}

}  // namespace

CoupledStop& World::addCoupledStop(const CoupledStopSpec& spec) {
  if (spec.joints.empty() || spec.gains.size() != spec.joints.size()) {
    throw std::invalid_argument("coupled stop: " + std::to_string(spec.joints.size()) +
                                " joints and " + std::to_string(spec.gains.size()) + " gains");
  }
  if (!std::isfinite(spec.lower)) throw std::invalid_argument("coupled stop: lower not finite");
  btMultiBody* multibody = nullptr;
  std::vector<detail::CoupledLimitConstraint::Term> terms;
  double lower = spec.lower;  // in Bullet's coordinates, which count from the load pose
  for (std::size_t i = 0; i < spec.joints.size(); ++i) {
    Joint& named = joint(spec.joints[i]);
    const auto at = named.dynamics().servoDof();
    if (at.multibody == nullptr || (multibody != nullptr && at.multibody != multibody)) {
      throw std::invalid_argument("coupled stop: joint '" + spec.joints[i] +
                                  "' is not a coordinate of the articulation the others are in");
    }
    if (!std::isfinite(spec.gains[i])) {
      throw std::invalid_argument("coupled stop: the gain of joint '" + spec.joints[i] +
                                  "' is not finite");
    }
    multibody = at.multibody;
    const int link = linkOfDof(*multibody, at.dof);
    lower -= spec.gains[i] * (named.dynamics().coordinate() - multibody->getJointPos(link));
    terms.push_back({link, spec.gains[i]});
  }
  auto constraint =
      std::make_unique<detail::CoupledLimitConstraint>(*multibody, std::move(terms), lower);
  return *impl_->coupled_stops.emplace_back(std::make_unique<CoupledStop>(
      spec, std::move(constraint), impl_->bullet.articulations(), stepSize()));
}

}  // namespace ambf_like
