#pragma once
// A live gamepad through SDL2's GameController API (any pad in SDL's mapping database), read on
// its own thread and normalised to the paper's scale.

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "recording/gamepad_state.hpp"

namespace controller {

/// How a trigger's travel maps onto the paper's trigger scale. The released controller divided
/// raw evdev values by 2^8: an Xbox One pad (10-bit triggers) reads 0 .. 3.996, which
/// grasp = 1 - trigger / 4 turns into the full grasp range; an 8-bit trigger reads only
/// 0 .. 0.996 and never closes the grasper past 0.75.
enum class TriggerScale {
  XboxOne,  ///< every pad's full travel reads 0 .. 1023/256 (what the mapping was made for)
  EightBit  ///< the released controller's result on an 8-bit trigger: 0 .. 255/256
};

/// Who polls SDL: a thread of the gamepad's own (the controller's gamepad thread), or the
/// caller through poll() (deterministic: tests, single-threaded tools).
enum class Polling { OwnThread, Caller };

/// The first game controller connected, polled every half millisecond (so at a 1 kHz command
/// rate an input is at most one poll plus one period old).
class SdlGamepad {
 public:
  static constexpr std::chrono::microseconds kPollPeriod{500};

  /// Starts SDL's game-controller subsystem (and the polling thread). Throws std::runtime_error
  /// if SDL cannot start.
  explicit SdlGamepad(TriggerScale scale = TriggerScale::XboxOne,
                      Polling polling = Polling::OwnThread);
  ~SdlGamepad();
  SdlGamepad(const SdlGamepad&) = delete;
  SdlGamepad& operator=(const SdlGamepad&) = delete;

  /// The latest reading; empty while no pad is connected.
  std::optional<recording::GamepadState> read() const;
  /// The connected pad's name ("" when none).
  std::string name() const;
  /// How many times a pad was unplugged so far.
  std::uint64_t unplugs() const { return unplugs_; }
  /// Asks the pad to rumble briefly (the controller does when IK clamps a target).
  void rumble() { rumble_requested_ = true; }
  /// One poll: connections, unplugs, the pad's state, a pending rumble. Polling::Caller only.
  void poll();

  /// Scales SDL's raw values: sticks -32768..32767 -> [-1, 1) (Y down when pushed forward, as
  /// evdev reports), triggers 0..32767 -> the paper's scale.
  static double stick(std::int16_t raw);
  static double trigger(std::int16_t raw, TriggerScale scale);

 private:
  TriggerScale scale_;
  struct Device;
  std::unique_ptr<Device> device_;  ///< touched by the polling thread only
  mutable std::mutex mutex_;
  std::optional<recording::GamepadState> state_;
  std::string name_;
  std::atomic<std::uint64_t> unplugs_{0};
  std::atomic<bool> rumble_requested_{false};
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace controller
