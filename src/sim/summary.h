// Copyright contactlaws authors.
//
// What a run's impact log says about it, in the terms of the paper's figures:
// how many impacts, the first impact's post-restitution (eq. 46), its depth,
// force and duration, and when the bodies came to rest.

#ifndef CONTACTLAWS_SIM_SUMMARY_H_
#define CONTACTLAWS_SIM_SUMMARY_H_

#include <optional>
#include <vector>

#include <cstdint>

#include "contactlaws/simulation.h"

namespace contactlaws {

struct RunSummary {
  int impacts = 0;                          // contact episodes, every tag
  std::optional<double> restitution_post;   // first episode, once it has ended
  std::optional<double> impact_velocity;    // first episode, m/s
  std::optional<double> contact_duration;   // first episode, once ended, s
  double max_depth = 0;                     // every episode, m
  double max_force = 0;                     // every episode, N
  std::optional<double> time_to_rest;       // s; see Summarize
};

// Summarizes impacts (ContactData::impacts(), in order of first touch) of a
// run that ended at end_time.
//
// time_to_rest is the first touch of the contact that never ended: for every
// geom pair that had episodes, its last episode must still be open at
// end_time and must have lasted longer than the pair's longest completed
// episode (a contact that has not outlasted every bounce before it cannot be
// told from one more bounce). It is the latest such first touch over the
// pairs; empty when a pair is not at rest, or there was no contact at all.
// settling, when given (one per impact): the impacts that are bodies
// settling into their contacts (run_report.h, SettlingImpacts), which are
// not the first impact whose e_post is reported.
RunSummary Summarize(const std::vector<Episode>& impacts, double end_time,
                     const std::vector<uint8_t>& settling = {});

// Summarize of the impacts of one tag of sim (ContactData::impacts() whose
// tag is tag, SettlingImpacts): the row per tag of `run`'s table and of the
// Python run().
RunSummary SummarizeTag(const Simulation& sim, int tag, double end_time);

}  // namespace contactlaws

#endif  // CONTACTLAWS_SIM_SUMMARY_H_
