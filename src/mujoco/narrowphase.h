// Copyright contactlaws authors.
//
// The narrowphase the laws are given: contactlaws' own box-box contact
// (geometry/box_box.h: full depths, the vertices of the contact patch, none
// repeated), MuJoCo's mjCOLLISIONFUNC for every other pair of geom types.
// MuJoCo 2.2.2's box-box halves its face contacts' depths and repeats or
// misplaces points (docs/geometry.md).

#ifndef CONTACTLAWS_MUJOCO_NARROWPHASE_H_
#define CONTACTLAWS_MUJOCO_NARROWPHASE_H_

#include <memory>

#include <mujoco/mujoco.h>

namespace contactlaws {

// The contacts of geoms g0 and g1 (geom_type[g0] <= geom_type[g1], as
// mjCOLLISIONFUNC wants, and a pair it collides) closer than margin (m), in
// out (room for mjMAXCONPAIR). Returns their count. Each has what MuJoCo's
// collision functions fill: dist (< 0 overlapping, m), pos midway between the
// surfaces, frame[0..2] the unit normal from g0 towards g1. With weight (room
// for mjMAXCONPAIR), each contact's share of the force (geometry/box_box.h:
// a face patch's points are weighted; MuJoCo's contacts and an edge
// contact's point weigh 1): the law's force at its depth times weight. With
// gradient (room for 3 mjMAXCONPAIR), each depth's gradient
// (BoxPoint::gradient: turned from frame[0..2] and longer at a face patch's
// point that slides along an edge; frame[0..2] for the others): the depth
// changes at its dot product with the approach velocity, and the force
// that the elastic energy stores acts along it. Allocates nothing.
int Collide(const mjModel* m, const mjData* d, int g0, int g1, mjtNum margin, mjContact* out,
            double* weight = nullptr, mjtNum* gradient = nullptr);

// Room for Collide's output, left uninitialized: Collide writes the contacts
// it counts, and only those are read (zeroing mjMAXCONPAIR contacts is 7
// pages the process would touch for nothing).
using ContactBuffer = std::unique_ptr<mjContact[]>;
inline ContactBuffer MakeContactBuffer() { return ContactBuffer(new mjContact[mjMAXCONPAIR]); }

}  // namespace contactlaws

#endif  // CONTACTLAWS_MUJOCO_NARROWPHASE_H_
