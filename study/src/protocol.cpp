#include "study/protocol.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "common/yaml_view.hpp"
#include "study/trial_metrics.hpp"

namespace study {

namespace {

using common::YamlView;

/// Unknown and duplicated keys are both errors in a protocol: a typo must not run a study.
void checkKeys(const YamlView& node, std::initializer_list<std::string_view> known) {
  std::vector<common::LoadIssue> issues;
  node.checkKeys(known, {true, issues});
  if (!issues.empty()) throw common::LoadError(issues);
}

double positive(const YamlView& node) {
  const double v = node.asDouble();
  if (!(v > 0.0)) node.fail("must be positive");
  return v;
}

double within(const YamlView& node, double low, double high) {
  const double v = node.asDouble();
  if (v < low || v > high) node.fail(fmt::format("must lie in [{}, {}]", low, high));
  return v;
}

std::vector<Eigen::Vector3d> points(const YamlView& node) {
  std::vector<Eigen::Vector3d> out;
  for (const YamlView& p : node.elements()) {
    const auto xyz = p.asDoubleList(3);
    out.emplace_back(xyz[0], xyz[1], xyz[2]);
    if (out.back().norm() > 0.05) p.fail("a target more than 50 mm from the start point");
  }
  return out;
}

TaskSpec readTask(const std::string& name, const YamlView& node) {
  checkKeys(node, {"kind", "instructions", "time_limit", "trials", "proficiency_time",
                   "excessive_force", "pattern", "count", "distance", "height", "width", "depth",
                   "left", "right", "tolerance", "dwell"});
  TaskSpec t;
  t.name = name;
  const std::string kind = node["kind"].asKeyword();
  if (kind == "targets") {
    t.kind = TaskKind::Targets;
  } else if (kind == "peg_transfer") {
    t.kind = TaskKind::PegTransfer;
  } else {
    node["kind"].fail("unknown task kind '" + kind + "' (targets or peg_transfer)");
  }
  if (auto v = node.find("instructions")) t.instructions = v->asString();
  if (auto v = node.find("time_limit")) t.time_limit = positive(*v);
  if (auto v = node.find("trials")) {
    t.trials = v->asInt();
    if (*t.trials < 1 || *t.trials > 50) v->fail("must lie in [1, 50]");
  }
  if (auto v = node.find("proficiency_time")) {
    t.proficiency_time = positive(*v);
    if (*t.proficiency_time > t.time_limit) v->fail("must not exceed the task's time_limit");
  }
  if (auto v = node.find("excessive_force")) t.excessive_force = positive(*v);
  if (t.kind == TaskKind::PegTransfer) {
    for (const char* key : {"pattern", "count", "distance", "height", "width", "depth", "left",
                            "right", "tolerance", "dwell"}) {
      if (node.has(key)) node[key].fail("a peg_transfer task has no targets");
    }
    if (t.instructions.empty()) {
      t.instructions = "Move each ring from its start post to the post straight behind it.";
    }
    return t;
  }
  if (auto v = node.find("pattern")) t.pattern = v->asKeyword();
  if (t.pattern != "random" && t.pattern != "rectangle" && t.pattern != "list") {
    node["pattern"].fail("unknown pattern '" + t.pattern + "' (random, rectangle or list)");
  }
  if (auto v = node.find("count")) {
    t.count = v->asInt();
    if (t.count < 1 || t.count > 50) v->fail("must lie in [1, 50]");
  }
  if (auto v = node.find("distance")) t.distance = within(*v, 0.002, 0.04);
  if (auto v = node.find("height")) t.height = within(*v, 0.0, 0.02);
  if (auto v = node.find("width")) t.width = within(*v, 0.002, 0.04);
  if (auto v = node.find("depth")) t.depth = within(*v, 0.002, 0.04);
  if (auto v = node.find("left")) t.left = points(*v);
  if (auto v = node.find("right")) t.right = points(*v);
  if (t.pattern == "list" && t.left.empty() && t.right.empty()) {
    node.fail("a list pattern needs targets under left or right");
  }
  if (t.pattern != "list" && (node.has("left") || node.has("right"))) {
    node.fail("left / right targets belong to pattern: list");
  }
  if (auto v = node.find("tolerance")) t.tolerance = within(*v, 0.0005, 0.02);
  if (auto v = node.find("dwell")) t.dwell = within(*v, 0.0, 5.0);
  if (t.instructions.empty()) {
    t.instructions = "Bring each tool tip onto its target and hold it there until the next one.";
  }
  return t;
}

/// The numeric settings of a condition and the values each may take.
struct SettingRange {
  std::string_view name;
  double low, high;
};
constexpr std::array<SettingRange, 6> kSettings{{{"velocity_scale", 0.05, 2.0},
                                                 {"man_steps", 1.0, 100.0},
                                                 {"deadzone", 0.0, 0.9},
                                                 {"divisor", 200.0, 20000.0},
                                                 {"wrist_divisor", 2.0, 200.0},
                                                 {"rate", 100.0, 1000.0}}};

const SettingRange* settingNamed(std::string_view name) {
  for (const SettingRange& s : kSettings) {
    if (s.name == name) return &s;
  }
  return nullptr;
}

/// Sets the numeric setting `name` of `c` (its range already checked).
void setSetting(Condition& c, std::string_view name, double v) {
  if (name == "velocity_scale") c.velocity_scale = v;
  if (name == "man_steps") c.man_steps = static_cast<int>(std::lround(v));
  if (name == "deadzone") c.deadzone = v;
  if (name == "divisor") c.divisor = v;
  if (name == "wrist_divisor") c.wrist_divisor = v;
  if (name == "rate") c.rate = v;
}

Condition readCondition(const std::string& name, const YamlView& node) {
  checkKeys(node, {"scheme", "ik", "velocity_scale", "man_steps", "deadzone", "divisor",
                   "wrist_divisor", "rate"});
  Condition c;
  c.name = name;
  if (auto v = node.find("scheme")) {
    c.scheme = v->asKeyword();
    if (c.scheme != "m2" && c.scheme != "m1" && c.scheme != "m1-left" && c.scheme != "m1-right") {
      v->fail("unknown scheme '" + c.scheme + "' (m2, m1, m1-left or m1-right)");
    }
  }
  if (auto v = node.find("ik")) {
    const std::string ik = v->asKeyword();
    if (ik != "wrist-locked" && ik != "full") v->fail("ik is wrist-locked (C_W) or full");
    c.full_ik = ik == "full";
  }
  for (const SettingRange& s : kSettings) {
    if (auto v = node.find(s.name)) setSetting(c, s.name, within(*v, s.low, s.high));
  }
  return c;
}

TuningSpec readTuning(const YamlView& node, const Protocol& p) {
  checkKeys(node, {"condition", "task", "parameters", "cost", "trials", "initial"});
  TuningSpec t;
  t.condition = node["condition"].asString();
  if (std::none_of(p.conditions.begin(), p.conditions.end(),
                   [&](const Condition& c) { return c.name == t.condition; })) {
    node["condition"].fail("no condition named '" + t.condition + "'");
  }
  t.task = node["task"].asString();
  if (std::none_of(p.tasks.begin(), p.tasks.end(),
                   [&](const TaskSpec& s) { return s.name == t.task; })) {
    node["task"].fail("no task named '" + t.task + "'");
  }
  const YamlView params = node["parameters"];
  for (const std::string& key : params.keys()) {
    const YamlView bounds = params[key];
    const SettingRange* range = settingNamed(key);
    if (!range || key == "rate") {
      bounds.fail("cannot tune '" + key +
                  "' (velocity_scale, divisor, deadzone, wrist_divisor or man_steps)");
    }
    const auto lh = bounds.asDoubleList(2);
    if (!(lh[0] < lh[1]) || lh[0] < range->low || lh[1] > range->high) {
      bounds.fail(fmt::format("bounds are [low, high] with {} <= low < high <= {}", range->low,
                              range->high));
    }
    t.parameters.push_back({key, lh[0], lh[1]});
  }
  if (t.parameters.empty()) params.fail("name at least one parameter to tune");
  const YamlView cost = node["cost"];
  for (const std::string& key : cost.keys()) {
    if (std::find(metricNames().begin(), metricNames().end(), key) == metricNames().end()) {
      cost[key].fail("unknown metric '" + key + "'");
    }
    t.cost[key] = cost[key].asDouble();
  }
  if (t.cost.empty()) cost.fail("weigh at least one metric");
  if (auto v = node.find("trials")) {
    t.trials = v->asInt();
    if (t.trials < 2 || t.trials > 100) v->fail("must lie in [2, 100]");
  }
  if (auto v = node.find("initial")) {
    t.initial = v->asInt();
    if (t.initial < 1 || t.initial > t.trials) v->fail("must lie in [1, trials]");
  }
  return t;
}

/// A protocol's own Likert set: `{points: 2..11 (default 7), items: [statement, ...]}`.
QuestionnaireForm readLikert(const std::string& name, const YamlView& node) {
  checkKeys(node, {"points", "items"});
  int points = 7;
  if (auto v = node.find("points")) {
    points = v->asInt();
    if (points < 2 || points > 11) v->fail("must lie in [2, 11]");
  }
  std::vector<std::string> statements;
  for (const YamlView& item : node["items"].elements()) statements.push_back(item.asString());
  if (statements.empty()) node["items"].fail("list at least one statement");
  return likertForm(name, statements, points);
}

/// The questionnaires asked after each condition, in order: built-in names or the protocol's
/// Likert sets (`likert:`); `tlx_weights: true` adds the TLXs' pairwise comparisons.
std::vector<QuestionnaireForm> readQuestionnaires(const YamlView& list, const YamlView& root) {
  const bool weighted = root.find("tlx_weights") ? root["tlx_weights"].asBool() : false;
  std::map<std::string, QuestionnaireForm> own;
  if (auto likert = root.find("likert")) {
    for (const std::string& name : likert->keys()) {
      if (builtinForm(name, false)) (*likert)[name].fail("a built-in questionnaire's name");
      own.emplace(name, readLikert(name, (*likert)[name]));
    }
  }
  std::vector<QuestionnaireForm> forms;
  std::set<std::string> seen;
  for (const YamlView& q : list.elements()) {
    const std::string name = q.asKeyword();
    std::optional<QuestionnaireForm> form = builtinForm(name, weighted);
    if (!form && own.contains(name)) form = own.at(name);
    if (!form) q.fail("unknown questionnaire (nasa-tlx, surg-tlx, sus or a set under likert:)");
    if (!seen.insert(name).second) q.fail("listed twice");
    forms.push_back(*form);
  }
  return forms;
}

}  // namespace

controller::ControllerOptions Condition::controllerOptions() const {
  controller::ControllerOptions o;
  o.rate = rate;
  o.scheme = scheme == "m2"         ? controller::MappingScheme::M2
             : scheme == "m1-right" ? controller::MappingScheme::M1Right
                                    : controller::MappingScheme::M1Left;
  o.caps.per_second *= velocity_scale;
  o.caps.min_steps = man_steps;
  o.mapping.deadzone = deadzone;
  o.mapping.divisor = divisor;
  o.mapping.wrist_divisor = wrist_divisor;
  return o;
}

std::string TuningSpec::costText() const {
  std::string out;
  for (const auto& [metric, weight] : cost) {
    out += fmt::format("{}{:g} x {}", out.empty() ? "" : " + ", weight, metric);
  }
  return out;
}

const TaskSpec& Protocol::task(const std::string& named) const {
  for (const TaskSpec& t : tasks) {
    if (t.name == named) return t;
  }
  throw std::out_of_range(file.string() + ": no task named '" + named + "'");
}

const Condition& Protocol::condition(const std::string& named) const {
  for (const Condition& c : conditions) {
    if (c.name == named) return c;
  }
  throw std::out_of_range(file.string() + ": no condition named '" + named + "'");
}

Protocol loadProtocol(const std::filesystem::path& file) {
  const YamlView root = YamlView::parseFile(file);
  checkKeys(root, {"study", "tasks", "conditions", "trials_per_condition", "rest", "countdown",
                   "order", "questionnaires", "tlx_weights", "likert", "tuning"});
  Protocol p;
  p.file = file;
  {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    p.text = bytes.str();
  }
  p.name = root["study"].asString();
  const YamlView tasks = root["tasks"];
  for (const std::string& name : tasks.keys()) p.tasks.push_back(readTask(name, tasks[name]));
  if (p.tasks.empty()) tasks.fail("name at least one task");
  const YamlView conditions = root["conditions"];
  for (const std::string& name : conditions.keys()) {
    p.conditions.push_back(readCondition(name, conditions[name]));
  }
  if (p.conditions.empty()) conditions.fail("name at least one condition");
  if (auto v = root.find("trials_per_condition")) {
    p.trials_per_condition = v->asInt();
    if (p.trials_per_condition < 1 || p.trials_per_condition > 50) v->fail("must lie in [1, 50]");
  }
  if (auto v = root.find("rest")) p.rest = within(*v, 0.0, 3600.0);
  if (auto v = root.find("countdown")) p.countdown = within(*v, 0.0, 60.0);
  if (auto v = root.find("order")) {
    const std::string order = v->asKeyword();
    if (order == "latin-square") {
      p.order = OrderKind::LatinSquare;
    } else if (order == "fixed") {
      p.order = OrderKind::Fixed;
    } else {
      v->fail("order is latin-square or fixed");
    }
  }
  if (auto v = root.find("questionnaires")) p.questionnaires = readQuestionnaires(*v, root);
  if (auto v = root.find("tuning")) p.tuning = readTuning(*v, p);
  return p;
}

Condition tunedCondition(const Condition& base, const std::vector<TunedParameter>& parameters,
                         const std::vector<double>& values) {
  Condition c = base;
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    setSetting(c, parameters[i].name, values.at(i));
  }
  return c;
}

}  // namespace study
