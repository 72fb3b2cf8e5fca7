#pragma once
// The --actuation flag of every program that builds a twin: one spelling and one meaning
// everywhere (raven_sim's Twin(actuation=...) takes the same two words).

#include <CLI/CLI.hpp>
#include <string>

#include "common/actuation_kind.hpp"

namespace common {

/// Adds `--actuation motors|ideal`; `kind` holds the program's default, named in the help.
inline CLI::Option* addActuationFlag(CLI::App& app, ActuationKind& kind) {
  const std::string fallback(actuationWord(kind));
  return app
      .add_option_function<std::string>(
          "--actuation", [&kind](const std::string& word) { kind = actuationNamed(word); },
          "what drives the twin's joints: motors (the Raven-II's motor-level actuation, fitted "
          "by raven_calibrate) or ideal (ideal joint servos); default " +
              fallback)
      ->check(CLI::IsMember({"motors", "ideal"}))
      ->type_name("motors|ideal");
}

}  // namespace common
