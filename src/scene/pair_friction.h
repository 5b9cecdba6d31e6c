// Copyright contactlaws authors.
//
// The friction of one tagged geom pair: the tag's friction keys, the
// overrides (--friction, --mu) and what MuJoCo would use for the pair (its
// geoms' condim and friction, combined by max as MuJoCo 2.2 combines them).

#ifndef CONTACTLAWS_SCENE_PAIR_FRICTION_H_
#define CONTACTLAWS_SCENE_PAIR_FRICTION_H_

#include <optional>
#include <string>

#include <mujoco/mujoco.h>

#include "contactlaws/contact_model.h"
#include "scene/tags.h"

namespace contactlaws {

struct PairFriction {
  FrictionParams params;
  int condim = 3;  // the larger of the two geoms' condim
  // set when the tag gives friction keys to a frictionless pair (condim 1):
  // the key, for the warning
  std::optional<std::string> ignored_key;
  // set when the tag gives a torque cap the pair's condim does not have
  // (torsional_friction below 4, rolling_friction below 6): "KEY=VALUE is
  // not read: ...", for the warning
  std::optional<std::string> unread_cap;
  // what is wrong, "KEY=VALUE RANGE", or empty
  std::string error;
};

// The friction of geoms g1, g2 under tag spec (its friction keys, and its
// materials for Mindlin's spring) and overrides.
PairFriction ResolvePairFriction(const mjModel* m, int g1, int g2, const internal::PairTagSpec& spec,
                                 const Overrides& overrides);

// The tangential damping's mass for the pair's bodies, kg (GeomPair::friction_mass).
// inertia: the bodies' largest principal moments of inertia instead of their
// subtree masses (GeomPair::friction_inertia).
double PairFrictionMass(const mjModel* m, int body0, int body1, bool inertia = false);

}  // namespace contactlaws

#endif  // CONTACTLAWS_SCENE_PAIR_FRICTION_H_
