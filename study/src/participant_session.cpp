#include "study/participant_session.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <istream>
#include <ostream>
#include <thread>

#include "harness/virtual_gamepad.hpp"
#include "study/settings_tuner.hpp"
#include "study/trial_metrics.hpp"
#include "study/trial_plan.hpp"
#include "study/trial_runner.hpp"

namespace study {

namespace fs = std::filesystem;

namespace {

Sint16 rawStick(double v) {
  return static_cast<Sint16>(std::clamp(std::lround(v * 32768.0), -32768L, 32767L));
}

/// Puts a pad reading on SDL's virtual joystick (what a thumb does to a real one).
void press(harness::VirtualGamepad& pad, const recording::GamepadState& s) {
  pad.axis(SDL_CONTROLLER_AXIS_LEFTX, rawStick(s.left_x));
  pad.axis(SDL_CONTROLLER_AXIS_LEFTY, rawStick(s.left_y));
  pad.axis(SDL_CONTROLLER_AXIS_RIGHTX, rawStick(s.right_x));
  pad.axis(SDL_CONTROLLER_AXIS_RIGHTY, rawStick(s.right_y));
  // The paper's scale back to the trigger's travel; SDL maps a virtual joystick's full axis
  // (-32768..32767) onto a game controller trigger's 0..32767.
  const auto trigger = [](double v) {
    const double travel = std::clamp(v * 256.0 / 1023.0, 0.0, 1.0);
    return static_cast<Sint16>(std::lround(travel * 65535.0 - 32768.0));
  };
  pad.axis(SDL_CONTROLLER_AXIS_TRIGGERLEFT, trigger(s.left_trigger));
  pad.axis(SDL_CONTROLLER_AXIS_TRIGGERRIGHT, trigger(s.right_trigger));
  pad.button(SDL_CONTROLLER_BUTTON_LEFTSHOULDER, s.left_bumper);
  pad.button(SDL_CONTROLLER_BUTTON_RIGHTSHOULDER, s.right_bumper);
  pad.button(SDL_CONTROLLER_BUTTON_A, s.a);
  pad.button(SDL_CONTROLLER_BUTTON_B, s.b);
  pad.button(SDL_CONTROLLER_BUTTON_X, s.x);
  pad.button(SDL_CONTROLLER_BUTTON_Y, s.y);
  pad.button(SDL_CONTROLLER_BUTTON_BACK, s.back);
  pad.button(SDL_CONTROLLER_BUTTON_START, s.start);
}

/// The next free place in the counterbalancing, or the one `participant` already has.
int registerParticipant(const fs::path& out, const std::string& participant,
                        std::optional<int> position) {
  const fs::path file = out / "participants.json";
  nlohmann::json registry = fs::exists(file) ? readJson(file) : nlohmann::json::object();
  if (registry.contains(participant)) return registry[participant].get<int>();
  const int place = position ? *position : static_cast<int>(registry.size());
  registry[participant] = place;
  writeJsonAtomically(file, registry);
  return place;
}

/// A person's wait: until A is pressed on the pad (or the session is stopped).
bool waitForA(const SessionSettings& s) {
  bool said = false;
  for (;;) {
    if (s.stop && *s.stop) return false;
    const auto pad = s.pad->read();
    if (pad && pad->a) return true;
    if (!pad && !said) {
      *s.out_text << "no gamepad is connected: plug one in (Ctrl-C stops the session)\n"
                  << std::flush;
      said = true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));  // a person's pace, not a test's
  }
}

/// A person's countdown on the terminal (wall clock).
bool countdown(const SessionSettings& s, double seconds, const char* what) {
  std::ostream& out = *s.out_text;
  for (int left = static_cast<int>(std::ceil(seconds)); left > 0; --left) {
    if (s.stop && *s.stop) return false;
    out << fmt::format("\r{} {} ", what, left) << std::flush;
    std::this_thread::sleep_for(std::chrono::seconds(1));
  }
  out << "\rgo!            \n" << std::flush;
  return true;
}

double costOf(const TuningSpec& tuning, const TrialMetrics& metrics) {
  double cost = 0.0;
  for (const auto& [name, weight] : tuning.cost) {
    const double v = metrics.at(name);
    if (std::isfinite(v)) cost += weight * v;
  }
  return cost;
}

std::vector<TuningObservation> tuningHistory(const fs::path& trials,
                                             const std::vector<PlannedTrial>& plan) {
  std::vector<TuningObservation> history;
  for (const PlannedTrial& t : plan) {
    const fs::path sealed = trials / t.folderName() / "trial.json";
    if (!t.tuning || !fs::exists(sealed)) continue;
    const nlohmann::json j = readJson(sealed);
    history.push_back({j.at("tuning").at("settings").get<std::vector<double>>(),
                       j.at("tuning").at("cost").get<double>()});
  }
  return history;
}

/// Moves trial folders without a trial.json (cut short) to aborted/.
void setAsideUnsealed(const fs::path& home) {
  for (const auto& entry : fs::directory_iterator(home / "trials")) {
    if (!entry.is_directory() || fs::exists(entry.path() / "trial.json")) continue;
    fs::create_directories(home / "aborted");
    fs::path target = home / "aborted" / entry.path().filename();
    for (int k = 1; fs::exists(target); ++k) {
      target = home / "aborted" / fmt::format("{}.{}", entry.path().filename().string(), k);
    }
    fs::rename(entry.path(), target);
    spdlog::warn("{}: cut short before; set aside as {} and run again", entry.path().string(),
                 target.string());
  }
}

bool lastOfBlock(const std::vector<PlannedTrial>& plan, std::size_t i) {
  return i + 1 == plan.size() || plan[i + 1].condition != plan[i].condition ||
         plan[i + 1].tuning != plan[i].tuning;
}

}  // namespace

void writeJsonAtomically(const fs::path& path, const nlohmann::json& j) {
  const fs::path temporary = fs::path(path).concat(".partial");
  {
    std::ofstream out(temporary, std::ios::trunc);
    out << j.dump(2) << '\n';
    out.flush();
    if (!out) throw std::runtime_error("cannot write " + temporary.string());
  }
  fs::rename(temporary, path);
}

nlohmann::json readJson(const fs::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path.string());
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw std::runtime_error(path.string() + ": " + e.what());
  }
}

nlohmann::json conditionJson(const Condition& c) {
  return {{"name", c.name},
          {"scheme", c.scheme},
          {"ik", c.full_ik ? "full" : "wrist-locked"},
          {"velocity_scale", c.velocity_scale},
          {"man_steps", c.man_steps},
          {"deadzone", c.deadzone},
          {"divisor", c.divisor},
          {"wrist_divisor", c.wrist_divisor},
          {"rate", c.rate},
          {"gain_m_per_s", c.translationGain()}};
}

namespace {

/// One participant's session as it runs: its folder, its plan (from session.json, written when
/// the session began) and who is at the pad.
class SessionRun {
 public:
  SessionRun(const Protocol& protocol, const SessionSettings& s)
      : protocol_(protocol), s_(s), home_(s.out / s.participant), trials_(home_ / "trials") {
    fs::create_directories(trials_);
    const nlohmann::json session = openPlan();
    for (const auto& t : session.at("plan")) plan_.push_back(PlannedTrial::fromJson(t));
    setAsideUnsealed(home_);
  }

  SessionProgress run() {
    for (std::size_t i = 0; i < plan_.size(); ++i) {
      if (!sealed(i) && (!rest(i) || !runTrial(i))) return progress(true);
      if (!askQuestionnaires(i)) return progress(true);
    }
    return progress(false);
  }

 private:
  bool person() const { return !s_.traits; }
  bool sealed(std::size_t i) const {
    return fs::exists(trials_ / plan_[i].folderName() / "trial.json");
  }

  /// The session's record: read back (refusing another protocol), or made now.
  nlohmann::json openPlan() const {
    const fs::path file = home_ / "session.json";
    if (fs::exists(file)) {
      nlohmann::json session = readJson(file);
      if (session.at("protocol_text").get<std::string>() != protocol_.text) {
        throw std::runtime_error(file.string() +
                                 ": this participant's session began under another protocol; "
                                 "use a new study folder");
      }
      return session;
    }
    const int position = registerParticipant(s_.out, s_.participant, s_.position);
    nlohmann::json plan = nlohmann::json::array();
    for (const PlannedTrial& t : planTrials(protocol_, position)) plan.push_back(t.json());
    const nlohmann::json session{
        {"study", protocol_.name},
        {"participant", s_.participant},
        {"position", position},
        {"order", conditionSequence(protocol_, position)},
        {"virtual", s_.traits ? s_.traits->json() : nlohmann::json(nullptr)},
        {"protocol_file", protocol_.file.string()},
        {"protocol_text", protocol_.text},
        {"plan", plan}};
    writeJsonAtomically(file, session);
    return session;
  }

  /// A person rests before a new scheme (not on resuming into one). False: stopped.
  bool rest(std::size_t i) const {
    if (!person() || !s_.rests || !s_.out_text || i == 0 ||
        plan_[i].condition == plan_[i - 1].condition || !sealed(i - 1)) {
      return true;
    }
    *s_.out_text << fmt::format("\nRest for {:.0f} s.\n", protocol_.rest);
    return countdown(s_, protocol_.rest, "rest");
  }

  /// Runs and seals trial `i`. False: stopped before its end (nothing sealed).
  bool runTrial(std::size_t i) {
    const PlannedTrial& planned = plan_[i];
    const TaskSpec& task = protocol_.task(planned.task);
    Condition condition = protocol_.condition(planned.condition);
    std::vector<double> tuned;
    if (planned.tuning) {
      const TuningSpec& tuning = *protocol_.tuning;
      tuned =
          SettingsTuner(tuning.parameters, tuning.initial).propose(tuningHistory(trials_, plan_));
      condition = tunedCondition(condition, tuning.parameters, tuned);
    }
    int trials_before = 0;
    for (std::size_t j = 0; j < i; ++j) {
      trials_before += plan_[j].condition == planned.condition && plan_[j].tuning == planned.tuning;
    }
    TrialSettings ts;
    ts.task = task;
    ts.condition = condition;
    ts.task_seed = planned.task_seed;
    ts.dir = trials_ / planned.folderName();
    ts.wall_clock = person();
    ts.pad = s_.pad;
    ts.stop = s_.stop;
    ts.video = s_.video;
    const std::string heading =
        fmt::format("{} trial {}/{}: {} under {}{}", s_.participant, i + 1, plan_.size(), task.name,
                    planned.condition, planned.tuning ? " (tuning)" : "");
    std::optional<VirtualParticipant> vp;
    if (s_.traits) {
      vp.emplace(*s_.traits, ConditionFeel::of(condition, trials_before),
                 s_.seed ^ (0x9e3779b97f4a7c15ull * (planned.index + 1)));
    }
    const bool drill = s_.drill_after >= 0 && finished_here_ == s_.drill_after;
    ts.before_turn = [&](double t, const raven::PerArm<ArmGoal>& goals,
                         const raven::PerArm<Eigen::Vector3d>& tips) {
      if (drill && t >= 1.0) std::raise(s_.drill_signal);
      if (!vp) return;
      press(*s_.virtual_pad, vp->act(t, goals, tips));
      s_.pad->poll();
    };
    std::ostream* out = s_.out_text;
    if (person() && out) {
      ts.ready = [&] {
        *out << fmt::format("\n{}\n{}\nPress A on the pad to start.\n", heading, task.instructions)
             << std::flush;
        return waitForA(s_) && countdown(s_, protocol_.countdown, "starting in");
      };
      ts.status = [&](const std::string& line) { *out << "\r" << line << "    " << std::flush; };
    }
    const TrialRun run = study::runTrial(ts);
    if (!run.finished) {
      if (out) *out << fmt::format("\n{}: stopped; run the same command to resume\n", heading);
      return false;
    }
    seal(planned, condition, tuned, trials_before, run, ts.dir);
    ++finished_here_;
    if (out) {
      *out << fmt::format("\n{}: {} in {:.1f} s\n", heading,
                          run.completed   ? "done"
                          : run.e_stopped ? "ended by an e-stop"
                          : run.diverged  ? "ended: the simulation diverged"
                                          : "time limit reached",
                          run.duration)
           << std::flush;
    }
    return true;
  }

  /// trial.json: the settings used and the metrics from the trial's files, written whole.
  void seal(const PlannedTrial& planned, const Condition& condition,
            const std::vector<double>& tuned, int trials_before, const TrialRun& run,
            const fs::path& dir) const {
    const TrialMetrics metrics = measureTrial(dir);
    nlohmann::json sealed{{"participant", s_.participant},
                          {"planned", planned.json()},
                          {"condition", conditionJson(condition)},
                          {"task", planned.task},
                          {"completed", run.completed},
                          {"duration_s", run.duration},
                          {"trials_before", trials_before}};
    for (const auto& [name, v] : metrics) {
      sealed["metrics"][name] = std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
    }
    if (const auto bar = protocol_.task(planned.task).proficiency_time) {
      sealed["proficiency_time_s"] = *bar;
    }
    if (planned.tuning) {
      sealed["tuning"] = {{"parameters", nlohmann::json::array()},
                          {"settings", tuned},
                          {"cost", costOf(*protocol_.tuning, metrics)},
                          {"cost_is", protocol_.tuning->costText()}};
      for (const TunedParameter& p : protocol_.tuning->parameters) {
        sealed["tuning"]["parameters"].push_back(
            {{"name", p.name}, {"low", p.low}, {"high", p.high}});
      }
    }
    writeJsonAtomically(dir / "trial.json", sealed);
  }

  /// After a scheme's last trial, its questionnaires not yet answered. False: the input ended.
  bool askQuestionnaires(std::size_t i) const {
    const PlannedTrial& planned = plan_[i];
    if (!lastOfBlock(plan_, i) || planned.tuning || !s_.questionnaires || !s_.desk ||
        !s_.out_text) {
      return true;
    }
    for (const QuestionnaireForm& form : protocol_.questionnaires) {
      const fs::path file =
          home_ / "questionnaires" / (planned.condition + "_" + form.name + ".json");
      if (fs::exists(file)) continue;
      const auto answers = s_.desk->ask(form, planned.condition);
      if (!answers) {
        *s_.out_text
            << "\nno more answers; the questionnaire is asked again when the session resumes\n";
        return false;
      }
      fs::create_directories(file.parent_path());
      nlohmann::json j = answers->json();
      j["condition"] = planned.condition;
      j["participant"] = s_.participant;
      writeJsonAtomically(file, j);
    }
    return true;
  }

  SessionProgress progress(bool stopped) const {
    SessionProgress p;
    p.total = static_cast<int>(plan_.size());
    for (std::size_t i = 0; i < plan_.size(); ++i) p.done += sealed(i) ? 1 : 0;
    p.stopped = stopped;
    p.finished = !stopped;
    return p;
  }

  const Protocol& protocol_;
  const SessionSettings& s_;
  fs::path home_, trials_;
  std::vector<PlannedTrial> plan_;
  int finished_here_ = 0;  ///< trials run and sealed by this run (the drill counts them)
};

}  // namespace

SessionProgress runSession(const Protocol& protocol, const SessionSettings& s) {
  return SessionRun(protocol, s).run();
}

}  // namespace study
