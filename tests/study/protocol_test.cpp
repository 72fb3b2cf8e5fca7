// The protocol reader: the shipped example loads as documented; bad protocols are refused naming
// the file, the line and the key.

#include "study/protocol.hpp"

#include <gtest/gtest.h>

#include "common/load_error.hpp"
#include "harness/temp_dir.hpp"

namespace {

const std::string kMinimal = R"(study: s
tasks:
  reach: {kind: targets}
conditions:
  A: {scheme: m2}
  B: {scheme: m1, deadzone: 0.3}
)";

std::string errorOf(const std::string& text) {
  harness::TempDir dir;
  try {
    study::loadProtocol(dir.write("p.yaml", text));
  } catch (const common::LoadError& e) {
    return e.what();
  }
  return "";
}

TEST(Protocol, TheExampleComparesThreeSchemesWithTuning) {
  const auto p = study::loadProtocol(RAVEN_STUDY_EXAMPLE);
  ASSERT_EQ(p.conditions.size(), 3u);
  EXPECT_EQ(p.condition("M2-degraded").deadzone, 0.6);
  EXPECT_EQ(p.condition("M2-degraded").controllerOptions().caps.min_steps, 40);
  EXPECT_EQ(p.task("rectangle").pattern, "rectangle");
  EXPECT_EQ(p.task("peg").kind, study::TaskKind::PegTransfer);
  EXPECT_EQ(p.task("peg").trials, 1);  // once per scheme; the others trials_per_condition times
  EXPECT_FALSE(p.task("reach").trials);
  EXPECT_EQ(p.order, study::OrderKind::LatinSquare);
  ASSERT_TRUE(p.tuning);
  EXPECT_EQ(p.tuning->costText(), "1 x completion_time_s + 2 x overshoots");
}

TEST(Protocol, AConditionBecomesTheControllersSettings) {
  study::Condition c;
  c.scheme = "m1-right";
  c.velocity_scale = 0.5;
  c.divisor = 1000;
  const auto o = c.controllerOptions();
  EXPECT_EQ(o.scheme, controller::MappingScheme::M1Right);
  EXPECT_NEAR(o.caps.per_second[raven::kInsertion], 0.01, 1e-12);
  EXPECT_EQ(o.mapping.divisor, 1000);
  EXPECT_NEAR(c.translationGain(), 500.0 / (1000.0 * 10.0), 1e-12);
}

TEST(Protocol, BadProtocolsAreRefusedNamingLineAndKey) {
  EXPECT_EQ(errorOf(kMinimal), "");
  const std::string typo = errorOf(kMinimal + "trials_per_conditon: 3\n");
  EXPECT_NE(typo.find("p.yaml:7"), std::string::npos) << typo;
  EXPECT_NE(typo.find("unknown key 'trials_per_conditon'"), std::string::npos) << typo;
  EXPECT_NE(errorOf(kMinimal + "trials_per_condition: 3\ntrials_per_condition: 4\n")
                .find("duplicate key"),
            std::string::npos);
  const std::string scheme = errorOf(R"(study: s
tasks: {reach: {kind: targets}}
conditions: {A: {scheme: m3}}
)");
  EXPECT_NE(scheme.find("conditions/A/scheme"), std::string::npos) << scheme;
  EXPECT_NE(scheme.find("unknown scheme 'm3'"), std::string::npos) << scheme;
  EXPECT_NE(errorOf(kMinimal + "order: random\n").find("latin-square or fixed"), std::string::npos);
  const std::string trials = errorOf(R"(study: s
tasks: {reach: {kind: targets, trials: 0}}
conditions: {A: {scheme: m2}}
)");
  EXPECT_NE(trials.find("tasks/reach/trials"), std::string::npos) << trials;
  EXPECT_NE(trials.find("must lie in [1, 50]"), std::string::npos) << trials;
  // A tuning block on the minimal protocol, one of its values wrong at a time.
  const auto tuning = [](const std::string& condition, const std::string& parameters,
                         const std::string& cost) {
    return errorOf(kMinimal + "tuning:\n  condition: " + condition + "\n  task: reach\n" +
                   "  parameters: {" + parameters + "}\n  cost: {" + cost + "}\n");
  };
  EXPECT_EQ(tuning("A", "divisor: [800, 4000]", "completion_time_s: 1"), "");
  const std::string bound = tuning("A", "velocity_scale: [0.5, 3.0]", "completion_time_s: 1");
  EXPECT_NE(bound.find("tuning/parameters/velocity_scale"), std::string::npos) << bound;
  EXPECT_NE(tuning("A", "divisor: [800, 4000]", "speed: 1").find("unknown metric 'speed'"),
            std::string::npos);
  EXPECT_NE(
      tuning("C", "divisor: [800, 4000]", "completion_time_s: 1").find("no condition named 'C'"),
      std::string::npos);
  EXPECT_NE(errorOf("study: [unclosed\n").find("p.yaml"), std::string::npos);
}

TEST(Protocol, QuestionnairesAreFormsInTheProtocolsOrder) {
  harness::TempDir dir;
  const auto p =
      study::loadProtocol(dir.write("p.yaml", kMinimal + R"(questionnaires: [sus, comfort, surg-tlx]
tlx_weights: true
likert:
  comfort: {points: 5, items: [The pad felt natural, I could see the tool]}
)"));
  ASSERT_EQ(p.questionnaires.size(), 3u);
  EXPECT_EQ(p.questionnaires[0].name, "sus");
  EXPECT_EQ(p.questionnaires[1].items.size(), 2u);
  EXPECT_EQ(p.questionnaires[1].scale.high, 5);
  EXPECT_TRUE(p.questionnaires[2].pairwise_weights);
  const std::string unknown = errorOf(kMinimal + "questionnaires: [nasa-tlx, tlx]\n");
  EXPECT_NE(unknown.find("p.yaml:7"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("unknown questionnaire"), std::string::npos) << unknown;
  const std::string taken =
      errorOf(kMinimal + "questionnaires: [sus]\nlikert:\n  sus: {items: [a]}\n");
  EXPECT_NE(taken.find("likert/sus"), std::string::npos) << taken;
  EXPECT_NE(errorOf(kMinimal + "questionnaires: [own]\nlikert:\n  own: {points: 1, items: [a]}\n")
                .find("must lie in [2, 11]"),
            std::string::npos);
}

}  // namespace
