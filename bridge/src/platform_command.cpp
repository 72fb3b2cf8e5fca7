#include "bridge/platform_command.hpp"

#include "bridge/overloaded.hpp"

namespace bridge {

namespace {

std::string onArm(const char* what, Arm arm) {
  return std::string(what) + " " + std::string(raven::armName(arm));
}

}  // namespace

std::string describe(const PlatformCommand& command) {
  return std::visit(Overloaded{
                        [](StateCommand c) { return "state_command " + std::string(wireName(c)); },
                        [](const ServoJp& c) { return onArm("servo_jp", c.arm); },
                        [](const ServoJr& c) { return onArm("servo_jr", c.arm); },
                        [](const MoveJp& c) { return onArm("move_jp", c.arm); },
                        [](const ServoCp& c) { return onArm("servo_cp", c.arm); },
                        [](const ServoCr& c) { return onArm("servo_cr", c.arm); },
                        [](const ServoJawJp& c) { return onArm("jaw servo_jp", c.arm); },
                        [](const ServoJawJr& c) { return onArm("jaw servo_jr", c.arm); },
                    },
                    command);
}

}  // namespace bridge
