"""scripts/cube_toss_report.py's flag of fitted values at a bound of their search range, and\nits resting height of the winner against the data."""
import importlib.util
import os

import pytest

SCRIPT = os.path.join(os.path.dirname(__file__), "..", "..", "scripts", "cube_toss_report.py")
spec = importlib.util.spec_from_file_location("cube_toss_report", SCRIPT)
report = importlib.util.module_from_spec(spec)
spec.loader.exec_module(report)

BOUNDS = report.parse_bounds("board.offset=-0.005:0.001,stiffness=1e4:3e6:log")


def row(**values):
    return {key: str(v) for key, v in values.items()}


@pytest.mark.parametrize("offset, flagged", [
    (-0.005, True),     # at the bound, as the cube tosses' fits end
    (-0.00489, True),   # 0.00011 from it: 1.8% of the 0.006 m range
    (0.00089, True),    # the same from the upper bound
    (-0.00485, False),  # 2.5%
    (-0.002, False),
])
def test_a_linear_range_within_two_percent_of_a_bound(offset, flagged):
    edge = report.at_bounds(row(**{"board.offset": offset}), BOUNDS)
    assert bool(edge) == flagged, edge


@pytest.mark.parametrize("share, flagged", [
    (0.0, True), (0.019, True), (0.981, True), (1.0, True), (0.021, False), (0.5, False),
])
def test_a_log_range_by_its_share_of_log_hi_over_lo(share, flagged):
    # a value `share` of the way from 1e4 to 3e6 on the log scale
    stiffness = 1e4 * 300 ** share
    edge = report.at_bounds(row(stiffness=stiffness), BOUNDS)
    assert bool(edge) == flagged, edge


def test_the_note_names_the_key_its_value_and_range():
    assert report.at_bounds(row(**{"board.offset": -0.005}, stiffness=2e5), BOUNDS) == [
        "board.offset = -0.005 (range -0.005:0.001)"]
    # a key the row does not have (a law that does not read it) is not flagged
    assert report.at_bounds(row(stiffness=1e4), BOUNDS) == [
        "stiffness = 1e+04 (range 10000:3e+06:log)"]


def samples(*z):
    return [{"cube.z": str(v)} for v in z]


def test_the_rest_height_is_the_median_gap_of_the_last_samples():
    measured = {"1": samples(0.2, 0.0512), "2": samples(0.3, 0.0510), "3": samples(0.1, 0.0520)}
    # the last samples 9, 8 and 7 mm low; toss 4 is not measured and counts for nothing
    simulated = {"1": samples(0.2, 0.0422), "2": samples(0.0430), "3": samples(0.0450),
                 "4": samples(0.0)}
    gap, tosses = report.rest_height(measured, simulated)
    assert tosses == 3
    assert gap == pytest.approx(-0.008, abs=1e-12)
    assert report.rest_height(measured, {"9": samples(0.0)}) is None


def test_published_scores_within_two_percent_share_a_label():
    assert report.published_labels(report.PUBLISHED) == [
        (0.270, "Drake 0.27, Bullet 0.272"), (0.371, "MuJoCo 0.371")]
