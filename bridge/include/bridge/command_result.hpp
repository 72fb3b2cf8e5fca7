#pragma once
// What a platform says to a command: taken (perhaps with a note) or refused, and why.

#include <string>

namespace bridge {

/// The answer to one command. A refused command changed nothing.
struct CommandResult {
  bool accepted = false;
  /// Why it was refused, or what was adjusted when it was taken (e.g. clamped to a limit).
  std::string note;

  static CommandResult ok(std::string note = {}) { return {true, std::move(note)}; }
  static CommandResult refused(std::string why) { return {false, std::move(why)}; }
  explicit operator bool() const { return accepted; }
};

}  // namespace bridge
