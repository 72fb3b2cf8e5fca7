#include "ros_peers.hpp"

#include "bridge/ros/low_latency.hpp"

namespace ros_test {

TwinNode::TwinNode(const std::string& ns, const std::vector<std::string>& args) : ns_(ns) {
  std::vector<std::string> argv{RAVEN_TWIN_NODE, "__ns:=" + ns, "__name:=twin"};
  argv.insert(argv.end(), args.begin(), args.end());
  process_ = std::make_unique<harness::ChildProcess>(argv, dir_.path() / "node.log");
}

std::string TwinNode::stopAndReadLog() {
  process_->stop();
  return test_support::readFile(dir_.path() / "node.log");
}

sensor_msgs::JointState jointCommand(std::vector<double> position) {
  sensor_msgs::JointState m;
  m.position = std::move(position);
  return m;
}

std::string freshNamespace() {
  static int count = 0;
  return "/t" + std::to_string(++count);
}

RawPeer::RawPeer(const std::string& ns) : node_(ns) {
  node_.setCallbackQueue(&queue_);
  step_ = node_.advertise<raven_twin::Step>(std::string(bridge::ros1::kStepTopic), 10);
  subscribers_.push_back(node_.subscribe<raven_twin::StepDone>(
      std::string(bridge::ros1::kStepDoneTopic), 100,
      [this](const raven_twin::StepDone::ConstPtr& m) {
        done_ = m->seq;
        step_refused_ = m->refused;
      },
      {}, bridge::ros1::lowLatency()));
  subscribers_.push_back(node_.subscribe<std_msgs::String>(
      std::string(bridge::ros1::kRefusalTopic), 100,
      [this](const std_msgs::String::ConstPtr& m) { refusals_.push_back(m->data); }, {},
      bridge::ros1::lowLatency()));
  waitFor(
      [&] {
        return step_.getNumSubscribers() > 0 && subscribers_[0].getNumPublishers() > 0 &&
               subscribers_[1].getNumPublishers() > 0;
      },
      "twin node in lock-step");
}

std::vector<std::string> RawPeer::step(std::uint32_t cycles, std::size_t refusals) {
  refusals_.clear();
  raven_twin::Step step;
  step.seq = ++seq_;
  step.cycles = cycles;
  step.command_order = order_;
  order_.clear();
  step_.publish(step);
  waitFor([&] { return done_ == step.seq; }, "answer to the step");
  waitFor([&] { return refusals_.size() >= refusals; }, "refusal report");
  return refusals_;
}

}  // namespace ros_test
