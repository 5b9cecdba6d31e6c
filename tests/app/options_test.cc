// Copyright contactlaws authors.
//
// The application's option grammar: a number given as a number reads as its
// text does, and every message names the option as its front-end spells it.

#include "app/options.h"

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace contactlaws::app {
namespace {

// The message of the Error fn throws, or "" when it throws none.
template <typename Fn>
std::string ErrorOf(Fn fn) {
  try {
    fn();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// A front-end's spelling unlike the key: "<max_timestep>", "<timestep auto>",
// "<settle!>".
std::string Bracketed(std::string_view key) { return "<" + std::string(key) + ">"; }
std::string BracketedGiven(std::string_view key, std::string_view word) {
  return "<" + std::string(key) + " " + std::string(word) + ">";
}
std::string BracketedSet(std::string_view key) { return "<" + std::string(key) + "!>"; }
std::string BracketedValued(std::string_view key, std::string_view number) {
  return "<" + std::string(key) + "=" + std::string(number) + ">";
}
std::string BracketedCommand(std::string_view name) { return "<" + std::string(name) + "()>"; }

const OptionReader kKeywords(kKeywordSpelling);
const OptionReader kBracketed(
    {&Bracketed, &BracketedGiven, &BracketedSet, &BracketedValued, &BracketedCommand});

TEST(OptionGrammarTest, ANumberReadsAsItsText) {
  EXPECT_EQ(kKeywords.Positive("timestep", 2.5e-4, "s"),
            kKeywords.Positive("timestep", std::string("2.5e-4"), "s"));
  EXPECT_EQ(kKeywords.Restitution("restitution", 0.3),
            kKeywords.Restitution("restitution", std::string("0.3")));
  EXPECT_EQ(kKeywords.ContactSteps(3.0), kKeywords.ContactSteps(std::string("3")));
  EXPECT_EQ(kKeywords.RestitutionList("restitution", 0.5), std::vector<double>{0.5});
  EXPECT_EQ(kKeywords.RestitutionList("restitution", std::vector<double>{0.3, 0.6}),
            kKeywords.RestitutionList("restitution", std::string("0.3,0.6")));
}

TEST(OptionGrammarTest, ANumberIsRefusedAsItsTextIs) {
  using Read = void (*)(const Value&);
  const Read positive = [](const Value& v) { kKeywords.Positive("timestep", v, "s"); };
  const Read restitution = [](const Value& v) { kKeywords.Restitution("restitution", v); };
  const Read contact_steps = [](const Value& v) { kKeywords.ContactSteps(v); };
  const Read list = [](const Value& v) { kKeywords.RestitutionList("restitution", v); };
  const Read dissipation = [](const Value& v) { kKeywords.Dissipation(v); };
  const struct {
    Read read;
    Value number;
    const char* text;  // the number's text
  } cases[] = {
      {positive, -1.0, "-1"},
      {restitution, 2.0, "2"},
      {contact_steps, 2.5, "2.5"},
      {contact_steps, 0.0, "0"},
      {list, 1.5, "1.5"},
      {list, std::vector<double>{0.5, 1.5}, "0.5,1.5"},
      {list, std::vector<double>{0.5, 0.5}, "0.5,0.5"},
      {dissipation, -0.5, "-0.5"},
  };
  for (const auto& c : cases) {
    const std::string message = ErrorOf([&] { c.read(c.number); });
    EXPECT_NE(message, "") << c.text;
    EXPECT_EQ(message, ErrorOf([&] { c.read(std::string(c.text)); }));
  }
  EXPECT_EQ(ErrorOf([] { kKeywords.Positive("timestep", -1.0, "s"); }),
            "timestep=-1 must be a number > 0 (s)");
  // a non-finite number is not a number of the grammar
  EXPECT_EQ(ErrorOf([] { kKeywords.Number("mu", std::nan("")); }), "mu=nan is not a finite number");
  EXPECT_EQ(ErrorOf([] { kKeywords.Positive("duration", HUGE_VAL, "s"); }),
            "duration=inf is not a finite number");
  // numbers where one is taken
  EXPECT_EQ(ErrorOf([] { kKeywords.Restitution("restitution", std::vector<double>{0.5, 0.6}); }),
            "restitution=0.5,0.6 must be one number, not a list");
}

TEST(OptionGrammarTest, MessagesSpellEveryOptionTheyName) {
  CommonInput input;
  input.timestep = 1e-4;
  input.accuracy = std::string("0.01");
  EXPECT_EQ(ErrorOf([&] { kBracketed.Common(input); }),
            "<accuracy>=0.01 goes with <timestep auto>, not with the fixed <timestep>=0.0001");
  input = CommonInput();
  input.max_timestep = 1e-3;
  EXPECT_EQ(ErrorOf([&] { kBracketed.Common(input); }),
            "<max_timestep>=0.001 goes with <timestep auto>");
  EXPECT_EQ(ErrorOf([] { kBracketed.LawList("laws", "hertz,hertz"); }),
            "<laws>=hertz,hertz names hertz twice");
  EXPECT_EQ(ErrorOf([] { kBracketed.UnderOption("params", [] { throw Error("x=1: bad"); }); }),
            "<params>: x=1: bad");
  // Python's
  EXPECT_EQ(ErrorOf([&] { kKeywords.Common(input); }),
            "max_timestep=0.001 goes with timestep=\"auto\"");
}

TEST(OptionGrammarTest, CommonOptionsTakeNumbers) {
  CommonInput input;
  input.duration = 0.5;
  input.timestep = std::string("auto");
  input.max_timestep = 1e-3;
  input.mu = 0.25;
  const CommonOptions options = kKeywords.Common(input);
  EXPECT_EQ(options.duration, 0.5);
  ASSERT_TRUE(options.auto_timestep);
  EXPECT_EQ(options.auto_timestep->max_step, 1e-3);
  EXPECT_EQ(options.simulation.overrides.mu, 0.25);
}

}  // namespace
}  // namespace contactlaws::app
