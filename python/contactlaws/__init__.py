"""contactlaws: continuous contact force laws in MuJoCo 2.2, from Python.

Results are pandas DataFrames whose columns are those of the command line's
CSV files (SI units: m, m/s, N, J, s); errors raise contactlaws.Error (a
ValueError) with the command line's message.
"""

import warnings as _warnings

import numpy as _np
import pandas as _pd

from ._contactlaws import Error, _parse_timestep, _run, _Simulation
from .commands import (CompareResult, FitResult, LawTables, ReplayResult, check, compare, fit,
                       laws, replay, restitution)

__all__ = ["Error", "Simulation", "RunResult", "run", "compare", "restitution", "replay", "fit",
           "laws", "check", "CompareResult", "ReplayResult", "FitResult", "LawTables"]


class RunResult:
    """What contactlaws run gives: .trajectory (the --output CSV: time in s,
    positions in m, velocities in m/s, forces in N, energies in J), .impacts
    (the --impacts CSV, one row per impact of a pair), .summary (the printed table,
    one row per tagged pair), .divergence (the message, or None)."""

    def __init__(self, trajectory, impacts, summary, divergence):
        self.trajectory = trajectory
        self.impacts = impacts
        self.summary = summary
        self.divergence = divergence


def _impact_frame(columns):
    """The library's impact table (app/impact_table.h) as a DataFrame."""
    return _pd.DataFrame(columns)


def run(scene, *, law=None, restitution=None, friction=None, mu=None, dissipation=None,
        duration=2, timestep=None, max_timestep=None, accuracy=None, integrator=None,
        sample_rate=1000, columns=None, settle=False, contact_steps=None):
    """Run a scene as `contactlaws run` does.

    scene: an MJCF file with contactlaw tags. law, restitution (e in [0, 1]),
    friction (model name), mu, dissipation (s/m): overrides of every tag.
    duration: s of simulated time. timestep: s, or "auto" (then accuracy, the
    relative error, and max_timestep, s). sample_rate: trajectory rows per
    simulated second. columns: "bodies,joints,pairs,friction,energy" or a part.
    settle: the bodies in contact at t = 0 moved into their static equilibrium.
    contact_steps: "auto" or a number of sub-steps: the contacts integrated
    inside each fixed step (docs/timestep.md, "Contact steps"); None: off.
    Returns a RunResult: .trajectory (time s, positions m, velocities m/s,
    forces N, energies J), .impacts, .summary; a diverged run keeps its rows
    up to the divergence, and warns.
    """
    options = dict(law=law, restitution=restitution, friction=friction, mu=mu,
                   dissipation=dissipation, duration=duration, timestep=timestep,
                   max_timestep=max_timestep, accuracy=accuracy, integrator=integrator,
                   sample_rate=sample_rate, columns=columns, settle=settle,
                   contact_steps=contact_steps)
    names, rows, impacts, summary, messages, divergence = _run(str(scene), options)
    for message in messages:
        _warnings.warn(f"{scene}: {message}", stacklevel=2)
    if divergence:
        _warnings.warn(f"{scene}: run stopped: diverged at {divergence}", stacklevel=2)
    trajectory = _pd.DataFrame(rows, columns=names, copy=False)
    # the printed table's header as printed: its "collisions" counts impacts
    summary_frame = _pd.DataFrame(summary, columns=[
        "pair", "law", "restitution", "collisions", "first e_post", "max force (N)"])
    return RunResult(trajectory, _impact_frame(impacts), summary_frame,
                     divergence or None)


class Simulation(_Simulation):
    """One tagged scene for a user's own loop.

    Simulation(scene, law=, restitution=, friction=, mu=, timestep=): the
    overrides as the command line's. step() one step; advance(t) to time t, s
    (Ctrl-C stops it at a step's end); reset(); time, timestep (s). qpos,
    qvel, ctrl, xfrc_applied: writable numpy views of MuJoCo's mjData; xpos,
    body_mass, geom_size: read-only views. body_names, joint_names, geom_names.
    """

    _KEYWORDS = ("law", "restitution", "friction", "mu", "timestep")

    def __init__(self, scene, **overrides):
        for key in overrides:
            if key not in self._KEYWORDS:
                raise TypeError(f"Simulation() got an unexpected keyword argument '{key}'")
        super().__init__(str(scene), overrides)
        self._timestep = self._initial_timestep

    @property
    def timestep(self):
        """The length of the following steps, s (> 0)."""
        return self._timestep

    @timestep.setter
    def timestep(self, value):
        self._timestep = _parse_timestep(value)

    def step(self):
        """One step of timestep s, the laws active (GIL released)."""
        self._step(self._timestep)

    def advance(self, t):
        """Steps of timestep s until the time reaches t, s (GIL released;
        Ctrl-C stops it at a step's end and raises KeyboardInterrupt)."""
        self._advance(t, self._timestep)

    def contacts(self):
        """The tagged contact points of the last step, one row each: pair,
        position x y z (m, world), normal x y z, depth (m), depth_rate (m/s),
        force (N, normal), friction x y z (N, world, on the pair's geom1)."""
        c = self._contacts()
        frame = _pd.DataFrame({"pair": c["pair"]})
        for name, axes in (("position", "xyz"), ("normal", "xyz")):
            for k, axis in enumerate(axes):
                frame[f"{name}_{axis}"] = c[name][:, k]
        for name in ("depth", "depth_rate", "force"):
            frame[name] = c[name]
        for k, axis in enumerate("xyz"):
            frame[f"friction_{axis}"] = c["friction"][:, k]
        return frame

    def impacts(self):
        """The impact log so far, as run's --impacts CSV (one row per impact of a pair)."""
        return _impact_frame(self._impacts())
