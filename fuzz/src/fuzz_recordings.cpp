// Fuzz target: the recording readers (rs and ci CSV files, chosen by the input's first byte).
// A RecordingError is the right answer to a bad file. A file read for commanding a robot must
// give finite times, strictly increasing, and finite joints in every row.

#include <cmath>
#include <cstdint>

#include "controller/recording_io.hpp"
#include "fuzz_file.hpp"

namespace {

void checkRs(const controller::RsRecording& rs) {
  for (std::size_t r = 0; r < rs.rows.size(); ++r) {
    const double t = rs.time(r);
    if (!std::isfinite(t)) fuzz::fail("an rs row with a non-finite time");
    if (r > 0 && !(t > rs.time(r - 1))) fuzz::fail("rs times that do not increase");
    for (raven::Arm arm : raven::kArms) {
      if (!rs.joints(r, arm).allFinite()) fuzz::fail("an rs row with non-finite joints");
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  try {
    if (data[0] % 2 == 0) {
      checkRs(controller::readRs(fuzz::asFile(data + 1, size - 1, "run_rs.csv")));
    } else {
      for (const auto& pad : controller::readCi(fuzz::asFile(data + 1, size - 1, "run_ci.csv"))) {
        (void)pad;
      }
    }
  } catch (const controller::RecordingError&) {
  }
  try {
    if (data[0] % 2 == 0) {
      controller::readRs(fuzz::asFile(data + 1, size - 1, "analysed_rs.csv"),
                         controller::NonFiniteJoints::Keep);
    }
  } catch (const controller::RecordingError&) {
  }
  return 0;
}
