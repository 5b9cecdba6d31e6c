// Copyright contactlaws authors.
//
// MuJoCo's small vector functions (engine_util_blas.c: mju_dot3, mju_sub3,
// mju_scl3, mju_rotVecMatT, ...) with the same operations in the same order,
// so the same bits, inlined: the hooks run them for every contact point of
// every RK4 stage, where a call into libmujoco costs more than its arithmetic.

#ifndef CONTACTLAWS_MUJOCO_VEC3_H_
#define CONTACTLAWS_MUJOCO_VEC3_H_

#include <cmath>

#include <mujoco/mujoco.h>

namespace contactlaws {
namespace vec3 {

inline mjtNum Dot(const mjtNum a[3], const mjtNum b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

inline void Cross(mjtNum res[3], const mjtNum a[3], const mjtNum b[3]) {
  res[0] = a[1] * b[2] - a[2] * b[1];
  res[1] = a[2] * b[0] - a[0] * b[2];
  res[2] = a[0] * b[1] - a[1] * b[0];
}

inline void Sub(mjtNum res[3], const mjtNum a[3], const mjtNum b[3]) {
  res[0] = a[0] - b[0];
  res[1] = a[1] - b[1];
  res[2] = a[2] - b[2];
}

inline void Scale(mjtNum res[3], const mjtNum v[3], mjtNum s) {
  res[0] = v[0] * s;
  res[1] = v[1] * s;
  res[2] = v[2] * s;
}

inline void AddTo(mjtNum res[3], const mjtNum v[3]) {
  res[0] += v[0];
  res[1] += v[1];
  res[2] += v[2];
}

// |v| (mju_norm3)
inline mjtNum Norm(const mjtNum v[3]) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

inline void Copy(mjtNum res[3], const mjtNum v[3]) {
  res[0] = v[0];
  res[1] = v[1];
  res[2] = v[2];
}

// res = mat v, mat 3x3 row-major (mju_rotVecMat)
inline void Rotate(mjtNum res[3], const mjtNum v[3], const mjtNum mat[9]) {
  const mjtNum r0 = mat[0] * v[0] + mat[1] * v[1] + mat[2] * v[2];
  const mjtNum r1 = mat[3] * v[0] + mat[4] * v[1] + mat[5] * v[2];
  const mjtNum r2 = mat[6] * v[0] + mat[7] * v[1] + mat[8] * v[2];
  res[0] = r0;
  res[1] = r1;
  res[2] = r2;
}

// res = mat^T v, mat 3x3 row-major (mju_rotVecMatT)
inline void RotateTransposed(mjtNum res[3], const mjtNum v[3], const mjtNum mat[9]) {
  const mjtNum r0 = mat[0] * v[0] + mat[3] * v[1] + mat[6] * v[2];
  const mjtNum r1 = mat[1] * v[0] + mat[4] * v[1] + mat[7] * v[2];
  const mjtNum r2 = mat[2] * v[0] + mat[5] * v[1] + mat[8] * v[2];
  res[0] = r0;
  res[1] = r1;
  res[2] = r2;
}

}  // namespace vec3
}  // namespace contactlaws

#endif  // CONTACTLAWS_MUJOCO_VEC3_H_
