#include "twin/ros/ambf_object_topics.hpp"

#include <ambf_msgs/ActuatorCmd.h>
#include <ambf_msgs/ActuatorState.h>
#include <ambf_msgs/RigidBodyState.h>
#include <ambf_msgs/SensorState.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <spdlog/spdlog.h>

#include <deque>
#include <vector>

#include "bridge/ros/ros_conversions.hpp"
#include "bridge/throttled_log.hpp"

namespace twin::ros1 {

namespace {

std_msgs::String text(const std::string& value) {
  std_msgs::String s;
  s.data = value;
  return s;
}

ambf_like::Vec3 offsetOf(const geometry_msgs::Pose& p) {
  return {p.position.x, p.position.y, p.position.z};
}

}  // namespace

class AmbfObjectTopics::Impl {
 public:
  Impl(ambf_like::World& world, bool simulated_stamps)
      : world_(world), simulated_stamps_(simulated_stamps) {
    node_.setCallbackQueue(&queue_);
    for (std::size_t i = 0; i < world.bodyCount(); ++i) {
      bodies_.push_back(
          node_.advertise<ambf_msgs::RigidBodyState>(world.body(i).qualifiedName() + "/State", 10));
    }
    for (std::size_t i = 0; i < world.softBodyCount(); ++i) {
      soft_bodies_.push_back(node_.advertise<ambf_msgs::RigidBodyState>(
          world.softBody(i).qualifiedName() + "/State", 10));
    }
    for (std::size_t i = 0; i < world.sensorCount(); ++i) {
      sensors_.push_back(
          node_.advertise<ambf_msgs::SensorState>(world.sensor(i).qualifiedName() + "/State", 10));
    }
    for (std::size_t i = 0; i < world.actuatorCount(); ++i) {
      const std::string name = world.actuator(i).qualifiedName();
      actuators_.push_back(node_.advertise<ambf_msgs::ActuatorState>(name + "/State", 10));
      commands_.push_back(node_.subscribe<ambf_msgs::ActuatorCmd>(
          name + "/Command", 100, [this, i](const ambf_msgs::ActuatorCmd::ConstPtr& command) {
            pending_.emplace_back(i, *command);
          }));
    }
  }

  void update(double sim_time) {
    queue_.callAvailable();
    while (!pending_.empty()) {
      apply(pending_.front().first, pending_.front().second);
      pending_.pop_front();
    }
    ++step_;
    for (std::size_t i = 0; i < bodies_.size(); ++i) publishBody(i, sim_time);
    for (std::size_t i = 0; i < soft_bodies_.size(); ++i) publishSoftBody(i, sim_time);
    for (std::size_t i = 0; i < sensors_.size(); ++i) publishSensor(i, sim_time);
    for (std::size_t i = 0; i < actuators_.size(); ++i) publishActuator(i, sim_time);
  }

  std::size_t bodyTopics() const { return bodies_.size() + soft_bodies_.size(); }
  std::size_t sensorTopics() const { return sensors_.size(); }
  std::size_t actuatorTopics() const { return actuators_.size(); }

 private:
  /// AMBF's rules: actuate attaches body_name (at body_offset if use_offset) or the body the
  /// named sensor senses nearest (use_sensor_data); actuate false releases.
  void apply(std::size_t index, const ambf_msgs::ActuatorCmd& command) {
    ambf_like::ConstraintActuator& actuator = world_.actuator(index);
    if (!command.actuate) {
      actuator.release();
      return;
    }
    if (actuator.actuated()) return;  // AMBF: already holding, the command is ignored
    try {
      std::string body = command.body_name.data;
      if (command.use_sensor_data) {
        const auto seen = world_.sensor(command.sensor_identifier.data).nearest();
        if (!seen) return;  // the sensor sees nothing: nothing to take
        body = seen->body;
      }
      const ambf_like::Vec3 offset =
          command.use_offset ? offsetOf(command.body_offset) : ambf_like::Vec3::Zero();
      actuator.actuate(world_.body(body), offset);
    } catch (const std::exception& e) {
      const std::string what = actuator.qualifiedName() + "/Command";
      log_.warn(what + " ignored", what + ": " + e.what() + "; ignored",
                ::ros::WallTime::now().toSec());
    }
  }

  template <typename Message>
  void stampCommon(Message& m, const std::string& type, const std::string& parent,
                   const std::string& name, const ambf_like::Transform& pose, double sim_time) {
    m.header.stamp = simulated_stamps_ ? ::ros::Time(sim_time) : ::ros::Time::now();
    m.sim_step = step_;
    m.type = text(type);
    m.parent_name = text(parent);
    m.identifier = text(name);
    m.name = text(name);
    m.wall_time = static_cast<float>(::ros::WallTime::now().toSec());
    m.sim_time = static_cast<float>(sim_time);
    m.pose = bridge::ros1::toPose(pose);
  }

  /// The fields AMBF's RigidBodyState shares with the other states (it has no type or parent).
  ambf_msgs::RigidBodyState bodyState(const std::string& name, const ambf_like::Transform& pose,
                                      double mass, double sim_time) {
    ambf_msgs::RigidBodyState m;
    m.header.stamp = simulated_stamps_ ? ::ros::Time(sim_time) : ::ros::Time::now();
    m.sim_step = step_;
    m.identifier = text(name);
    m.name = text(name);
    m.wall_time = static_cast<float>(::ros::WallTime::now().toSec());
    m.sim_time = static_cast<float>(sim_time);
    m.mass = static_cast<float>(mass);
    m.pose = bridge::ros1::toPose(pose);
    return m;
  }

  void publishBody(std::size_t index, double sim_time) {
    if (bodies_[index].getNumSubscribers() == 0) return;
    const ambf_like::RigidBody& body = world_.body(index);
    auto m = bodyState(body.name(), body.pose(), body.mass(), sim_time);
    const ambf_like::Vec3 v = body.linearVelocity(), w = body.angularVelocity();
    m.twist.linear.x = v.x();
    m.twist.linear.y = v.y();
    m.twist.linear.z = v.z();
    m.twist.angular.x = w.x();
    m.twist.angular.y = w.y();
    m.twist.angular.z = w.z();
    bodies_[index].publish(m);
  }

  /// A soft body as the frame a tracker would report (SoftBody::pose).
  void publishSoftBody(std::size_t index, double sim_time) {
    if (soft_bodies_[index].getNumSubscribers() == 0) return;
    const ambf_like::SoftBody& body = world_.softBody(index);
    soft_bodies_[index].publish(bodyState(body.name(), body.pose(), body.spec().mass, sim_time));
  }

  void publishSensor(std::size_t index, double sim_time) {
    if (sensors_[index].getNumSubscribers() == 0) return;
    const ambf_like::ProximitySensor& sensor = world_.sensor(index);
    const auto& spec = sensor.spec();
    ambf_msgs::SensorState m;
    stampCommon(m, spec.type == ambf_like::SensorType::Resistance ? "RESISTANCE" : "PROXIMITY",
                sensor.parent().name(), sensor.name(), spec.location, sim_time);
    const auto& readings = sensor.readings();
    m.count = static_cast<std::uint32_t>(readings.size());
    m.range.push_back(static_cast<float>(spec.range));
    for (const auto& r : readings) {
      m.triggered.push_back(r.triggered);
      // AMBF's depth fraction: how far into the range the hit is (1 at the ray's origin).
      m.measurement.push_back(r.triggered ? static_cast<float>(1.0 - r.distance / spec.range)
                                          : 0.0F);
      m.sensed_objects.push_back(text(r.triggered ? r.body : ""));
    }
    sensors_[index].publish(m);
  }

  void publishActuator(std::size_t index, double sim_time) {
    if (actuators_[index].getNumSubscribers() == 0) return;
    const ambf_like::ConstraintActuator& actuator = world_.actuator(index);
    ambf_msgs::ActuatorState m;
    stampCommon(m, "CONSTRAINT", actuator.spec().parent, actuator.name(), actuator.spec().location,
                sim_time);
    m.actuated = actuator.actuated();
    actuators_[index].publish(m);
  }

  ambf_like::World& world_;
  bool simulated_stamps_;
  ::ros::NodeHandle node_;
  ::ros::CallbackQueue queue_;
  std::vector<::ros::Publisher> bodies_, soft_bodies_, sensors_, actuators_;
  std::vector<::ros::Subscriber> commands_;
  std::deque<std::pair<std::size_t, ambf_msgs::ActuatorCmd>> pending_;
  std::uint32_t step_ = 0;
  bridge::ThrottledLog log_;
};

AmbfObjectTopics::AmbfObjectTopics(ambf_like::World& world, bool simulated_stamps)
    : impl_(std::make_unique<Impl>(world, simulated_stamps)) {}
AmbfObjectTopics::~AmbfObjectTopics() = default;

void AmbfObjectTopics::update(double sim_time) {
  impl_->update(sim_time);
}
std::size_t AmbfObjectTopics::bodyTopics() const {
  return impl_->bodyTopics();
}
std::size_t AmbfObjectTopics::sensorTopics() const {
  return impl_->sensorTopics();
}
std::size_t AmbfObjectTopics::actuatorTopics() const {
  return impl_->actuatorTopics();
}

}  // namespace twin::ros1
