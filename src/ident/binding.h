// Copyright contactlaws authors.
//
// The columns of measured data bound to a scene (which body or joint each
// names), and the state a trajectory starts from under a ReplayOptions'
// rule: Replay's two jobs before it simulates.

#ifndef CONTACTLAWS_IDENT_BINDING_H_
#define CONTACTLAWS_IDENT_BINDING_H_

#include <vector>

#include "contactlaws/replay.h"

namespace contactlaws::internal {

enum BodyQuantity { kX = 0, kQw = 3, kVx = 7, kWx = 10 };  // in kBodyQuantities

// A measured body: its free joint's slots and the data's columns.
struct MeasuredBody {
  int body = -1;
  bool free = false;        // it has a free joint of its own: its state is set
  int qpos = 0, qvel = 0;   // its free joint's addresses
  int col[13];              // kBodyQuantities' columns, -1 when absent
  double length = 0;        // e_q's default L_b: its smallest GeomSize, m
  double rbound = 0;        // the refit's default height, m
  bool has(int q) const { return col[q] >= 0; }
};


// A measured hinge or slide.
struct MeasuredJoint {
  int joint = -1;
  int qpos = 0, qvel = 0;
  int col_q = -1, col_v = -1;
};

class Binding {
 public:
  // Throws Error naming the file and column (Replay's constructor).
  Binding(const Scene& scene, const MeasuredData& data);

  const std::vector<MeasuredBody>& bodies() const { return bodies_; }
  const std::vector<MeasuredJoint>& joints() const { return joints_; }

  // The start sample of trajectory i under options' rule.
  int StartSample(int i, const ReplayOptions& options) const;

  // The measured state of sample s of t into d (RefitRule's velocities under
  // kRefit from min_samples on): the measured free bodies' qpos and qvel,
  // the measured joints'.
  void SetStart(const MeasuredTrajectory& t, int s, const ReplayOptions& options,
                const mjModel* m, mjData* d) const;

 private:
  const double* Sample(const MeasuredTrajectory& t, int k) const {
    return t.values.data() + static_cast<size_t>(k) * data_.columns.size();
  }
  // RefitRule's velocities of body b at start sample s.
  void RefitVelocity(const MeasuredTrajectory& t, int s, const MeasuredBody& b,
                     const double* gravity, double* qvel) const;

  const MeasuredData& data_;
  std::vector<MeasuredBody> bodies_;
  std::vector<MeasuredJoint> joints_;
};

}  // namespace contactlaws::internal

#endif  // CONTACTLAWS_IDENT_BINDING_H_
