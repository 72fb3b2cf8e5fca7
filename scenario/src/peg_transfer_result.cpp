#include "scenario/peg_transfer_result.hpp"

#include <algorithm>

namespace scenario {

std::string_view assistName(AssistMode mode) {
  return mode == AssistMode::Contact ? "contact" : "off";
}

std::size_t PegTransferResult::placed() const {
  return static_cast<std::size_t>(
      std::count_if(rings.begin(), rings.end(), [](const RingOutcome& p) { return p.placed; }));
}

std::size_t PegTransferResult::lost() const {
  return static_cast<std::size_t>(
      std::count_if(rings.begin(), rings.end(), [](const RingOutcome& p) { return p.lost; }));
}

std::size_t PegTransferResult::regrasps() const {
  std::size_t count = 0;
  for (const RingOutcome& p : rings) count += static_cast<std::size_t>(p.regrasps);
  return count;
}

nlohmann::json PegTransferResult::json() const {
  nlohmann::json rings_json = nlohmann::json::array();
  for (const RingOutcome& p : rings) {
    if (failed()) break;
    rings_json.push_back(
        {{"ring", p.ring},
         {"arm", raven::armName(p.arm)},
         {"from_m", {p.from.x(), p.from.y()}},
         {"to_m", {p.to.x(), p.to.y()}},
         {"grasped", p.grasped},
         {"lift_m", p.lift},
         {"regrasps", p.regrasps},
         {"carried_squeeze_n", p.carried_squeeze},
         {"placed", p.placed},
         {"lost", p.lost},
         {"loss", p.loss},
         {"volume_ratio_min", p.volume_seen ? nlohmann::json(p.min_volume_ratio) : nullptr},
         {"volume_ratio_max", p.volume_seen ? nlohmann::json(p.max_volume_ratio) : nullptr},
         {"final_centre_m", {p.final_centre.x(), p.final_centre.y(), p.final_centre.z()}},
         {"miss_m", p.miss}});
  }
  nlohmann::json j{{"task", "peg_transfer"},
                   {"seed", variation.seed},
                   {"scene", variation.json()},
                   {"grasp_assist", assistName(assist)},
                   {"actuation", common::actuationWord(actuation)},
                   {"placed", placed()},
                   {"lost", lost()},
                   {"regrasps", regrasps()},
                   {"stopped", stopped},
                   {"all_placed", allPlaced()},
                   {"timed_out", timed_out},
                   {"failure", failed() ? nlohmann::json(failure) : nlohmann::json(nullptr)},
                   {"iterations", iterations},
                   {"assisted_grasps", grasps},
                   {"refused_commands", refused},
                   {"rs_file", rs_file.string()},
                   {"rs_rows", rs_rows},
                   {"rings", rings_json}};
  timing.addTo(j);
  return j;
}

}  // namespace scenario
