"""contactlaws from Python against the command line on the same scenes."""

import _thread
import os
import subprocess
import threading
import time

import numpy as np
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


@pytest.mark.parametrize("scene, options", [
    (BALL, {"law": "hunt-crossley", "restitution": 0.7, "duration": 1}),
    (INCLINE, {"friction": "coulomb", "mu": 0.3, "duration": 0.5}),
    # the contacts inside MuJoCo's own 2 ms step, as check advises them
    (BALL, {"law": "flores", "restitution": 0.9, "duration": 1, "timestep": 2e-3,
            "integrator": "euler", "contact_steps": "auto"}),
])
def test_run_gives_the_command_lines_files(tmp_path, scene, options):
    out, impacts = tmp_path / "t.csv", tmp_path / "i.csv"
    flags = [f"--{k.replace('_', '-')}={v}" for k, v in options.items()]
    printed = cli("run", scene, *flags, "--output", str(out), "--impacts", str(impacts)).stdout
    result = contactlaws.run(scene, **options)
    # the CSV's numbers are in their shortest exact form: equal doubles (read
    # exactly; a column of whole numbers reads as integers)
    def read(path):
        return pd.read_csv(path, float_precision="round_trip")
    pd.testing.assert_frame_equal(result.trajectory, read(out), check_exact=True,
                                  check_dtype=False)
    pd.testing.assert_frame_equal(result.impacts, read(impacts), check_exact=True,
                                  check_dtype=False)
    # the printed table: one line per pair, its impacts (header "collisions") and max force
    for row, line in zip(result.summary.itertuples(), printed.splitlines()[1:]):
        fields = line.split()
        assert fields[0] == row.pair and fields[1] == row.law
        assert int(fields[3]) == row.collisions
        # printed with {:.6g}: to half a unit of its sixth digit
        assert float(fields[5]) == pytest.approx(row[6], rel=5e-6)


def test_a_block_starting_deep_warns_as_the_command_line_does_in_keywords(tmp_path):
    # a 0.2 kg cube 0.1 mm into its floor: 40 N against its 1.962 N weight
    scene = tmp_path / "deep.xml"
    scene.write_text("""<mujoco><worldbody><geom name="floor" type="plane" size="2 2 0.1"/>
      <body name="block" pos="0 0 0.0299"><freejoint/>
        <geom name="block" type="box" size="0.03 0.03 0.03" mass="0.2"/></body></worldbody>
      <custom><text name="contactlaw:block-floor" data="geom1=block geom2=floor
        law=zhiying-qishao restitution=0.3 stiffness=1e7"/></custom></mujoco>""")
    printed = cli("run", str(scene), "--duration", "0.001", "--timestep", "auto").stderr
    with pytest.warns(UserWarning) as caught:
        contactlaws.run(scene, duration=0.001, timestep="auto")
    deep = [str(w.message) for w in caught if "deep in contact" in str(w.message)]
    assert len(deep) == 1 and deep[0].split(": ", 1)[1] in _contactlaws._spelled(printed)
    assert "settle=True moves the bodies" in deep[0]
    assert "starts 0.0001 m deep in contact: its law pushes with 40 N" in deep[0]


def test_a_settled_ball_that_rolls_away_is_named(tmp_path):
    # a ball on a 10 degree ramp its friction holds: it rolls, so it has no
    # resting pose; settled into its contact's depth, it starts rolling
    scene = tmp_path / "ramp.xml"
    scene.write_text("""<mujoco><option timestep="1e-4" integrator="RK4"/><worldbody>
      <geom name="ramp" type="plane" size="2 1 0.1" euler="0 10 0"/>
      <body name="roller" pos="0 0 0.0505"><freejoint/>
        <geom name="roller" type="sphere" size="0.05" mass="1"/></body></worldbody>
      <custom><text name="contactlaw:roll" data="geom1=ramp geom2=roller law=hunt-crossley
        restitution=0.5 stiffness=1e7 friction=coulomb mu=0.6"/></custom></mujoco>""")
    with pytest.warns(UserWarning) as caught:
        result = contactlaws.run(scene, duration=0.5, timestep="auto", settle=True)
    assert any("'roller' has no resting pose" in str(w.message) for w in caught)
    # 5/7 g sin 10 degrees down the ramp (its x part), as the command line's
    # settle_test: the lever R - d/2 makes it 0.06% slow
    rolling = 5 / 7 * 9.81 * np.sin(np.radians(10)) * np.cos(np.radians(10))
    assert result.trajectory["roller.vx"].iloc[-1] == pytest.approx(rolling * 0.5, rel=5e-3)


def test_refused_values_raise_the_command_lines_message():
    refused = cli("run", BALL, "--restitution=1.5", check=False)
    assert refused.returncode == 2
    with pytest.raises(contactlaws.Error) as error:
        contactlaws.run(BALL, restitution=1.5)
    assert str(error.value) == spoken(refused)
    assert isinstance(error.value, ValueError)
    with pytest.raises(contactlaws.Error, match="no_such.xml"):
        contactlaws.Simulation("no_such.xml")
    with pytest.raises(contactlaws.Error, match="^law=nope"):
        contactlaws.Simulation(BALL, law="nope")


def test_a_wrong_keyword_is_a_type_error_naming_it():
    with pytest.raises(TypeError, match="restitutoin"):
        contactlaws.run(BALL, restitutoin=0.5)
    with pytest.raises(TypeError, match="restitutoin"):
        contactlaws.Simulation(BALL, restitutoin=0.5)


def test_writing_qpos_moves_the_body():
    sim = contactlaws.Simulation(BALL)
    ball = sim.body_names.index("ball")
    sim.qpos[2] = 3.0  # the free joint's z, m
    sim.step()
    assert sim.xpos[ball, 2] == pytest.approx(3.0, abs=1e-6)  # one step of a fall from rest
    # the views are MuJoCo's memory: the state survives a new view
    assert sim.qpos[2] == pytest.approx(3.0, abs=1e-6)
    with pytest.raises(ValueError, match="read-only"):
        sim.body_mass[ball] = 2.0
    with pytest.raises(ValueError, match="read-only"):
        sim.xpos[ball, 2] = 0.0


def test_a_simulation_bounces_as_run_does():
    sim = contactlaws.Simulation(BALL, restitution=0.5)
    sim.advance(1.0)
    first = contactlaws.run(BALL, restitution=0.5, duration=1).impacts
    pd.testing.assert_frame_equal(sim.impacts(), first)
    # energy: dissipated by the one bounce, the total kept to RK4's error
    energy = sim.energy()
    assert energy["dissipated"] > 0
    # m g h of the 1 kg ball at 1 m, to the ledger's error over one bounce
    # (measured 1.6e-5 relative)
    assert energy["total"] == pytest.approx(9.81, rel=1e-4)
    sim.reset()
    assert sim.time == 0 and sim.impacts().empty


def test_contacts_are_the_points_in_contact():
    sim = contactlaws.Simulation(BALL)
    sim.advance(0.42)  # the ball touches at 0.428 s (the impact log)
    while sim.contacts().empty:
        sim.step()
    points = sim.contacts()
    assert list(points["pair"]) == ["ball-floor"]
    assert points["depth"][0] > 0 and points["force"][0] > 0
    assert points["normal_z"][0] == pytest.approx(1.0, abs=1e-9)


def test_stepping_releases_the_gil_and_two_simulations_run_in_parallel():
    sims = [contactlaws.Simulation(BALL) for _ in range(2)]
    spans = []
    inside = threading.Event()

    def advance(sim):
        inside.set()
        start = time.perf_counter()
        sim.advance(0.2)
        spans.append((start, time.perf_counter()))

    threads = [threading.Thread(target=advance, args=(s,)) for s in sims]
    for t in threads:
        t.start()
    inside.wait()
    spins = 0
    while any(t.is_alive() for t in threads):
        spins += 1  # Python running while both threads step
    for t in threads:
        t.join()
    assert spins > 1000
    # both stepped at once (their spans overlap), and both as one alone does
    assert max(s for s, _ in spans) < min(e for _, e in spans)
    alone = contactlaws.Simulation(BALL)
    alone.advance(0.2)
    for sim in sims:
        np.testing.assert_array_equal(sim.qpos, alone.qpos)


def test_ctrl_c_interrupts_a_run_and_the_next_runs():
    timer = threading.Timer(0.2, _thread.interrupt_main)
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        contactlaws.run(BALL, duration=1000, timestep=1e-5)
    timer.join()
    assert len(contactlaws.run(BALL, duration=0.01).trajectory) == 11


def test_the_timestep_set_is_the_length_of_the_following_steps():
    sim = contactlaws.Simulation(BALL, timestep=1e-3)
    assert sim.timestep == 1e-3
    sim.step()
    sim.timestep = 2.5e-4
    sim.step()
    assert sim.time == pytest.approx(1.25e-3, abs=1e-15)  # 1e-3 + 2.5e-4, s
    sim.advance(2e-3)  # three more steps of 2.5e-4 s
    assert sim.time == pytest.approx(2e-3, abs=1e-15)
    # a second simulation of the scene keeps the scene's own timestep
    assert contactlaws.Simulation(BALL).timestep == 1e-5
    refused = cli("run", BALL, "--timestep=-1", check=False)
    with pytest.raises(contactlaws.Error) as error:
        sim.timestep = -1
    assert str(error.value) == spoken(refused)
    assert sim.timestep == 2.5e-4
