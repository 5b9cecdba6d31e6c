// Copyright contactlaws authors.
//
// PointEvaluator: the laws at every contact point of the tagged pairs an
// evaluation covers. For each pair: the bounding test (FarApart), the
// narrowphase (narrowphase.h), and at each point in contact the normal law
// (Evaluate) and the friction (friction_force.h), their forces added to
// qfrc_passive equal and opposite on the pair's two bodies. A pure function
// of the state it is given and the committed memory (the episodes, the
// step-start velocities): RK4 evaluates four times a step, and only the
// step committer (step_committer.h) writes the memory.

#ifndef CONTACTLAWS_MUJOCO_POINT_EVALUATOR_H_
#define CONTACTLAWS_MUJOCO_POINT_EVALUATOR_H_

#include <cstdint>
#include <vector>

#include <mujoco/mujoco.h>

#include "memory/contact_memory.h"
#include "contactlaws/contact_model.h"
#include "mujoco/contact_stepper.h"
#include "mujoco/narrowphase.h"
#include "mujoco/step_start.h"

namespace contactlaws::internal {

class PointEvaluator {
 public:
  // model must outlive this object.
  explicit PointEvaluator(const ContactModel& model);

  // Evaluates pairs (ContactModel::pairs() indices) at d's state into
  // latest() (time d->time) and adds their forces to d->qfrc_passive. With
  // inner (contacts integrated inside the step of h s, contact_stepper.h):
  // the points within its reach but not in contact go to inner, and the
  // normal forces are left to it (friction is added).
  void Evaluate(mjData* d, const std::vector<int>& pairs, const EpisodeLog& episodes,
                const StepStartVelocities& start, ContactStepper* inner = nullptr,
                double h = 0);

  // Forgets the latest evaluation.
  void Reset() { latest_.clear(); }

  // The contact points of the latest evaluation (depth > 0), in pair order.
  const std::vector<PointEvaluation>& latest() const { return latest_; }
  double latest_time() const { return latest_time_; }  // s

 private:
  // The normal law at a contact point of pair p (narrowphase output con, of
  // weight and depth gradient), into *e (default-constructed); episode: its
  // open episode (EpisodeLog::MatchOpenEpisodes), or -1.
  void EvaluatePoint(mjData* d, int p, const mjContact& con, double weight,
                     const mjtNum gradient[3], int episode, const EpisodeLog& episodes,
                     const StepStartVelocities& start, PointEvaluation* e) const;

  const ContactModel& model_;
  // per pair: its law reads the effective mass (Kelvin-Voigt with its
  // damping from e), resolved once
  std::vector<char> reads_mass_;
  ContactBuffer contacts_;  // narrowphase output, mjMAXCONPAIR
  std::vector<double> weights_;  // its points' weights, mjMAXCONPAIR
  // its points in contact: where they sit on the two bodies (6 each), their
  // open episodes; mjMAXCONPAIR points
  std::vector<double> locals_;
  std::vector<int> matched_;
  std::vector<mjtNum> gradients_;  // its points' depth gradients, 3 mjMAXCONPAIR
  std::vector<PointEvaluation> latest_;
  double latest_time_ = 0;
};

}  // namespace contactlaws::internal

#endif  // CONTACTLAWS_MUJOCO_POINT_EVALUATOR_H_
