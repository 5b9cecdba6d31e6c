// Copyright contactlaws authors.

#include "sim/settle.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "contactlaws/auto_timestep.h"
#include "contactlaws/contact_model.h"
#include "sim/estimate.h"
#include "contactlaws/simulation.h"
#include "mujoco/narrowphase.h"
#include "sim/settle_directions.h"
#include "sim/settle_friction.h"

namespace contactlaws {
namespace {

// The option settling is refused under (SimulationOptions::settle).
const OptionError::Mention kSettle{OptionError::Form::kSet, "settle", ""};

// The movable bodies of tagged pairs touching at sim's state (1 per body),
// with the depth their contacts allow (the largest GeomPair::depth_limit)
// and the normals of their contacts.
struct Touching {
  std::vector<uint8_t> body;
  std::vector<double> limit;
  std::vector<int> other;  // a body it touches
  SettleDirections directions;
  int count = 0;
};

Touching FindTouching(const Simulation& sim) {
  const ContactModel& cm = sim.contact_model();
  const mjModel* m = sim.model();
  Touching t;
  t.body.assign(m->nbody, 0);
  t.limit.assign(m->nbody, 0.0);
  t.other.assign(m->nbody, 0);
  ContactBuffer contacts = MakeContactBuffer();
  for (const GeomPair& pair : cm.pairs()) {
    const int n = Collide(m, sim.data(), pair.geom[0], pair.geom[1], kTouchingGap, contacts.get());
    if (n == 0) continue;
    for (const int b : {0, 1}) {
      const int body = pair.body[b];
      if (cm.FindDrive(body)) {
        throw OptionError(
            fmt::format("{}: {}: body '{}' touches the driven body '{}' at t = 0: a driven "
                        "body moves, so no static equilibrium holds",
                        sim.source(), OptionError::kMark,
                        ObjectName(m, mjOBJ_BODY, pair.body[1 - b]),
                        ObjectName(m, mjOBJ_BODY, body)),
            {kSettle});
      }
      if (Immovable(cm, body)) continue;
      t.count += !t.body[body];
      t.body[body] = 1;
      t.other[body] = pair.body[1 - b];
      t.limit[body] = std::max(t.limit[body], pair.depth_limit);
      for (int c = 0; c < n; ++c) t.directions.AddNormal(m, body, contacts[c].frame);
    }
  }
  return t;
}

// The joints that carry a touching body (its own and its ancestors').
std::vector<uint8_t> MovingJoints(const mjModel* m, const Touching& touching) {
  std::vector<uint8_t> moving(m->njnt, 0);
  for (int b = 1; b < m->nbody; ++b) {
    if (!touching.body[b]) continue;
    for (int a = b; a > 0; a = m->body_parentid[a]) {
      for (int j = m->body_jntadr[a]; j < m->body_jntadr[a] + m->body_jntnum[a]; ++j) {
        moving[j] = 1;
      }
    }
  }
  return moving;
}

// Refuses a free body in contact whose load (gravity, the scene's actuator
// and applied forces) lies along its contact surfaces: its contacts carry
// none of it, and it would fall as if they were not there.
void RefuseUnsupported(const Simulation& sim, const Touching& touching) {
  const mjModel* m = sim.model();
  const mjData* d = sim.data();
  for (int b = 1; b < m->nbody; ++b) {
    if (!touching.body[b] || !touching.directions.Held(b)) continue;
    mjtNum load[3];
    SettleDirections::Load(m, d, b, load);
    const double carried = touching.directions.Carried(b, load);
    if (carried < kSettleCarried) {
      throw OptionError(
          fmt::format("{}: {}: no contact carries body '{}': its load ({:.3g} N) lies along "
                      "its contact with '{}' ({:.3g} of it along the normal): it would fall",
                      sim.source(), OptionError::kMark, ObjectName(m, mjOBJ_BODY, b),
                      mju_norm3(load), ObjectName(m, mjOBJ_BODY, touching.other[b]), carried),
          {kSettle});
    }
  }
}

// qpos and qvel entries of joint j.
int QposSize(int type) { return type == mjJNT_FREE ? 7 : type == mjJNT_BALL ? 4 : 1; }
int DofSize(int type) { return type == mjJNT_FREE ? 6 : type == mjJNT_BALL ? 3 : 1; }

// 1/2 qvel^T M qvel; mv: room for nv numbers.
double Kinetic(const mjModel* m, mjData* d, std::vector<mjtNum>* mv) {
  mj_mulM(m, d, mv->data(), d->qvel);
  return 0.5 * mju_dot(d->qvel, mv->data(), m->nv);
}

// The largest |qacc| of the moving joints' dofs at rest (after mj_forward),
// a held body's in its directions.
double Residual(const mjModel* m, const mjData* d, const std::vector<uint8_t>& moving,
                const SettleDirections& directions) {
  double residual = 0;
  for (int j = 0; j < m->njnt; ++j) {
    if (!moving[j]) continue;
    if (directions.Held(m->jnt_bodyid[j])) {
      residual = std::max(residual, directions.Residual(m, d, m->jnt_bodyid[j]).Max());
      continue;
    }
    for (int v = 0; v < DofSize(m->jnt_type[j]); ++v) {
      residual = std::max(residual, std::abs(d->qacc[m->jnt_dofadr[j] + v]));
    }
  }
  return residual;
}

// A body's reach: its geoms' largest bounding radius, m.
double Reach(const mjModel* m, int b) {
  double reach = 0;
  for (int g = m->body_geomadr[b]; g >= 0 && g < m->body_geomadr[b] + m->body_geomnum[b]; ++g) {
    reach = std::max(reach, m->geom_rbound[g]);
  }
  return reach;
}

// The refusal of body b, which tips: its contacts carry its weight and not
// its turn; how, in evidence.
OptionError Tips(const Simulation& sim, int b, const std::string& evidence) {
  return OptionError(
      fmt::format("{}: {}: body '{}' tips: its contacts carry its weight but not its turn ({}), "
                  "so it has no resting pose to start from; start it without {}, or where it "
                  "rests",
                  sim.source(), OptionError::kMark, ObjectName(sim.model(), mjOBJ_BODY, b),
                  evidence, OptionError::kMark),
      {kSettle, kSettle});
}

}  // namespace

std::string SettleReport::Line() const {
  if (bodies == 0) return "settle: no body touches another at t = 0: nothing moved";
  std::string line = fmt::format(
      "settled {} bod{} in contact at t = 0 ({:.3g} s of relaxation): the farthest, '{}', "
      "by {:.3g} m; turns <= {:.3g} rad",
      bodies, bodies == 1 ? "y" : "ies", relaxation, body, distance, angle);
  if (!unheld.empty()) {
    line += fmt::format("; '{}' has no resting pose: it starts at its contacts' depth and rolls "
                        "or tips from there",
                        unheld);
  }
  return line;
}

SettleReport Settle(Simulation* sim, std::vector<PointEvaluation>* start_contacts) {
  const mjModel* m = sim->model();
  mjData* d = sim->data();
  mj_forward(m, d);
  Touching touching = FindTouching(*sim);
  SettleReport report;
  if (touching.count == 0) return report;
  RefuseUnsupported(*sim, touching);
  touching.directions.Start(m, d);
  const std::vector<uint8_t> moving = MovingJoints(m, touching);
  // the scene's applied forces, given back at the end
  const std::vector<mjtNum> applied(d->qfrc_applied, d->qfrc_applied + m->nv);
  const std::vector<mjtNum> qpos0(d->qpos, d->qpos + m->nq);
  const std::vector<mjtNum> xpos0(d->xpos, d->xpos + 3 * m->nbody);
  const std::vector<mjtNum> xquat0(d->xquat, d->xquat + 4 * m->nbody);
  const double start = d->time;

  // the farthest touching body from its start, and the largest turn; a
  // body that left its contacts' reach: the refusal that says how
  int departed = -1;  // the body measure refused
  auto measure = [&]() -> std::optional<OptionError> {
    for (int b = 1; b < m->nbody; ++b) {
      if (!touching.body[b]) continue;
      mjtNum offset[3];
      mju_sub3(offset, d->xpos + 3 * b, xpos0.data() + 3 * b);
      const double distance = mju_norm3(offset);
      if (distance >= report.distance) {
        report.distance = distance;
        report.body = ObjectName(m, mjOBJ_BODY, b);
      }
      const double cosine = std::min(1.0, std::abs(mju_dot(d->xquat + 4 * b,
                                                           xquat0.data() + 4 * b, 4)));
      const double angle = 2 * std::acos(cosine);
      report.angle = std::max(report.angle, angle);
      // moved mostly by turning (its turn at its reach at least half the
      // distance): it tips over its contacts rather than sinking through them
      if (distance > touching.limit[b]) departed = b;
      if (distance > touching.limit[b] && angle * Reach(m, b) >= 0.5 * distance) {
        return Tips(*sim, b, fmt::format("it turned {:.3g} rad in {:.3g} s of relaxation", angle,
                                         d->time - start));
      }
      if (distance > touching.limit[b]) {
        return OptionError(
            fmt::format("{}: {}: no contact holds body '{}': it moved {:.3g} m in {:.3g} s of "
                        "relaxation, farther than its contacts can compress ({:.3g} m): it "
                        "would fall",
                        sim->source(), OptionError::kMark, ObjectName(m, mjOBJ_BODY, b),
                        distance, d->time - start, touching.limit[b]),
            {kSettle});
      }
    }
    return std::nullopt;
  };

  // quasi-static relaxation: the other bodies held, the velocities quenched
  // as the kinetic energy starts to fall, until the residual is small;
  // directions: the free bodies in contact moved along their contacts'
  // normals only, their load along the surfaces cancelled (else the full
  // dynamics, friction's springs holding them). Whether it converged.
  const SettleDirections anywhere;
  std::vector<mjtNum> mv(m->nv);
  // its steps: the run's, and no longer than the auto timestep's rules let
  // the laws' explicit forces go (a scene at MuJoCo's 2 ms, whose run takes
  // auto steps or integrates its contacts inside the step, relaxes too);
  // the run's own wherever those allow it (a scene at its fine step)
  const double timestep = sim->contacts().options().timestep;
  AutoTimestep steps(sim->contacts());
  // refuse: a body leaving its contacts is refused (the normal equilibrium),
  // else it ends the relaxation unconverged
  auto relax = [&](const SettleDirections& directions, bool refuse) {
    mju_copy(d->qfrc_applied, applied.data(), m->nv);
    mju_zero(d->qvel, m->nv);
    mj_forward(m, d);
    directions.CancelAlongSurfaces(m, d);
    mj_forward(m, d);
    double previous = 0;
    bool converged = Residual(m, d, moving, directions) < kSettleResidual;
    steps.Reset();
    while (!converged && d->time - start < kSettleDuration) {
      sim->Step(std::min(timestep, steps.Next(d, kSettleDuration - (d->time - start))));
      if (sim->contacts().divergence()) {
        throw OptionError(fmt::format("{}: {}: the relaxation diverged at t = {:.6g} s: {}",
                                      sim->source(), OptionError::kMark, d->time - start,
                                      sim->contacts().divergence()->what),
                          {kSettle});
      }
      for (int j = 0; j < m->njnt; ++j) {
        if (moving[j]) continue;
        const int type = m->jnt_type[j];
        mju_copy(d->qpos + m->jnt_qposadr[j], qpos0.data() + m->jnt_qposadr[j], QposSize(type));
        mju_zero(d->qvel + m->jnt_dofadr[j], DofSize(type));
      }
      directions.Project(m, d);
      if (std::optional<OptionError> departure = measure()) {
        if (refuse) throw *departure;
        return false;
      }
      const double kinetic = Kinetic(m, d, &mv);
      if (kinetic < previous) {
        mju_zero(d->qvel, m->nv);
        mj_forward(m, d);
        converged = Residual(m, d, moving, directions) < kSettleResidual;
        previous = 0;
      } else {
        previous = kinetic;
      }
    }
    mju_copy(d->qfrc_applied, applied.data(), m->nv);
    mj_forward(m, d);
    if (std::optional<OptionError> departure = measure()) {
      if (refuse) throw *departure;
      return false;
    }
    return converged;
  };

  // the normal equilibrium
  if (!relax(touching.directions, /*refuse=*/true)) {
    // a body whose contacts carry its weight and not its turn tips: a domino
    // stood on an edge; no relaxation ends that, and the refusal says so
    int tipping = -1;
    double turn = 0;
    for (int b = 1; b < m->nbody; ++b) {
      if (!touching.body[b] || !touching.directions.Held(b)) continue;
      const SettleDirections::Acceleration a = touching.directions.Residual(m, d, b);
      // its turn's acceleration at its reach, against its translation's: a
      // turn ten times faster tips it
      if (a.angular > std::max(turn, kSettleResidual) && a.angular * Reach(m, b) > 10 * a.linear) {
        tipping = b;
        turn = a.angular;
      }
    }
    if (tipping >= 0) {
      throw Tips(*sim, tipping, fmt::format("it still turns at {:.3g} rad/s^2 after {} s of "
                                            "relaxation", turn, kSettleDuration));
    }
    throw OptionError(
        fmt::format("{}: {}: no equilibrium along the contacts' normals: the bodies in contact "
                    "still accelerate at {:.3g} m/s^2 after {} s of relaxation (body '{}' "
                    "moved {:.3g} m)",
                    sim->source(), OptionError::kMark,
                    Residual(m, d, moving, touching.directions), kSettleDuration, report.body,
                    report.distance),
        {kSettle});
  }
  bool sliding = false;
  std::vector<PointEvaluation> contacts = StartFriction(*sim, touching.directions, &sliding);
  // nothing slides: on to the static equilibrium, the friction's springs
  // loaded (kept where it does not converge, a contact ends sliding, or a
  // body leaves: a ball on a slope its friction holds rolls, a domino on an
  // edge tips, as a block on a steeper slope slides; the run starts them
  // from their normal equilibrium)
  if (!sliding) {
    const std::vector<mjtNum> normal(d->qpos, d->qpos + m->nq);
    const SettleReport normal_report = report;
    const double normal_time = d->time;
    bool held = relax(anywhere, /*refuse=*/false);
    for (const PointEvaluation& e : sim->contacts().latest()) held = held && !e.friction_state.sliding;
    if (held) {
      contacts = HeldFriction(*sim);
    } else {
      mju_copy(d->qpos, normal.data(), m->nq);
      report = normal_report;
      if (departed >= 0) report.unheld = ObjectName(m, mjOBJ_BODY, departed);
      d->time = normal_time;
      mj_forward(m, d);
    }
  }
  report.relaxation = d->time - start;
  report.bodies = touching.count;
  if (start_contacts) *start_contacts = std::move(contacts);
  mju_zero(d->qvel, m->nv);
  return report;
}

}  // namespace contactlaws
