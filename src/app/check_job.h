// Copyright contactlaws authors.
//
// check: a scene's tags resolved, their estimated contacts and the timestep
// they need, as a report (text) naming the options by the front-end's
// spelling (app/options.h).

#ifndef CONTACTLAWS_APP_CHECK_JOB_H_
#define CONTACTLAWS_APP_CHECK_JOB_H_

#include <optional>
#include <string>
#include <vector>

#include "app/options.h"
#include "contactlaws/contactlaws.h"

namespace contactlaws::app {

// check's options as given.
struct CheckInput {
  std::optional<std::string> law;
  std::optional<Value> restitution;
  std::optional<Value> dissipation;      // s/m
  std::optional<std::string> friction;
  std::optional<Value> mu;
  std::optional<Value> timestep;         // s, or "auto"
  std::optional<Value> accuracy;         // auto's relative error; implies auto
  std::optional<Value> impact_velocity;  // m/s, in place of the estimate
};

// check's options read and validated.
struct CheckRequest {
  SimulationOptions options;  // the overrides, a fixed timestep
  // the auto timestep's accuracy (timestep "auto" or accuracy given): the
  // contacts' steps are then its own
  std::optional<double> accuracy;
  std::optional<double> impact_velocity;  // m/s
};

// Refuses what the reader refuses, in the order the options are listed.
CheckRequest ReadCheck(const OptionReader& reader, const CheckInput& input);

struct CheckReport {
  std::string text;  // the report: settings, each tag, the driven bodies
  int coarse = 0;    // tags whose contact the timestep resolves too coarsely
};

// The report of sim (made with the request's options; its data moved by
// mj_forward), options named by reader.
CheckReport Check(Simulation* sim, const CheckRequest& request, const OptionReader& reader);

}  // namespace contactlaws::app

#endif  // CONTACTLAWS_APP_CHECK_JOB_H_
