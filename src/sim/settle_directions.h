// Copyright contactlaws authors.
//
// Where settling may move a free body in contact: along its contacts'
// normals only. Its position along the contact surfaces and its turn about
// a single contact normal are the scene's, so that a body pushed along the
// surface (an actuator, an applied force, a slope steeper than its friction)
// is settled into the depth its contacts carry it at, not slid away.
//
// The translation is kept in the span of the normals of its contacts (one
// normal: a line; two independent ones: their plane; three: anything). Its
// turns are free but about the one normal when it has one: a box on four
// corners tilts to share its load, and does not spin in the floor's plane.

#ifndef CONTACTLAWS_SIM_SETTLE_DIRECTIONS_H_
#define CONTACTLAWS_SIM_SETTLE_DIRECTIONS_H_

#include <vector>

#include <mujoco/mujoco.h>

namespace contactlaws {

class SettleDirections {
 public:
  // A normal (unit) of a contact of body b, either sign.
  void AddNormal(const mjModel* m, int b, const mjtNum normal[3]);

  // Records the state d's positions as where each body started (call after
  // the normals, at the scene's state).
  void Start(const mjModel* m, const mjData* d);

  // Whether body b's motion is held to its normals (a body whose own joint
  // is a free joint); the others move as their joints let them.
  bool Held(int b) const;

  // Moves each held body back into its directions from its start: qpos and
  // qvel of its free joint.
  void Project(const mjModel* m, mjData* d) const;

  // The largest |qacc| of body b's free joint in its directions, after
  // mj_forward: of its translation (m/s^2) and of its turn (rad/s^2).
  struct Acceleration {
    double linear = 0, angular = 0;
    double Max() const { return linear > angular ? linear : angular; }
  };
  Acceleration Residual(const mjModel* m, const mjData* d, int b) const;

  // The load of a free body b (world, N): gravity on its subtree, the
  // actuator and applied forces on its free joint's translation.
  static void Load(const mjModel* m, const mjData* d, int b, mjtNum f[3]);

  // The part of body b's load along its contact surfaces (world, N; 0 for
  // a body not held).
  void Tangential(const mjModel* m, const mjData* d, int b, mjtNum t[3]) const;

  // Adds to d->qfrc_applied what cancels each held body's load along its
  // contact surfaces, and its torque about its one normal, at d's state
  // (after mj_forward): held where it is, the relaxation is not dragged
  // along a surface and back at each step (its friction springs would be
  // wound up doing so, and would hold the body off its rest).
  void CancelAlongSurfaces(const mjModel* m, mjData* d) const;

  // The fraction of force f (world) its directions take (|P f| / |f|; 1 for
  // f = 0): 0 for a body whose load is all along its contact surfaces (a
  // ball touching a wall beside it under gravity).
  double Carried(int b, const mjtNum f[3]) const;

 private:
  struct Body {
    int body = -1;
    int joint = -1;             // its free joint
    int rank = 0;               // independent normals (<= 3)
    mjtNum basis[3][3] = {};    // orthonormal, rank rows
    mjtNum pos0[3] = {};        // its free joint's position at the start
    mjtNum quat0[4] = {1, 0, 0, 0};
  };
  const Body* Find(int b) const;
  // v projected onto body's translations
  static void Translate(const Body& body, mjtNum v[3]);
  std::vector<Body> bodies_;
};

}  // namespace contactlaws

#endif  // CONTACTLAWS_SIM_SETTLE_DIRECTIONS_H_
