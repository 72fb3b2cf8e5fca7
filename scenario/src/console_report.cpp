#include "scenario/console_report.hpp"

#include <spdlog/fmt/fmt.h>
#include <unistd.h>

#include <algorithm>

#include "scenario/batch_summary.hpp"

namespace scenario {

namespace {

std::string yesNo(bool value) {
  return value ? "yes" : "no";
}

std::string millimetres(const Eigen::Vector2d& p) {
  return fmt::format("({:4.0f}, {:3.0f})", p.x() * 1e3, p.y() * 1e3);
}

}  // namespace

ProgressBar::ProgressBar(std::FILE* stream, std::string label)
    : stream_(stream), label_(std::move(label)), enabled_(isatty(fileno(stream)) != 0) {}

ProgressBar::~ProgressBar() {
  finish();
}

void ProgressBar::show(const RunProgress& progress) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (drawn_ && now - last_ < std::chrono::milliseconds(100) && progress.done < progress.total) {
    return;
  }
  last_ = now;
  constexpr int kWidth = 30;
  const double fraction =
      progress.total > 0 ? static_cast<double>(progress.done) / static_cast<double>(progress.total)
                         : 0.0;
  const int filled = static_cast<int>(fraction * kWidth);
  std::fprintf(stream_, "\r[%s%s] %zu/%zu %s, simulated %.1f s", std::string(filled, '#').c_str(),
               std::string(kWidth - filled, '.').c_str(), progress.done, progress.total,
               label_.c_str(), progress.sim_time);
  std::fflush(stream_);
  drawn_ = true;
}

void ProgressBar::finish() {
  if (drawn_) std::fputc('\n', stream_);
  drawn_ = false;
}

std::string ringTable(const PegTransferResult& result) {
  if (result.failed()) return fmt::format("the run failed: {}\n", result.failure);
  std::string out =
      fmt::format("{:<5} {:<5} {:<12} {:<12} {:<7} {:>9} {:>8} {:>11} {:<6} {:>9} {:>13}  {}\n",
                  "ring", "arm", "from (mm)", "to (mm)", "lifted", "lift (mm)", "regrasps",
                  "squeeze (N)", "placed", "miss (mm)", "volume ratio", "lost");
  for (const RingOutcome& p : result.rings) {
    out += fmt::format(
        "{:<5} {:<5} {:<12} {:<12} {:<7} {:>9.1f} {:>8} {:>11} {:<6} {:>9.1f} {:>13}  {}\n", p.ring,
        raven::armName(p.arm), millimetres(p.from), millimetres(p.to), yesNo(p.grasped),
        p.lift * 1e3, p.regrasps,
        fmt::format("{:.2f}/{:.2f}", p.carried_squeeze[0], p.carried_squeeze[1]), yesNo(p.placed),
        p.miss * 1e3,
        p.volume_seen ? fmt::format("{:.2f}-{:.2f}", p.min_volume_ratio, p.max_volume_ratio)
                      : "not seen",
        p.lost ? p.loss : "no");
  }
  out += fmt::format("placed {}/{}, lost {}, re-grasps {}{}\n", result.placed(),
                     result.rings.size(), result.lost(), result.regrasps(),
                     result.timed_out ? " (stopped at the time limit)" : "");
  return out;
}

std::string timingLine(const RunTiming& t) {
  return fmt::format(
      "simulated {:.1f} s in {:.1f} s of wall time: {:.2f}x real time; dynamic loop {:.0f} Hz "
      "({} physics steps of 1 ms)\n",
      t.sim_time, t.wall_time, t.realTimeFactor(), t.loopFrequency(), t.steps);
}

std::string batchTable(const std::vector<PegTransferResult>& results) {
  std::string out =
      fmt::format("{:>6} {:>7} {:>5} {:>8} {:>9} {:>8} {:>6} {:>8}\n", "seed", "placed", "lost",
                  "regrasps", "sim (s)", "wall (s)", "RTF", "loop Hz");
  for (const PegTransferResult& r : results) {
    if (r.failed()) {
      out += fmt::format("{:>6} failed: {}\n", r.variation.seed, r.failure);
      continue;
    }
    out += fmt::format("{:>6} {:>5}/6 {:>5} {:>8} {:>9.1f} {:>8.1f} {:>6.2f} {:>8.0f}\n",
                       r.variation.seed, r.placed(), r.lost(), r.regrasps(), r.timing.sim_time,
                       r.timing.wall_time, r.timing.realTimeFactor(), r.timing.loopFrequency());
  }
  const nlohmann::json total = summarize(results);
  out += fmt::format(
      "{} of {} runs placed all six rings ({} failed); {} of {} rings placed, {} lost, {} "
      "re-grasps; {:.2f}x real time and a {:.0f} Hz dynamic loop over all runs\n",
      total["runs_all_placed"].get<std::size_t>(), results.size(),
      total["runs_failed"].get<std::size_t>(), total["rings_placed"].get<std::size_t>(),
      total["rings"].get<std::size_t>(), total["rings_lost"].get<std::size_t>(),
      total["regrasps"].get<std::size_t>(), total["real_time_factor"].get<double>(),
      total["loop_frequency_hz"].get<double>());
  return out;
}

std::string rectangleSummary(const RectangleResult& result, const RectangleOptions& options) {
  std::string out = fmt::format("rectangle asked: {:.1f} x {:.1f} mm in XY under M2\n",
                                options.width * 1e3, options.depth * 1e3);
  for (raven::Arm arm : raven::kArms) {
    const Eigen::Vector3d e = result.extent(arm);
    out += fmt::format("{:<5} arm traced {:.1f} x {:.1f} mm, height varied {:.2f} mm\n",
                       raven::armName(arm), e.x() * 1e3, e.y() * 1e3, e.z() * 1e3);
  }
  out += fmt::format("{} readings, {} refused commands, {} clamped iterations{}\n",
                     result.iterations, result.refused, result.clamped,
                     result.timed_out ? " (stopped at the time limit)" : "");
  return out;
}

}  // namespace scenario
