// Fuzz target: the recording readers (rs and ci CSV files, chosen by the input's first byte).
// A RecordingError is the right answer to a bad file. A file read for commanding a robot must
// give finite times, strictly increasing, and finite joints within about +-1e3 in every row.

#include <cmath>
#include <cstdint>

#include "fuzz_file.hpp"
#include "recording/recording_io.hpp"

namespace {

void checkRs(const recording::RsRecording& rs) {
  for (std::size_t r = 0; r < rs.rows.size(); ++r) {
    const double t = rs.time(r);
    if (!std::isfinite(t)) fuzz::fail("an rs row with a non-finite time");
    if (r > 0 && !(t > rs.time(r - 1))) fuzz::fail("rs times that do not increase");
    for (raven::Arm arm : raven::kArms) {
      if (!rs.joints(r, arm).allFinite()) fuzz::fail("an rs row with non-finite joints");
      // The reader bounds each column by 1e3; a platform's convention shifts a joint by at most
      // a turn or two.
      if (rs.joints(r, arm).cwiseAbs().maxCoeff() > 1.1e3) fuzz::fail("an rs joint beyond 1e3");
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  try {
    if (data[0] % 2 == 0) {
      checkRs(recording::readRs(fuzz::asFile(data + 1, size - 1, "run_rs.csv")));
    } else {
      for (const auto& pad : recording::readCi(fuzz::asFile(data + 1, size - 1, "run_ci.csv"))) {
        (void)pad;
      }
    }
  } catch (const recording::RecordingError&) {
  }
  try {
    if (data[0] % 2 == 0) {
      recording::readRs(fuzz::asFile(data + 1, size - 1, "analysed_rs.csv"),
                        recording::NonFiniteJoints::Keep);
    }
  } catch (const recording::RecordingError&) {
  }
  return 0;
}
