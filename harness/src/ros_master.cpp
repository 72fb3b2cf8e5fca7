#include "harness/ros_master.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <thread>

namespace harness {

namespace {

using Clock = std::chrono::steady_clock;

bool acceptsConnections(int port) {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  const bool ok = connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address)) == 0;
  close(fd);
  return ok;
}

}  // namespace

RosMaster::RosMaster() : port_(freePort()) {
  uri_ = "http://127.0.0.1:" + std::to_string(port_);
  setenv("ROS_MASTER_URI", uri_.c_str(), 1);
  setenv("ROS_HOME", dir_.path().c_str(), 1);
  setenv("ROS_LOG_DIR", (dir_.path() / "log").c_str(), 1);
  setenv("ROS_IP", "127.0.0.1", 1);
  start();
}

RosMaster::~RosMaster() {
  process_->stop();
}

void RosMaster::restart() {
  process_->kill();
  start();
}

void RosMaster::start() {
  // Debian's ROS Python modules are only visible to /usr/bin/python3.
  process_ = std::make_unique<ChildProcess>(
      std::vector<std::string>{"/usr/bin/python3", "/usr/bin/rosmaster", "--core", "-p",
                               std::to_string(port_)},
      dir_.path() / "rosmaster.log");
  const auto deadline = Clock::now() + std::chrono::seconds(30);
  while (!acceptsConnections(port_)) {
    if (Clock::now() > deadline) {
      throw std::runtime_error("rosmaster did not come up on port " + std::to_string(port_) +
                               "; see " + (dir_.path() / "rosmaster.log").string());
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
}

}  // namespace harness
