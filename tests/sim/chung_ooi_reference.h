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

}  // namespace contactlaws::testing

#endif  // CONTACTLAWS_TESTS_SIM_CHUNG_OOI_REFERENCE_H_
