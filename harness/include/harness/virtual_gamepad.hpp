#pragma once
// An SDL virtual game controller (SDL_JoystickAttachVirtualEx): in place of a physical
// gamepad on machines without /dev/input. SDL's GameController API sees it as a real pad.

#include <SDL2/SDL.h>

#include <atomic>

namespace harness {

/// A virtual pad with every game-controller axis and button, counting rumble requests.
class VirtualGamepad {
 public:
  VirtualGamepad();
  ~VirtualGamepad();
  VirtualGamepad(const VirtualGamepad&) = delete;
  VirtualGamepad& operator=(const VirtualGamepad&) = delete;

  /// False if SDL refused to attach it (SDL_GetError() says why).
  bool ok() const { return joystick_ != nullptr; }
  void axis(SDL_GameControllerAxis a, Sint16 value);
  void button(SDL_GameControllerButton b, bool down);
  /// Detaches the pad, as pulling its cable does.
  void unplug();

  std::atomic<int> rumbles{0};

 private:
  int index_ = -1;
  SDL_Joystick* joystick_ = nullptr;
};

}  // namespace harness
