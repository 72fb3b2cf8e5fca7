#pragma once
// What drives a twin's joints, and its one spelling ("motors", "ideal") in every program, file and
// binding.

#include <stdexcept>
#include <string>
#include <string_view>

namespace common {

/// What drives a twin's joints.
enum class ActuationKind {
  Motors,  ///< the Raven-II's motor-level actuation (motors, cables, its control software)
  Ideal,   ///< ideal joint servos
};

/// "motors" or "ideal": the word the flags, the JSON and raven_sim use.
constexpr std::string_view actuationWord(ActuationKind kind) {
  return kind == ActuationKind::Motors ? "motors" : "ideal";
}

/// The kind `word` names; throws std::invalid_argument naming the word when it names none.
inline ActuationKind actuationNamed(std::string_view word) {
  if (word == "motors") return ActuationKind::Motors;
  if (word == "ideal") return ActuationKind::Ideal;
  throw std::invalid_argument("actuation must be 'motors' or 'ideal', not '" + std::string(word) +
                              "'");
}

}  // namespace common
