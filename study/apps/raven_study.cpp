// raven_study: human-factors studies of the mapping schemes on the twin. `run` takes one
// participant (or N virtual ones) through a protocol's trials, resumable; `report` compares the
// schemes across participants; `power` tells how many participants a study needs.

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <atomic>
#include <csignal>
#include <iostream>
#include <memory>

#include "common/number_checks.hpp"
#include "harness/virtual_gamepad.hpp"
#include "study/participant_session.hpp"
#include "study/questionnaire_server.hpp"
#include "study/study_report.hpp"

namespace {

namespace fs = std::filesystem;

/// Exit status of a session stopped before its end (resume it with the same command).
constexpr int kStopped = 130;

std::atomic<bool> stop_requested{false};
extern "C" void requestStop(int) {
  stop_requested = true;
}

/// `run`'s settings.
struct RunOptions {
  fs::path protocol, out;
  std::string participant;
  std::optional<int> position;
  int virtual_count = 0;
  bool autopilot = false;
  std::uint64_t seed = 1;
  std::string trigger_range = "xbox-one";
  int drill_after = -1;
  std::string drill_with = "int";
  bool video = false;
  int video_fps = 30;
  std::string video_size = "960x540";
  std::string questionnaires = "terminal";  ///< or "browser"
  std::string host = "127.0.0.1";
  int port = 8765;
};

/// Where the named participant answers the questionnaires, and where the session's words go.
struct Desk {
  std::unique_ptr<study::QuestionnaireDesk> desk;
  std::ostream* words = &std::cout;
};

Desk openDesk(const RunOptions& o) {
  Desk d;
  if (o.questionnaires == "terminal") {
    d.desk = std::make_unique<study::TerminalDesk>(std::cin, std::cout);
    return d;
  }
  auto server = std::make_unique<study::QuestionnaireServer>(o.host, o.port, &stop_requested);
  fmt::print("the participant's pages (instructions, questionnaires): {}\n", server->url());
  std::fflush(stdout);
  d.words = &server->board(std::cout);
  d.desk = std::move(server);
  return d;
}

int run(const RunOptions& o) {
  const study::Protocol protocol = study::loadProtocol(o.protocol);
  const bool simulated = o.virtual_count > 0 || o.autopilot;
  if (o.virtual_count == 0 && o.participant.empty()) {
    throw CLI::ValidationError("--participant", "name the participant (or --virtual N)");
  }
  const controller::TriggerScale scale = o.trigger_range == "8bit"
                                             ? controller::TriggerScale::EightBit
                                             : controller::TriggerScale::XboxOne;
  controller::SdlGamepad pad(
      scale, simulated ? controller::Polling::Caller : controller::Polling::OwnThread);
  std::unique_ptr<harness::VirtualGamepad> thumbs;
  if (simulated) {
    thumbs = std::make_unique<harness::VirtualGamepad>();
    if (!thumbs->ok()) throw std::runtime_error(std::string("SDL: ") + SDL_GetError());
    pad.poll();
  }
  std::vector<std::string> people;
  if (o.virtual_count > 0) {
    for (int k = 1; k <= o.virtual_count; ++k) people.push_back(fmt::format("V{:02d}", k));
  } else {
    people.push_back(o.participant);
  }
  const Desk desk = openDesk(o);
  bool all_done = true;
  for (std::size_t k = 0; k < people.size(); ++k) {
    study::SessionSettings s;
    s.out = o.out;
    s.participant = people[k];
    s.position = o.virtual_count > 0 ? std::optional<int>(static_cast<int>(k)) : o.position;
    s.pad = &pad;
    if (simulated) {
      // Each virtual person drawn from the population by the run's seed and their code.
      std::uint64_t h = o.seed * 0x9e3779b97f4a7c15ull;
      for (char c : people[k]) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
      s.traits = study::ParticipantTraits::draw(h);
      s.seed = h + 1;
      s.virtual_pad = thumbs.get();
    }
    s.questionnaires = o.virtual_count == 0;
    s.rests = !simulated;
    s.desk = desk.desk.get();
    s.out_text = desk.words;
    s.stop = &stop_requested;
    s.drill_after = o.drill_after;
    s.drill_signal = o.drill_with == "kill" ? SIGKILL : SIGINT;
    if (o.video) {
      s.video = viewer::VideoOptions::of({"trial.mp4", o.video_fps, o.video_size});
    }
    const study::SessionProgress p = study::runSession(protocol, s);
    fmt::print("{}: {} of {} trials sealed in {}\n", people[k], p.done, p.total,
               (o.out / people[k]).string());
    if (p.stopped) return kStopped;
    all_done = all_done && p.finished;
  }
  if (all_done) fmt::print("report: raven_study report {}\n", o.out.string());
  return 0;
}

/// A comparison's measure as the console names it: "task/metric", or a questionnaire's name.
std::string measureOf(const nlohmann::json& row) {
  const std::string metric = row.at("metric").get<std::string>();
  return row.at("task").is_null() ? metric : row.at("task").get<std::string>() + "/" + metric;
}

int report(const std::vector<fs::path>& dirs, const fs::path& out,
           const study::PowerQuestion& power) {
  const study::StudyData data = study::loadStudy(dirs);
  const std::string failure = study::writeReport(data, out, power);
  const nlohmann::json summary = study::readJson(out / "summary.json");
  fmt::print("{} participants, {} trials\n", data.participants.size(), data.trials.size());
  for (const auto& row : summary.at("comparisons")) {
    if (!row.at("significant").get<bool>()) continue;
    fmt::print("  {:<30} {} vs {}: p = {:.3g} ({}), d_z = {}, better: {}\n", measureOf(row),
               row.at("a").get<std::string>(), row.at("b").get<std::string>(),
               row.at("p").get<double>(), "holm", row.at("effect_size").dump(),
               row.at("better").dump());
  }
  fmt::print("{}\n", (out / "summary.json").string());
  if (!failure.empty()) {
    spdlog::error("{}", failure);
    return 1;
  }
  fmt::print("{}\n", (out / "report.html").string());
  return 0;
}

int power(const std::vector<fs::path>& dirs, const study::PowerQuestion& question) {
  const nlohmann::json summary = study::summarize(study::loadStudy(dirs), question);
  const nlohmann::json& p = summary.at("power");
  fmt::print("{}, alpha {}, power {}\n", p.at("test").get<std::string>(), question.alpha,
             question.power);
  for (const auto& row : p.at("stated_effects")) {
    fmt::print("  stated effect d_z {:.2f}: {} participants\n", row.at("effect_size").get<double>(),
               row.at("participants_needed").dump());
  }
  fmt::print("observed in the pilot (alpha divided by the scheme pairs):\n");
  for (const auto& row : p.at("observed")) {
    fmt::print("  {:<30} {} vs {}: d_z {} -> {} participants\n", measureOf(row),
               row.at("a").get<std::string>(), row.at("b").get<std::string>(),
               row.at("observed_effect").dump(), row.at("participants_needed").dump());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"raven_study: human-factors studies of the mapping schemes on the twin"};
  app.require_subcommand(1);

  RunOptions o;
  CLI::App* run_cmd = app.add_subcommand("run", "one participant's session (resumable)");
  run_cmd->add_option("--protocol", o.protocol, "the study's protocol (YAML)")
      ->required()
      ->check(CLI::ExistingFile);
  run_cmd->add_option("--out", o.out, "the study's folder")->required();
  run_cmd->add_option("--participant", o.participant, "the participant's code, e.g. P03");
  run_cmd->add_option("--position", o.position,
                      "place in the counterbalancing (default: arrival order)");
  run_cmd
      ->add_option("--virtual", o.virtual_count,
                   "run N virtual participants V01..VN instead of a person")
      ->check(common::finiteWithin(1, 999));
  run_cmd->add_flag("--autopilot", o.autopilot,
                    "a virtual participant drives the named participant's pad (rehearsal); the "
                    "questionnaires are still asked here");
  run_cmd->add_option("--seed", o.seed, "draws the virtual participants");
  run_cmd->add_option("--trigger-range", o.trigger_range, "xbox-one or 8bit")
      ->check(CLI::IsMember({"xbox-one", "8bit"}));
  run_cmd->add_option("--drill-after", o.drill_after,
                      "drill: interrupt the trial after this many finished trials");
  run_cmd->add_option("--drill-with", o.drill_with, "int (Ctrl-C) or kill (a crash)")
      ->check(CLI::IsMember({"int", "kill"}));
  run_cmd->add_flag("--video", o.video,
                    "a video of every trial (its folder's trial.mp4; headless, no display needed)");
  run_cmd->add_option("--video-fps", o.video_fps, "frames per simulated second (default 30)")
      ->check(common::finiteWithin(1, 240));
  run_cmd->add_option("--video-size", o.video_size, "WIDTHxHEIGHT, even (default 960x540)");
  run_cmd
      ->add_option("--questionnaires", o.questionnaires,
                   "where a person answers them: terminal, or browser (pages served on --host "
                   "and --port, with the session's instructions)")
      ->check(CLI::IsMember({"terminal", "browser"}));
  run_cmd->add_option("--host", o.host,
                      "the pages' address (default 127.0.0.1; 0.0.0.0 for a tablet on the LAN)");
  run_cmd->add_option("--port", o.port, "the pages' port (default 8765; 0: any free one)")
      ->check(common::finiteWithin(0, 65535));

  std::vector<fs::path> dirs;
  fs::path report_out;
  study::PowerQuestion question;
  CLI::App* report_cmd = app.add_subcommand("report", "compare the schemes across participants");
  report_cmd->add_option("dirs", dirs, "study folders (or participants' folders)")
      ->required()
      ->check(CLI::ExistingDirectory);
  report_cmd->add_option("--out", report_out, "where report.html and summary.json go")->required();
  CLI::App* power_cmd = app.add_subcommand("power", "participants needed, from a pilot");
  power_cmd->add_option("dirs", dirs, "the pilot's study folders")
      ->required()
      ->check(CLI::ExistingDirectory);
  for (CLI::App* cmd : {report_cmd, power_cmd}) {
    cmd->add_option("--alpha", question.alpha, "significance level")
        ->check(common::finiteWithin(0.0, 0.5));
    cmd->add_option("--power", question.power, "wanted power")
        ->check(common::finiteWithin(0.5, 0.999));
    cmd->add_option("--effect", question.effects, "stated effects (d_z)")->check(common::kFinite);
  }
  CLI11_PARSE(app, argc, argv);

  std::signal(SIGINT, requestStop);
  std::signal(SIGTERM, requestStop);
  try {
    if (*run_cmd) return run(o);
    if (*report_cmd) return report(dirs, report_out, question);
    return power(dirs, question);
  } catch (const CLI::Error& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return 1;
  }
}
