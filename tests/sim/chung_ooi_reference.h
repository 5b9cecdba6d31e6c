// Copyright contactlaws authors.
//
// Published reference data of H. Chung, J. Y. Ooi, "Benchmark tests for
// verifying discrete element modelling codes at particle impact level",
// Granular Matter 13:643-656 (2011): the DEM codes' curves of test 4 (a
// sphere at 3.9 m/s onto a rigid plane at 5 ... 85 degrees from the normal,
// mu 0.092, e 0.98, R 2.5 mm; alumina and aluminium alloy), as points read
// off the paper's figures.
//
// Source of the numbers: KratosMultiphysics/Kratos,
// applications/DEMApplication/test_examples/basic_benchmarks/paper_data/
// benchmark4_graph1.dat (tangential restitution) and benchmark4_graph2.dat
// (spin, rad/s), BSD-4 licence (the Kratos project's). Numbers only,
// rounded to 4 digits; the paper itself was not read here.
//
// And one DEM code's own results of test 4 (alumina, a wall of E 7e20 Pa,
// Hertz with Mindlin's no-slip spring, 2e-8 s): Kratos' DEMApplication, the
// same repository, applications/DEMApplication/tests/DEM3D_chung_ooi_tests/
// test4_data/benchmark4_dt_2e-08_tangential_restitution_coefficient_list_
// data.dat and ..._final_angular_vel_list_data.dat (BSD-4). Below 15
// degrees the paper's curves, read off a steep slope, and this code's
// results part (at 5 degrees v_t'/v_t 0.948 read, 0.854 computed).

#ifndef CONTACTLAWS_TESTS_SIM_CHUNG_OOI_REFERENCE_H_
#define CONTACTLAWS_TESTS_SIM_CHUNG_OOI_REFERENCE_H_

namespace contactlaws::testing {

// One point of a digitized curve: the incident angle from the normal
// (degrees) and the quantity there.
struct CurvePoint {
  double degrees, value;
};

// The radius the benchmark's test 4 takes (m): its spins are for it.
inline constexpr double kChungOoiTest4Radius = 2.5e-3;

// Test 4: v_t'/v_t of the sphere's centre.
inline constexpr CurvePoint kTest4TangentialRestitutionAlumina[] = {
    {5.168, 0.9481},  {10.158, 0.6870}, {14.990, 0.6244}, {20.059, 0.6161}, {25.050, 0.6343},
    {30.119, 0.6837}, {35.030, 0.7372}, {40.020, 0.7809}, {50.000, 0.8451}, {59.980, 0.8929},
    {69.960, 0.9316}, {80.020, 0.9662}, {85.010, 0.9827}};
inline constexpr CurvePoint kTest4TangentialRestitutionAlloy[] = {
    {5.089, 0.8987},  {10.000, 0.6713}, {15.069, 0.6129}, {20.059, 0.6087}, {24.970, 0.6334},
    {30.040, 0.6829}, {35.030, 0.7364}, {40.020, 0.7801}, {49.921, 0.8443}, {59.980, 0.8913},
    {70.040, 0.9325}, {80.099, 0.9662}, {84.931, 0.9827}};

// Test 4: the magnitude of the spin after the impact, rad/s, at R 2.5 mm.
inline constexpr CurvePoint kTest4SpinAlumina[] = {
    {4.951, 19.27},   {10.079, 213.00}, {14.970, 377.83}, {19.941, 510.55}, {24.911, 599.39},
    {29.961, 616.51}, {34.931, 582.26}, {39.980, 544.80}, {50.000, 457.03}, {60.020, 357.49},
    {69.961, 246.18}, {80.059, 126.30}, {85.030, 63.15}};
inline constexpr CurvePoint kTest4SpinAlloy[] = {
    {4.951, 35.32},   {9.921, 223.70},  {14.970, 389.60}, {20.020, 519.11}, {24.911, 599.39},
    {30.039, 617.58}, {34.852, 582.26}, {39.980, 544.80}, {50.000, 458.10}, {60.020, 358.56},
    {69.961, 245.11}, {80.059, 125.23}, {85.030, 64.22}};

// Kratos' results of test 4 (alumina), 5 ... 85 degrees by 5: v_t'/v_t and
// the magnitude of the spin (rad/s, at R 2.5 mm).
struct KratosPoint {
  double degrees, restitution, spin;
};
inline constexpr KratosPoint kTest4KratosAlumina[] = {
    {5, 0.85406, 49.462},   {10, 0.71177, 194.627}, {15, 0.63327, 369.109},
    {20, 0.62191, 502.955}, {25, 0.63968, 592.395}, {30, 0.68591, 611.056},
    {35, 0.74085, 578.406}, {40, 0.78375, 540.969}, {45, 0.81854, 499.420},
    {50, 0.84774, 454.054}, {55, 0.87294, 405.231}, {60, 0.89524, 353.309},
    {65, 0.91538, 298.688}, {70, 0.93395, 241.774}, {75, 0.95138, 182.999},
    {80, 0.96800, 122.808}, {85, 0.98412, 61.656}};

// Tests 5 and 6, from the same directory of the same repository
// (benchmark5_graph1.dat, benchmark5_graph2.dat, benchmark6_graph1.dat, the
// paper's curves as Kratos digitized them), with the inputs Kratos' scenes
// of those tests take (benchmark5DEM.mdpa, benchmark6DEM.mdpa): one point
// is {x, y} of the figure.
struct FigurePoint {
  double x, y;
};

// Test 5: steel (E 208 GPa, nu 0.30, rho 7850), v_n 5 m/s, mu 0.3, e 1, no
// spin, v_t for x = v_t / (mu v_n). The contact point's rebound tangent over
// mu, v_t,c' / (mu v_n'):
inline constexpr FigurePoint kTest5ReboundSteel[] = {
    {0.0665, -0.0800}, {0.3323, -0.2800}, {0.6707, -0.4933}, {1.0091, -0.7467}, {1.3353, -1.0000},
    {1.6616, -1.2667}, {2.0000, -1.5333}, {2.3505, -1.8133}, {2.9909, -2.4400}, {3.3414, -2.6933},
    {4.0060, -2.7867}, {4.9970, -2.0000}, {6.0000, -1.0133}, {9.9879, 3.0133},  {12.9607, 6.0133}};
// and the spin, R w' / (mu v_n), against the same x:
inline constexpr FigurePoint kTest5SpinSteel[] = {
    {0.0578, 0.1055},  {0.3526, 0.4301},  {0.6821, 0.8197},  {0.9942, 1.2498},  {1.3410, 1.6637},
    {1.6879, 2.0938},  {2.0000, 2.5240},  {2.3295, 2.9784},  {2.9884, 3.9037},  {3.3179, 4.2932},
    {3.9942, 4.8368},  {5.0000, 5.0068},  {6.0058, 5.0062},  {10.0116, 5.0041}, {20.0000, 4.9905}};

// Test 5, polyethylene (chung_ooi_model.h), the same two curves as PySPH
// digitized them: dineshadepu/pysph, branch dem (ad11343b),
// pysph/examples/dem/discontinuous_dem/test_chung_paper/chung_test_5_
// normalized_recoil_angle_vs_normalized_incident_angle_polyethylene.csv and
// ..._post_collision_ang_vel_..._polyethylene.csv, BSD-3 licence (PySPH's).
// The spin negated: PySPH's tangential axis points the other way (its steel
// spin curve is negative where Kratos' is positive). Sorted by x.
inline constexpr FigurePoint kTest5ReboundPolyethylene[] = {
    {0.0492, -0.0460}, {0.3331, -0.3389}, {0.6736, -0.5272}, {1.0144, -0.9038}, {1.3359, -1.1130},
    {1.6767, -1.4895}, {1.9796, -1.7824}, {2.3391, -2.0962}, {2.9638, -2.7238}, {3.3421, -2.9540},
    {4.0222, -2.8912}, {5.0408, -2.0335}, {5.9647, -1.0502}, {10.0003, 2.9665}, {12.3197, 5.3305}};
inline constexpr FigurePoint kTest5SpinPolyethylene[] = {
    {0.1138, 0.1463},  {0.2840, 0.4522},  {0.6252, 0.9043},  {0.9665, 1.3298},
    {1.2790, 1.7952},  {1.6776, 2.2073},  {2.0187, 2.6727},  {2.3314, 3.1116},
    {3.0421, 4.0689},  {3.2690, 4.4945},  {3.9536, 4.9198},  {4.9834, 4.9856},
    {5.9562, 4.9850},  {9.9621, 4.9557},  {17.4585, 4.9507}, {20.0050, 4.9490}};

// Test 6: aluminium alloy (E 70 GPa, nu 0.33, rho 2700), v_n 0.2 m/s, mu
// 0.4, e 0.5, no tangential speed, the spin giving the contact point v_t,c
// for x = 3.5 mu (1 + e) v_n / v_t,c. The contact point's tangential
// restitution beta = -v_t,c' / v_t,c:
inline constexpr FigurePoint kTest6BetaAlloy[] = {
    {0.1762, -0.8200},  {0.3524, -0.6335}, {0.5507, -0.4447}, {0.7709, -0.2428}, {0.9692, -0.0277},
    {1.1894, 0.0974},   {1.4537, 0.1193},  {1.7401, 0.0996},  {2.0925, 0.0579},  {2.4890, 0.0052},
    {2.9956, -0.0497},  {3.6344, -0.1001}, {4.5154, -0.1396}, {5.7489, -0.1748}, {7.8194, -0.2077},
    {11.8943, -0.2582}, {24.0088, -0.3416}};

// Test 6, nylon (chung_ooi_model.h), Kratos' benchmark6_graph2.dat (its
// second set): the tangent of the contact point's rebound angle v_t,c'/v_n'
// against the incident one's, v_t,c/v_n.
inline constexpr FigurePoint kTest6ReboundTangentNylon[] = {
    {0.0848, 0.0216}, {0.1798, 0.0485}, {0.2613, 0.0487}, {0.3632, 0.0891}, {0.4650, 0.0625},
    {0.5736, 0.0359}, {0.6958, -0.0308}, {0.8383, -0.1242}, {0.9944, -0.2310}, {1.1912, -0.3244},
    {1.4220, -0.3775}, {1.7344, -0.3769}, {2.1420, 0.0523}, {2.7471, 1.2717}, {3.7329, 3.2548},
    {5.6706, 7.1273}, {6.1057, 7.9983}};

// Test 8 (the inputs: chung_ooi_test), from the same directory
// (benchmark8_graph1.dat, the paper's curves as Kratos digitized them): beta
// against x as in test 6, for a sphere onto a sphere of 5 times its radius,
// case A (the larger sphere 1000 times stiffer) and case B (of one
// material). They part from x = 7.8 on.
inline constexpr FigurePoint kTest8BetaCaseA[] = {
    {0.1872, -0.8152},  {0.3583, -0.6262}, {0.5508, -0.4394}, {0.7647, -0.2378}, {0.9786, -0.0173},
    {1.2139, 0.0961},   {1.4920, 0.1108},  {1.7701, 0.0898},  {2.0909, 0.0583},  {2.5187, 0.0058},
    {2.9893, -0.0488},  {3.6310, -0.1034}, {4.5080, -0.1391}, {5.7701, -0.1622}, {7.8449, -0.2042},
    {11.9091, -0.2483}, {23.9733, -0.3176}};
inline constexpr FigurePoint kTest8BetaCaseB[] = {
    {0.1872, -0.8152},  {0.3583, -0.6262}, {0.5508, -0.4394}, {0.7647, -0.2378}, {0.9786, -0.0173},
    {1.2139, 0.0961},   {1.4920, 0.1108},  {1.7701, 0.0898},  {2.0909, 0.0583},  {2.5187, 0.0058},
    {2.9893, -0.0488},  {3.6310, -0.1034}, {4.5080, -0.1391}, {5.7701, -0.1622}, {7.8449, -0.1055},
    {11.9091, -0.1076}, {23.9947, -0.1055}};

}  // namespace contactlaws::testing

#endif  // CONTACTLAWS_TESTS_SIM_CHUNG_OOI_REFERENCE_H_
