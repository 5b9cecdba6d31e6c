// Copyright contactlaws authors.

#include "mujoco/visible_contacts.h"

#include <cmath>
#include <cstdio>
#include <cstring>

#include "mujoco/step_committer.h"

namespace contactlaws {
namespace {

// frame[0..2] = n (unit), frame[3..5] and frame[6..8] two unit tangents with
// t1 x t2 = n: t1 from the world axis least aligned with n.
void MakeContactFrame(const double normal[3], mjtNum frame[9]) {
  mjtNum n[3] = {normal[0], normal[1], normal[2]};
  mju_normalize3(n);
  int least = 0;
  for (int k = 1; k < 3; ++k) {
    if (std::abs(n[k]) < std::abs(n[least])) least = k;
  }
  mjtNum axis[3] = {0, 0, 0};
  axis[least] = 1;
  mjtNum t1[3];
  mjtNum t2[3];
  mju_cross(t1, axis, n);
  mju_normalize3(t1);
  mju_cross(t2, n, t1);
  mju_copy3(frame, n);
  mju_copy3(frame + 3, t1);
  mju_copy3(frame + 6, t2);
}

// One contact point as MuJoCo lists a contact within a geom's gap.
void FillContact(const GeomPair& pair, const PointEvaluation& point, mjContact* con) {
  std::memset(con, 0, sizeof(mjContact));
  con->dist = -point.depth;
  mju_copy3(con->pos, point.pos);
  MakeContactFrame(point.normal, con->frame);
  con->dim = 1;
  con->geom1 = pair.geom[0];
  con->geom2 = pair.geom[1];
  con->exclude = 1;        // in gap: detected, not given to the solver
  con->efc_address = -1;   // no constraint row: mjv draws no solver force
}

}  // namespace

int internal::AppendVisiblePoints(const ContactModel& model, const std::vector<PointEvaluation>& points,
                        mjData* d, VisibleContactsOverflow* overflow) {
  const mjModel* m = model.model();
  const std::vector<GeomPair>& pairs = model.pairs();
  int appended = 0;
  for (const PointEvaluation& point : points) {
    if (d->ncon >= m->nconmax) {
      if (overflow->dropped++ == 0) {
        char message[160];
        std::snprintf(message, sizeof(message),
                      "contactlaws: nconmax = %d leaves no room to show every tagged contact "
                      "point (those that do not fit are not drawn)",
                      m->nconmax);
        mju_warning(message);
      }
      continue;
    }
    FillContact(pairs[point.pair], point, d->contact + d->ncon);
    ++d->ncon;
    ++appended;
  }
  return appended;
}

int AppendVisibleContacts(const ContactData& contacts, mjData* d,
                          VisibleContactsOverflow* overflow) {
  return internal::AppendVisiblePoints(contacts.model(), contacts.latest(), d, overflow);
}

}  // namespace contactlaws
