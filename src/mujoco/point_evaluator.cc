// Copyright contactlaws authors.

#include "mujoco/point_evaluator.h"

#include <algorithm>
#include <limits>

#include "mujoco/kinematics.h"
#include "mujoco/friction_force.h"
#include "mujoco/vec3.h"

namespace contactlaws::internal {

PointEvaluator::PointEvaluator(const ContactModel& model)
    : model_(model),
      contacts_(MakeContactBuffer()),
      weights_(mjMAXCONPAIR),
      locals_(6 * mjMAXCONPAIR),
      matched_(mjMAXCONPAIR),
      gradients_(3 * mjMAXCONPAIR) {
  for (const GeomPair& pair : model.pairs()) {
    reads_mass_.push_back(ReadsEffectiveMass(pair.params));
  }
  latest_.reserve(std::min<size_t>(model.slot_count(), 4 * model.pairs().size()));
}

void PointEvaluator::Evaluate(mjData* d, const std::vector<int>& pairs,
                              const EpisodeLog& episodes, const StepStartVelocities& start,
                              ContactStepper* inner, double h) {
  const mjModel* m = model_.model();
  latest_.clear();
  latest_time_ = d->time;
  if (inner) inner->Clear();
  for (const int p : pairs) {
    const GeomPair& pair = model_.pairs()[p];
    const int g0 = pair.geom[0];
    const int g1 = pair.geom[1];
    const double margin = inner ? inner->Reach(d, pair, h) : 0.0;
    if (margin > 0) {
      double gap;
      mjtNum normal[3];
      if (BoundingGap(m, d, g0, g1, &gap, normal) && gap > margin) continue;
    } else if (FarApart(m, d, g0, g1)) {
      continue;
    }

    // the narrowphase (MuJoCo's, or ours for box-box: narrowphase.h): dist < 0
    // is penetration, frame[0..2] the normal from geom[0] to geom[1], pos
    // midway between the surfaces
    const int count =
        std::min(Collide(m, d, g0, g1, margin, contacts_.get(), weights_.data(), gradients_.data()),
                 pair.slots);
    // the points in contact: their open episodes, matched all at once (a
    // face patch's point that appears beside one in contact takes no episode
    // from the point nearer to it)
    int touching = 0;
    for (int i = 0; i < count; ++i) {
      if (!(-contacts_[i].dist > 0)) continue;
      double* local = locals_.data() + 6 * touching++;
      PointInBodies(d, pair, contacts_[i].pos, local, local + 3);
    }
    episodes.MatchOpenEpisodes(p, locals_.data(), touching, pair.identity_tolerance,
                               matched_.data());
    touching = 0;
    for (int i = 0; i < count; ++i) {
      const mjContact& con = contacts_[i];
      if (!(-con.dist > 0)) {
        if (inner) inner->AddNear(d, p, con, weights_[i], gradients_.data() + 3 * i);
        continue;
      }
      // the point is made where it is kept (it is large: no copy)
      PointEvaluation& e = latest_.emplace_back();
      const mjtNum* gradient = gradients_.data() + 3 * i;
      EvaluatePoint(d, p, con, weights_[i], gradient, matched_[touching++], episodes, start, &e);

      // equal and opposite, at the same point: geom[1] pushed along the
      // depth's gradient (+normal but at a face patch's sliding points),
      // its component along the normal the law's force
      mjtNum push[3];
      for (int b = 0; inner == nullptr && b < 2; ++b) {
        vec3::Scale(push, gradient, b == 1 ? e.force : -e.force);
        AddPointForce(m, d, pair.body[b], con.pos, push, d->qfrc_passive);
      }
      AddFriction(model_, d, episodes, pair, con, &e,
                  inner ? TangentialForce::kRecordOnly : TangentialForce::kAdd);
    }
  }
}

void PointEvaluator::EvaluatePoint(mjData* d, int p, const mjContact& con, double weight,
                                   const mjtNum gradient[3], int episode,
                                   const EpisodeLog& episodes, const StepStartVelocities& start,
                                   PointEvaluation* out) const {
  const GeomPair& pair = model_.pairs()[p];
  const mjtNum* normal = con.frame;
  PointEvaluation& e = *out;
  mjtNum v0[3], v1[3];
  ReadContactPoint(model_, d, p, con, &e, v0, v1);
  e.weight = weight;
  e.episode = episode;

  // the slip before its projection into the tangent plane (SlipAndSpin):
  // the same two velocities, computed once
  vec3::Sub(e.slip, v1, v0);
  // the depth's rate along its gradient (the normal's but at a face patch's
  // sliding points: narrowphase.h), which the rates, masses and the touch
  // below are taken along
  e.depth_rate = -vec3::Dot(e.slip, gradient);
  vec3::Copy(e.gradient, gradient);

  ContactState state{e.depth, e.depth_rate, 0.0, 0.0};
  if (reads_mass_[p]) {
    state.effective_mass = EffectiveMass(model_.model(), d, pair, con.pos, gradient);
  }
  const int open = e.episode;
  e.touch = open < 0;
  if (e.touch) {
    // v0: the rate at the step before first touch, which no force has slowed
    e.at_start = !start.has_previous();
    e.touch_velocity = start.has_previous()
                           ? ApproachRate(model_, d, pair, con.pos, gradient, start.previous(),
                                          start.previous_time())
                           : e.depth_rate;
    state.impact_velocity = std::max(e.touch_velocity, pair.params.min_impact_velocity);
    // the law at the touch itself (d = 0+, d' = v0)
    const ContactState touch{std::numeric_limits<double>::min(), e.touch_velocity,
                             state.impact_velocity, state.effective_mass};
    e.touch_power = weight * EvaluateLaw(pair.params, touch).dissipated_power(e.touch_velocity);
    e.max_approach = e.touch_velocity;
  } else {
    // v0: the touch speed, or the largest approach rate committed since, for
    // a contact compressed faster than it touched (a pulse through touching
    // bodies: Episode::chained)
    const double committed = episodes.MaxApproach(open);
    state.impact_velocity = std::max({episodes.episodes()[open].impact_velocity, committed,
                                      pair.params.min_impact_velocity});
    e.max_approach = std::max(committed, e.depth_rate);
  }
  e.impact_velocity = state.impact_velocity;
  const ContactForce f = EvaluateLaw(pair.params, state);
  e.force = weight * f.total;
  e.dissipated_power = weight * f.dissipated_power(e.depth_rate);
  vec3::Copy(e.pos, con.pos);
  vec3::Copy(e.normal, normal);
}

}  // namespace contactlaws::internal
