#include "controller/sdl_gamepad.hpp"

#include <SDL2/SDL.h>
#include <spdlog/spdlog.h>

#include <stdexcept>

namespace controller {

namespace {

bool pressed(SDL_GameController* pad, SDL_GameControllerButton button) {
  return SDL_GameControllerGetButton(pad, button) != 0;
}

}  // namespace

double SdlGamepad::stick(std::int16_t raw) {
  return static_cast<double>(raw) / 32768.0;
}

double SdlGamepad::trigger(std::int16_t raw, TriggerScale scale) {
  const double travel = std::max(0.0, static_cast<double>(raw) / 32767.0);
  const double full_scale = scale == TriggerScale::XboxOne ? 1023.0 : 255.0;
  return travel * full_scale / 256.0;
}

/// The open controller.
struct SdlGamepad::Device {
  SDL_GameController* pad = nullptr;
  SDL_JoystickID id = -1;
};

SdlGamepad::SdlGamepad(TriggerScale scale, Polling polling)
    : scale_(scale), device_(std::make_unique<Device>()) {
  SDL_SetHint(SDL_HINT_JOYSTICK_ALLOW_BACKGROUND_EVENTS, "1");
  if (SDL_InitSubSystem(SDL_INIT_GAMECONTROLLER | SDL_INIT_EVENTS) != 0) {
    throw std::runtime_error(std::string("SDL game controllers unavailable: ") + SDL_GetError());
  }
  if (polling == Polling::OwnThread) {
    thread_ = std::thread([this] {
      while (!stop_) {
        poll();
        std::this_thread::sleep_for(kPollPeriod);
      }
    });
  }
}

SdlGamepad::~SdlGamepad() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
  if (device_->pad) SDL_GameControllerClose(device_->pad);
  SDL_QuitSubSystem(SDL_INIT_GAMECONTROLLER | SDL_INIT_EVENTS);
}

std::optional<recording::GamepadState> SdlGamepad::read() const {
  std::lock_guard lock(mutex_);
  return state_;
}

std::string SdlGamepad::name() const {
  std::lock_guard lock(mutex_);
  return name_;
}

void SdlGamepad::poll() {
  Device& d = *device_;
  SDL_GameControllerUpdate();
  SDL_Event event;
  while (SDL_PollEvent(&event)) {
    if (event.type == SDL_CONTROLLERDEVICEREMOVED && d.pad && event.cdevice.which == d.id) {
      SDL_GameControllerClose(d.pad);
      d.pad = nullptr;
      ++unplugs_;
      std::lock_guard lock(mutex_);
      spdlog::warn("gamepad '{}' unplugged", name_);
      state_.reset();
      name_.clear();
    }
  }
  for (int i = 0; !d.pad && i < SDL_NumJoysticks(); ++i) {  // the first pad SDL recognises
    if (!SDL_IsGameController(i) || !(d.pad = SDL_GameControllerOpen(i))) continue;
    d.id = SDL_JoystickInstanceID(SDL_GameControllerGetJoystick(d.pad));
    std::lock_guard lock(mutex_);
    name_ = SDL_GameControllerName(d.pad) ? SDL_GameControllerName(d.pad) : "gamepad";
    spdlog::info("gamepad '{}' connected", name_);
  }
  if (!d.pad) return;
  SDL_GameController* pad = d.pad;
  recording::GamepadState s;
  s.left_x = stick(SDL_GameControllerGetAxis(pad, SDL_CONTROLLER_AXIS_LEFTX));
  s.left_y = stick(SDL_GameControllerGetAxis(pad, SDL_CONTROLLER_AXIS_LEFTY));
  s.right_x = stick(SDL_GameControllerGetAxis(pad, SDL_CONTROLLER_AXIS_RIGHTX));
  s.right_y = stick(SDL_GameControllerGetAxis(pad, SDL_CONTROLLER_AXIS_RIGHTY));
  s.left_trigger = trigger(SDL_GameControllerGetAxis(pad, SDL_CONTROLLER_AXIS_TRIGGERLEFT), scale_);
  s.right_trigger =
      trigger(SDL_GameControllerGetAxis(pad, SDL_CONTROLLER_AXIS_TRIGGERRIGHT), scale_);
  s.left_bumper = pressed(pad, SDL_CONTROLLER_BUTTON_LEFTSHOULDER);
  s.right_bumper = pressed(pad, SDL_CONTROLLER_BUTTON_RIGHTSHOULDER);
  s.a = pressed(pad, SDL_CONTROLLER_BUTTON_A);
  s.b = pressed(pad, SDL_CONTROLLER_BUTTON_B);
  s.x = pressed(pad, SDL_CONTROLLER_BUTTON_X);
  s.y = pressed(pad, SDL_CONTROLLER_BUTTON_Y);
  s.back = pressed(pad, SDL_CONTROLLER_BUTTON_BACK);
  s.start = pressed(pad, SDL_CONTROLLER_BUTTON_START);
  if (rumble_requested_.exchange(false)) SDL_GameControllerRumble(pad, 0x8000, 0x8000, 150);
  std::lock_guard lock(mutex_);
  state_ = s;
}

}  // namespace controller
