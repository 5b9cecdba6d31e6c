"""compare, restitution, replay, fit, laws and check from Python against the
command line on the same scene: the same files, the same numbers."""

import _thread
import io
import os
import subprocess
import tempfile
import threading
import time

import pandas as pd
import pytest

import contactlaws
from contactlaws import _contactlaws

CLI = os.environ["CONTACTLAWS_CLI"]
BALL = os.path.join(os.environ["CONTACTLAWS_MJCF"], "bouncing_ball.xml")
INCLINE = os.path.join(os.environ["CONTACTLAWS_MJCF"], "friction_incline.xml")


def cli(*args, check=True):
    return subprocess.run([CLI, *args], capture_output=True, text=True, check=check)


def spoken(refused):
    """The command line's refusal as Python raises it: its flags named as the
    keyword arguments (python/keywords.cc)."""
    return _contactlaws._spelled(refused.stderr.removeprefix("contactlaws: ").rstrip("\n"))


def read(path):
    """A CSV of the command line, its numbers read exactly (shortest exact
    form), its empty fields as NaN and nothing else."""
    return pd.read_csv(path, float_precision="round_trip", keep_default_na=False,
                       na_values=[""])


def assert_same(frame, path):
    pd.testing.assert_frame_equal(frame, read(path), check_exact=True)


def assert_same_numbers(frame, path):
    """frame, the library's columns, against the command line's CSV read
    with frame's column types: its numbers (a score of 0 is written 0, read
    back as an integer otherwise) and its names and words as text."""
    types = {c: str if frame[c].dtype == object else frame[c].dtype for c in frame.columns}
    # an empty field: a number not known (NaN), a text that is empty ("")
    unknown = {c: [""] for c in frame.columns if frame[c].dtype != object}
    expected = pd.read_csv(path, float_precision="round_trip", keep_default_na=False,
                           na_values=unknown, dtype=types)
    pd.testing.assert_frame_equal(frame, expected, check_exact=True)


def test_compare_gives_the_command_lines_three_files(tmp_path, monkeypatch):
    cli("compare", BALL, "--laws=hertz,flores,hunt-crossley", "--restitution=0.5,0.8",
        "--duration=0.6", "--sample-rate=200", "--quiet", "--output-dir", str(tmp_path))

    # the results come back as the library's columns: no folder, no CSV read back
    def no_file(*args, **kwargs):
        raise AssertionError("compare went through a file")
    monkeypatch.setattr(tempfile, "TemporaryDirectory", no_file)
    monkeypatch.setattr(contactlaws.commands._pd, "read_csv", no_file)
    result = contactlaws.compare(BALL, laws=["hertz", "flores", "hunt-crossley"],
                                 restitution=[0.5, 0.8], duration=0.6, sample_rate=200)
    monkeypatch.undo()
    for name in ("trajectories", "impacts", "summary"):
        assert_same_numbers(getattr(result, name), tmp_path / f"{name}.csv")
    # hertz once (elastic), the two others at both e: five runs
    assert list(result.summary["law"]) == ["hertz"] + ["flores"] * 2 + ["hunt-crossley"] * 2
    assert "first e_post" in result.report


def test_compare_of_friction_models(tmp_path):
    cli("compare", INCLINE, "--laws=hertz", "--frictions=coulomb,stribeck", "--duration=0.3",
        "--quiet", "--output-dir", str(tmp_path))
    result = contactlaws.compare(INCLINE, laws="hertz", frictions="coulomb,stribeck",
                                 duration=0.3)
    for name in ("trajectories", "impacts", "summary"):
        assert_same_numbers(getattr(result, name), tmp_path / f"{name}.csv")
    assert list(result.summary["friction"]) == ["coulomb", "stribeck"]


def test_restitution_gives_the_command_lines_table(tmp_path, monkeypatch):
    out = tmp_path / "fig7.csv"
    cli("restitution", BALL, "--laws=hertz,flores,gonthier", "--restitution=0.2,0.6,1",
        "--duration=0.6", "--quiet", "--output", str(out))

    # the table comes back as the library's columns: no folder, no CSV read back
    def no_file(*args, **kwargs):
        raise AssertionError("restitution went through a file")
    monkeypatch.setattr(tempfile, "TemporaryDirectory", no_file)
    monkeypatch.setattr(contactlaws.commands._pd, "read_csv", no_file)
    table = contactlaws.restitution(BALL, laws="hertz,flores,gonthier", restitution=[0.2, 0.6, 1],
                                    duration=0.6)
    monkeypatch.undo()
    assert_same(table, out)
    assert list(table["law"]) == ["hertz"] * 3 + ["flores"] * 3 + ["gonthier"] * 3


@pytest.fixture(scope="module")
def measured(tmp_path_factory):
    """Two bounces of the ball at e = 0.6 as measured data: run's body
    columns with a trajectory column in front (docs/identification.md)."""
    folder = tmp_path_factory.mktemp("measured")
    frames = []
    for name, restitution in (("a", 0.6), ("b", 0.62)):
        run = contactlaws.run(BALL, law="flores", restitution=restitution, duration=0.8,
                              sample_rate=100, columns="bodies").trajectory
        run.insert(0, "trajectory", name)
        frames.append(run)
    path = folder / "ball.csv"
    pd.concat(frames).to_csv(path, index=False)
    return path


def test_replay_gives_the_command_lines_files(tmp_path, measured):
    cli("replay", BALL, "--data", str(measured), "--law=flores", "--restitution=0.5",
        "--timestep=1e-4", "--quiet", "--output", str(tmp_path))
    result = contactlaws.replay(BALL, measured, law="flores", restitution=0.5, timestep=1e-4)
    assert_same_numbers(result.scores, tmp_path / "replay.csv")
    assert_same_numbers(result.trajectories, tmp_path / "trajectories.csv")
    assert len(result.scores) == 2


def test_replay_takes_a_dataframe_as_the_file(tmp_path, measured):
    # the measured CSV read into a DataFrame: the same scores to the bit as the
    # command line on the file, the data never written
    frame = pd.read_csv(measured, float_precision="round_trip")
    cli("replay", BALL, "--data", str(measured), "--law=flores", "--restitution=0.5",
        "--timestep=1e-4", "--quiet", "--output", str(tmp_path))
    result = contactlaws.replay(BALL, frame, law="flores", restitution=0.5, timestep=1e-4)
    assert_same_numbers(result.scores, tmp_path / "replay.csv")
    assert_same_numbers(result.trajectories, tmp_path / "trajectories.csv")
    # refused as the file would be, the table's row named (from 0)
    backwards = frame.copy()
    backwards.loc[1, "time"] = backwards.loc[0, "time"]
    with pytest.raises(contactlaws.Error, match=r"the DataFrame data row 1: column time: value "
                                                r".* does not increase within trajectory"):
        contactlaws.replay(BALL, backwards, law="flores", timestep=1e-4)
    with pytest.raises(ValueError, match="first columns must be trajectory, time"):
        contactlaws.replay(BALL, frame.drop(columns="trajectory"), timestep=1e-4)


def test_replay_keeps_numbered_trajectories_names_and_writes_no_file(tmp_path, monkeypatch,
                                                                    measured):
    # names that read as numbers (the cube tosses' 0, 1, ...) stay names: text
    numbered = pd.read_csv(measured, float_precision="round_trip")
    numbered["trajectory"] = numbered["trajectory"].map({"a": 7, "b": 8})
    numbered.to_csv(tmp_path / "numbered.csv", index=False)
    cli("replay", BALL, "--data", str(tmp_path / "numbered.csv"), "--law=flores",
        "--timestep=1e-4", "--quiet", "--output", str(tmp_path))

    # the results come back as the library's columns: no folder, no CSV read back
    def no_file(*args, **kwargs):
        raise AssertionError("replay went through a file")
    monkeypatch.setattr(tempfile, "TemporaryDirectory", no_file)
    monkeypatch.setattr(contactlaws.commands._pd, "read_csv", no_file)
    result = contactlaws.replay(BALL, numbered, law="flores", timestep=1e-4)
    monkeypatch.undo()
    assert list(result.scores["trajectory"]) == ["7", "8"]
    assert_same_numbers(result.scores, tmp_path / "replay.csv")
    assert_same_numbers(result.trajectories, tmp_path / "trajectories.csv")


def assert_same_ranking(frame, path):
    """wall_seconds is the one column that is not a result."""
    frame = frame.drop(columns="wall_seconds")
    types = {c: str if frame[c].dtype == object else frame[c].dtype for c in frame.columns}
    expected = pd.read_csv(path, float_precision="round_trip", keep_default_na=False,
                           na_values=[""], dtype=types).drop(columns="wall_seconds")
    pd.testing.assert_frame_equal(frame, expected, check_exact=True)


def test_fit_gives_the_command_lines_files(tmp_path, measured, monkeypatch):
    flags = ["--params=restitution=0.3:0.9", "--law=flores", "--timestep=1e-4", "--budget=6",
             "--folds=2", "--profile=all", "--profile-points=3"]
    cli("fit", BALL, "--data", str(measured), *flags, "--quiet", "--output", str(tmp_path))

    # the results come back as the library's columns: no folder, no CSV read back
    def no_file(*args, **kwargs):
        raise AssertionError("fit went through a file")
    monkeypatch.setattr(tempfile, "TemporaryDirectory", no_file)
    monkeypatch.setattr(contactlaws.commands._pd, "read_csv", no_file)
    result = contactlaws.fit(BALL, measured, "restitution=0.3:0.9", law="flores",
                             timestep=1e-4, budget=6, folds=2, profile="all", profile_points=3)
    monkeypatch.undo()
    assert_same_ranking(result.ranking, tmp_path / "ranking.csv")
    for name in ("errors", "best_trajectories", "folds", "profile"):
        assert_same_numbers(getattr(result, name), tmp_path / f"{name}.csv")
    assert result.best_tag == (tmp_path / "best_tag.txt").read_text()
    assert list(result.profile["key"].unique()) == ["restitution"]
    assert "\n  restitution: " in result.report  # the profile's line
    assert result.report.startswith("law/friction")


def test_fit_starts_where_it_is_told(tmp_path, measured):
    # a budget of one: the one evaluation is the start, 0.45 exactly
    flags = ["--params=restitution=0.3:0.9", "--law=flores", "--timestep=1e-4", "--budget=1"]
    cli("fit", BALL, "--data", str(measured), *flags, "--initial=restitution=0.45", "--quiet",
        "--output", str(tmp_path))
    result = contactlaws.fit(BALL, measured, "restitution=0.3:0.9", initial={"restitution": 0.45},
                             law="flores", timestep=1e-4, budget=1)
    assert_same_ranking(result.ranking, tmp_path / "ranking.csv")
    assert list(result.ranking["restitution"]) == [0.45]
    assert list(result.ranking["evaluations"]) == [1]
    # outside its bounds: the command line's message
    refused = cli("fit", BALL, "--data", str(measured), *flags, "--initial=restitution=0.95",
                  check=False)
    assert refused.returncode == 2
    with pytest.raises(contactlaws.Error) as error:
        contactlaws.fit(BALL, measured, "restitution=0.3:0.9", initial={"restitution": 0.95},
                        law="flores", timestep=1e-4, budget=1)
    assert str(error.value) == spoken(refused)
    assert str(error.value) == "initial: restitution=0.95: outside its bounds [0.3, 0.9]"


def test_laws_gives_the_command_lines_tables():
    printed = cli("laws").stdout
    tables = contactlaws.laws()
    # every law and friction model, in the printed order, with its formula
    for table in (tables.laws, tables.frictions):
        for row in table.itertuples():
            assert f"\n{row.name}\n  {row.formula}\n" in printed
    csv = cli("laws", "--format=csv", "--restitution=0.1:0.9:0.4").stdout
    mine = contactlaws.laws(restitution="0.1:0.9:0.4").restitution
    assert_same_numbers(mine, io.StringIO(csv))


def test_check_prints_the_command_lines_report():
    printed = cli("check", BALL, "--law=flores", "--restitution=0.4", "--timestep=1e-4").stdout
    report = contactlaws.check(BALL, law="flores", restitution=0.4, timestep=1e-4)
    # the options it advises named as the keywords
    assert report == _contactlaws._spelled(printed)
    assert 'or contact_steps="auto": 2 sub-steps' in report
    assert "need a smaller timestep (timestep)" in report
    assert "steps per contact" in printed


@pytest.mark.parametrize("call", [
    lambda: contactlaws.compare(BALL, restitutoin=0.5),
    lambda: contactlaws.restitution(BALL, restitutoin=0.5),
    lambda: contactlaws.replay(BALL, "d.csv", restitutoin=0.5),
    lambda: contactlaws.fit(BALL, "d.csv", "mu=0:1", restitutoin=0.5),
    lambda: contactlaws.laws(restitutoin=0.5),
    lambda: contactlaws.check(BALL, restitutoin=0.5),
])
def test_a_wrong_keyword_is_a_type_error_naming_it(call):
    with pytest.raises(TypeError, match="restitutoin"):
        call()


@pytest.mark.parametrize("args, call", [
    (["compare", BALL, "--laws=hartz"], lambda: contactlaws.compare(BALL, laws="hartz")),
    (["restitution", BALL, "--restitution=0.5,1.5"],
     lambda: contactlaws.restitution(BALL, restitution=[0.5, 1.5])),
    (["restitution", BALL, "--jobs=0"], lambda: contactlaws.restitution(BALL, jobs=0)),
    (["replay", BALL, "--data=/nonexistent.csv"],
     lambda: contactlaws.replay(BALL, "/nonexistent.csv")),
    (["laws", "--format=csv", "--restitution=2"], lambda: contactlaws.laws(restitution=2)),
    (["check", BALL, "--timestep=-1"], lambda: contactlaws.check(BALL, timestep=-1)),
    (["check", "no_such.xml"], lambda: contactlaws.check("no_such.xml")),
    (["compare", "no_such.xml"], lambda: contactlaws.compare("no_such.xml")),
])
def test_a_wrong_value_is_the_command_lines_message(args, call):
    refused = cli(*args, check=False)
    assert refused.returncode == 2
    with pytest.raises(contactlaws.Error) as error:
        call()
    # the command line prints "contactlaws: MESSAGE"
    assert str(error.value) == spoken(refused)


def test_a_wrong_measured_value_in_fit(measured):
    args = ["--params=restitution=0.5:2", "--law=flores", "--timestep=1e-4"]
    refused = cli("fit", BALL, "--data", str(measured), *args, check=False)
    assert refused.returncode == 2
    with pytest.raises(contactlaws.Error) as error:
        contactlaws.fit(BALL, measured, "restitution=0.5:2", law="flores", timestep=1e-4)
    assert str(error.value) == spoken(refused)


def test_ctrl_c_interrupts_a_long_fit_and_the_next_call_runs(measured):
    timer = threading.Timer(0.5, _thread.interrupt_main)
    start = time.perf_counter()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        # 100000 evaluations: hours, were it not stopped
        contactlaws.fit(BALL, measured, "restitution=0.3:0.9", law="flores", timestep=1e-5,
                        budget=100000)
    timer.join()
    # stopped after its current evaluation: one replay of two 0.8 s runs at
    # 1e-5 s takes ~0.3 s alone, allow 10 s on 2 loaded cores
    assert time.perf_counter() - start < 10
    assert len(contactlaws.restitution(BALL, laws="flores", restitution=0.5)) == 1


def test_ctrl_c_interrupts_a_long_replay(measured):
    timer = threading.Timer(0.5, _thread.interrupt_main)
    start = time.perf_counter()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        # two 0.8 s runs at 1e-7 s: minutes, were it not stopped
        contactlaws.replay(BALL, measured, law="flores", timestep=1e-7)
    timer.join()
    # stopped after the current step of each run: allow 10 s on 2 loaded cores
    assert time.perf_counter() - start < 10


def test_messages_name_the_keyword_arguments(capfd):
    # the warning the notebook printed in the command line's flags (--laws
    # all ... give --dissipation), on stderr as the command line prints it
    contactlaws.compare(BALL, restitution=0.5, duration=0.05)
    printed = capfd.readouterr().err
    assert ('laws="all" leaves out hunt-crossley-constant: it needs a dissipation '
            '(give dissipation, s/m)') in printed
    assert "--" not in printed
    with pytest.raises(contactlaws.Error) as error:
        contactlaws.run(BALL, max_timestep=-1, timestep="auto")
    assert str(error.value).startswith("max_timestep=-1 ")
    assert (_contactlaws._spelled("use --impacts-per-point or --settle; see contactlaws check")
            == "use impacts_per_point=True or settle=True; see contactlaws.check()")


def test_run_writes_a_numpy_archive_that_holds_the_csvs_doubles(tmp_path):
    """run --output FILE.npz: numpy.load gives the rows (float64) and the
    column names, each number the CSV's double (the CSV writes -0 as 0)."""
    import numpy as np
    args = ["run", BALL, "--duration", "0.5", "--friction", "coulomb"]
    cli(*args, "--output", str(tmp_path / "ball.csv"))
    cli(*args, "--output", str(tmp_path / "ball.npz"))
    archive = np.load(tmp_path / "ball.npz")
    assert sorted(archive.files) == ["columns", "rows"]
    assert archive["rows"].dtype == np.float64
    frame = pd.DataFrame(archive["rows"], columns=archive["columns"])
    expected = read(tmp_path / "ball.csv").astype(np.float64)  # a column of 0s reads as ints
    assert list(frame.columns) == list(expected.columns)
    assert len(frame) == 501
    pd.testing.assert_frame_equal(frame + 0.0, expected, check_exact=True)


def test_a_numpy_archive_of_many_bodies_loads_with_numpys_default_limits(tmp_path):
    """64 balls: 10 columns each, more names than a .npy header may hold
    (numpy.load refuses one beyond 10000 bytes); the archive loads as is, and
    a .npy is refused before the run, naming the .npz."""
    import numpy as np
    scene = os.path.join(os.environ["CONTACTLAWS_MJCF"], "ball_box_64.xml")
    cli("run", scene, "--duration", "1e-4", "--sample-rate", "1e5",
        "--output", str(tmp_path / "box.npz"))
    archive = np.load(tmp_path / "box.npz")
    names = list(archive["columns"])
    assert len(names) > 640 and names[0] == "time"
    assert sum(len(repr((n, "<f8"))) for n in names) > 10000  # a .npy's descr alone
    assert archive["rows"].shape == (11, len(names))
    refused = cli("run", scene, "--output", str(tmp_path / "box.npy"), check=False)
    assert refused.returncode != 0
    assert refused.stderr.count("\n") == 1 and "give FILE.npz" in refused.stderr
    assert not (tmp_path / "box.npy").exists()
