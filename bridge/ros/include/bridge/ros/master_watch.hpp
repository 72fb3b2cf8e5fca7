#pragma once
// Keeps this process's topics registered across a rosmaster restart. A new master knows nothing
// of the publishers and subscribers registered with the old one, and roscpp does not register
// them again by itself, so without this no new peer could find them.

#include <condition_variable>
#include <mutex>
#include <thread>

namespace bridge::ros1 {

/// Asks the master for its process id every `period` wall seconds on a thread of its own (a
/// master that is down never holds up the caller's loop). When a master answers with another id
/// than the last one did, it registers every publication and subscription of this process with
/// it, as roscpp did at advertise and subscribe time; connections already open stay open.
/// One per process, after initRos().
class MasterWatch {
 public:
  explicit MasterWatch(double period = 0.5);
  ~MasterWatch();
  MasterWatch(const MasterWatch&) = delete;
  MasterWatch& operator=(const MasterWatch&) = delete;

 private:
  void watch(double period);

  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace bridge::ros1
