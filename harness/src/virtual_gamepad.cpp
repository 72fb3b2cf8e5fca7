#include "harness/virtual_gamepad.hpp"

namespace harness {

VirtualGamepad::VirtualGamepad() {
  SDL_InitSubSystem(SDL_INIT_JOYSTICK);
  SDL_VirtualJoystickDesc desc{};
  desc.version = SDL_VIRTUAL_JOYSTICK_DESC_VERSION;
  desc.type = SDL_JOYSTICK_TYPE_GAMECONTROLLER;
  desc.naxes = SDL_CONTROLLER_AXIS_MAX;
  desc.nbuttons = SDL_CONTROLLER_BUTTON_MAX;
  desc.name = "virtual gamepad";
  desc.userdata = this;
  desc.Rumble = [](void* self, Uint16, Uint16) {
    ++static_cast<VirtualGamepad*>(self)->rumbles;
    return 0;
  };
  index_ = SDL_JoystickAttachVirtualEx(&desc);
  joystick_ = SDL_JoystickOpen(index_);
}

VirtualGamepad::~VirtualGamepad() {
  unplug();
  SDL_QuitSubSystem(SDL_INIT_JOYSTICK);
}

void VirtualGamepad::axis(SDL_GameControllerAxis a, Sint16 value) {
  SDL_JoystickSetVirtualAxis(joystick_, a, value);
}

void VirtualGamepad::button(SDL_GameControllerButton b, bool down) {
  SDL_JoystickSetVirtualButton(joystick_, b, down ? 1 : 0);
}

void VirtualGamepad::unplug() {
  if (!joystick_) return;
  SDL_JoystickClose(joystick_);
  SDL_JoystickDetachVirtual(index_);
  joystick_ = nullptr;
}

}  // namespace harness
