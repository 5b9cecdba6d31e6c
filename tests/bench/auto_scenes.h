// Copyright contactlaws authors.
//
// The scenes of issue 22's costs of the contact-aware step (the one source of
// each: the benchmark auto_cost, the tests and `auto_scenes write` take them
// from here):
//   BallDropXml: 49 balls (radius 0.1 m, 10 kg) in a 7 x 7 grid 2 m apart,
//     dropped from 5 m on a floor tagged hertz (K = 1.4e8 N/m^1.5, the
//     paper's ball material); the ball-ball pairs, which never come near
//     each other, are left untagged, tagged (hertz, K / (2 sqrt 2): E*/2,
//     R/2), or masked by contype/conaffinity. RK4, the scene's 1e-5 s.
//   PileXml: SimBenchmark's "666": 216 balls (radius 0.1 m, 10 kg) in a
//     6 x 6 x 6 lattice with 1 cm gaps, 1 cm above the ground, collapsing;
//     ball-ball and ball-ground tagged hunt-crossley, e = 0.05, K = 1e9,
//     frictionless. RK4, 1e-4 s.

#ifndef CONTACTLAWS_TESTS_BENCH_AUTO_SCENES_H_
#define CONTACTLAWS_TESTS_BENCH_AUTO_SCENES_H_

#include <string>

namespace contactlaws::bench {

enum class BallBallPairs { kUntagged, kTagged, kMasked };

// The drop's grid: balls per side (per_side^2 balls), and the names of the
// three variants ("untagged", "tagged", "masked").
inline constexpr int kDropPerSide = 7;
const char* BallBallPairsName(BallBallPairs pairs);

// The drop of per_side^2 balls (kDropPerSide by default) with its ball-ball
// pairs as given.
std::string BallDropXml(BallBallPairs pairs, int per_side = kDropPerSide);

// The pile of per_side^3 balls (6: SimBenchmark's 216).
std::string PileXml(int per_side = 6);

}  // namespace contactlaws::bench

#endif  // CONTACTLAWS_TESTS_BENCH_AUTO_SCENES_H_
