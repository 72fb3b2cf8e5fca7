#include "bridge/ros/master_watch.hpp"

#include <ros/master.h>
#include <ros/network.h>
#include <ros/this_node.h>
#include <ros/xmlrpc_manager.h>
#include <spdlog/spdlog.h>
#include <xmlrpcpp/XmlRpcClient.h>

#include <chrono>
#include <map>
#include <optional>
#include <set>
#include <string>

namespace bridge::ros1 {

namespace {

using XmlRpc::XmlRpcValue;

/// The master's process id, or nothing when no master answers.
std::optional<int> masterPid() {
  XmlRpcValue request, response, payload;
  request[0] = ::ros::this_node::getName();
  if (!::ros::master::execute("getPid", request, response, payload, /*wait_for_master=*/false) ||
      payload.getType() != XmlRpcValue::TypeInt) {
    return std::nullopt;
  }
  return static_cast<int>(payload);
}

/// A call to this process's own ROS slave API (the one the master and other nodes call): its
/// payload when it succeeded.
std::optional<XmlRpcValue> askThisNode(const char* method, XmlRpcValue request) {
  std::string host;
  std::uint32_t port = 0;
  if (!::ros::network::splitURI(::ros::XMLRPCManager::instance()->getServerURI(), host, port)) {
    return std::nullopt;
  }
  XmlRpc::XmlRpcClient client(host.c_str(), static_cast<int>(port), "/");
  XmlRpcValue response;
  if (!client.execute(method, request, response) || client.isFault() ||
      response.getType() != XmlRpcValue::TypeArray || response.size() != 3 ||
      static_cast<int>(response[0]) != 1) {
    return std::nullopt;
  }
  return response[2];
}

/// [[topic, type], ...] from getPublications or getSubscriptions.
std::map<std::string, std::string> topicsOfThisNode(const char* method) {
  XmlRpcValue request;
  request[0] = ::ros::this_node::getName();
  std::map<std::string, std::string> topics;
  const auto list = askThisNode(method, request);
  if (!list || list->getType() != XmlRpcValue::TypeArray) return topics;
  for (int i = 0; i < list->size(); ++i) {
    XmlRpcValue entry = (*list)[i];
    topics[static_cast<std::string>(entry[0])] = static_cast<std::string>(entry[1]);
  }
  return topics;
}

/// The publishers (their XML-RPC URIs) this process's subscription to `topic` is connected to,
/// from getBusInfo: a new master's list lacks those that never re-register, and telling roscpp
/// a list without them would drop their connections.
std::set<std::string> connectedPublishers(const XmlRpcValue& bus_info, const std::string& topic) {
  std::set<std::string> uris;
  for (int i = 0; i < bus_info.size(); ++i) {
    XmlRpcValue link = bus_info[i];
    if (link.size() >= 5 && static_cast<std::string>(link[2]) == "i" &&
        static_cast<std::string>(link[4]) == topic) {
      uris.insert(static_cast<std::string>(link[1]));
    }
  }
  return uris;
}

/// Registers `topic` of `type` as this node's with the master (`method`: registerPublisher or
/// registerSubscriber); the master's answer (for a subscriber, the topic's publishers) in
/// `payload`. False when the master did not take it.
bool registerWithMaster(const char* method, const std::string& topic, const std::string& type,
                        XmlRpcValue& payload) {
  XmlRpcValue request, response;
  request[0] = ::ros::this_node::getName();
  request[1] = topic;
  request[2] = type;
  request[3] = ::ros::XMLRPCManager::instance()->getServerURI();
  return ::ros::master::execute(method, request, response, payload, false);
}

/// Registers every publication and subscription of this process with the (new) master and
/// hands each subscription the publishers the master knows of. Returns how many topics.
int registerEverything() {
  int registered = 0;
  for (const auto& [topic, type] : topicsOfThisNode("getPublications")) {
    XmlRpcValue payload;
    if (registerWithMaster("registerPublisher", topic, type, payload)) ++registered;
  }
  XmlRpcValue no_request;
  no_request[0] = ::ros::this_node::getName();
  const XmlRpcValue bus_info = askThisNode("getBusInfo", no_request).value_or(XmlRpcValue());
  for (const auto& [topic, type] : topicsOfThisNode("getSubscriptions")) {
    XmlRpcValue payload;
    if (!registerWithMaster("registerSubscriber", topic, type, payload)) continue;
    ++registered;
    std::set<std::string> publishers = bus_info.getType() == XmlRpcValue::TypeArray
                                           ? connectedPublishers(bus_info, topic)
                                           : std::set<std::string>{};
    for (int i = 0; i < payload.size(); ++i)
      publishers.insert(static_cast<std::string>(payload[i]));
    XmlRpcValue update;
    update[0] = std::string("/master");
    update[1] = topic;
    update[2].setSize(static_cast<int>(publishers.size()));
    int k = 0;
    for (const auto& uri : publishers) update[2][k++] = uri;
    askThisNode("publisherUpdate", update);
  }
  return registered;
}

}  // namespace

MasterWatch::MasterWatch(double period) : thread_([this, period] { watch(period); }) {}

MasterWatch::~MasterWatch() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void MasterWatch::watch(double period) {
  std::optional<int> last = masterPid();
  std::unique_lock lock(mutex_);
  while (!wake_.wait_for(lock, std::chrono::duration<double>(period), [&] { return stopping_; })) {
    lock.unlock();
    const std::optional<int> pid = masterPid();
    if (pid && last && *pid != *last) {
      const int topics = registerEverything();
      spdlog::warn(
          "rosmaster {} restarted (pid {}, was {}): registered this node's {} topics again",
          ::ros::master::getURI(), *pid, *last, topics);
    }
    if (pid) last = pid;
    lock.lock();
  }
}

}  // namespace bridge::ros1
