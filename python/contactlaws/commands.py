"""compare, restitution, replay, fit, laws and check, as the command line's
commands (the same options, the same checks and messages, the same numbers),
their results as DataFrames with the columns of the command's CSV files.

Each calls the library's application layer (src/app), the jobs the command
line calls, whose results come back as columns of numbers and names: no
file is written, nothing read back. Ctrl-C stops the runs after their
current step and raises KeyboardInterrupt.
"""

import sys as _sys
import warnings as _warnings

import numpy as _np
import pandas as _pd

from . import _contactlaws



def _text_list(value):
    """A list or tuple as the command line's comma-separated text."""
    if isinstance(value, (list, tuple)):
        return ",".join(str(v) for v in value)
    return value


def _numbers(value):
    """A list or tuple of numbers as it is (the library takes them as
    numbers); anything else as _text_list."""
    if isinstance(value, (list, tuple)) and all(
            isinstance(v, (int, float)) and not isinstance(v, bool) for v in value):
        return list(value)
    return _text_list(value)


def _assignments(value):
    """A mapping {KEY: VALUE} as the command line's KEY=VALUE,... text,
    each number in its shortest exact form (the same double read back); text
    or a list of KEY=VALUE as _text_list."""
    if isinstance(value, dict):
        return ",".join(f"{key}={v if isinstance(v, str) else repr(float(v))}"
                        for key, v in value.items())
    return _text_list(value)


class CompareResult:
    """compare's three files: .trajectories (law, restitution[, friction],
    then run's trajectory columns: s, m, m/s, N, J), .impacts (one row per
    impact of a pair, as run's --impacts), .summary (one row per run: impacts,
    restitution_post, max_depth m, max_force N, contact_duration s,
    time_to_rest s, dissipated_energy J, status, reason); .report, the
    printed table."""

    def __init__(self, trajectories, impacts, summary, report):
        self.trajectories = trajectories
        self.impacts = impacts
        self.summary = summary
        self.report = report


def compare(scene, *, laws="all", restitution=None, frictions=None, friction=None, mu=None,
            dissipation=None, duration=2, timestep=None, max_timestep=None, accuracy=None,
            integrator=None, sample_rate=1000, columns=None, settle=False, jobs=None,
            impacts_per_point=False, contact_steps=None):
    """Every law x restitution on a scene, as `contactlaws compare`.

    laws: "all", "L1,L2" or a list. restitution: e in [0, 1], "E1,E2",
    "start:stop:step" or a list (default: the scene's). frictions: friction
    models to compare, each with every law. friction, mu, dissipation (s/m):
    overrides of every tag. duration: s of simulated time; timestep: s or
    "auto" (accuracy: relative error; max_timestep: s); sample_rate: rows per
    simulated second; jobs: runs at a time (the results do not depend on it);
    contact_steps: "auto" or a number of sub-steps, the contacts integrated
    inside each fixed step (None: off).
    Returns a CompareResult; warns when a run failed (its summary row says why).
    """
    options = dict(laws=_text_list(laws), restitution=_numbers(restitution),
                   frictions=_text_list(frictions), friction=friction, mu=mu,
                   dissipation=dissipation, duration=duration, timestep=timestep,
                   max_timestep=max_timestep, accuracy=accuracy, integrator=integrator,
                   sample_rate=sample_rate, columns=columns, settle=settle, jobs=jobs,
                   impacts_per_point=impacts_per_point, contact_steps=contact_steps)
    result = _contactlaws._compare(str(scene), options)
    if result["failed"]:
        _warnings.warn(f"{scene}: a run failed: its summary row gives the reason", stacklevel=2)
    return CompareResult(*(_pd.DataFrame(result[name])
                           for name in ("trajectories", "impacts", "summary")),
                         result["report"])


def restitution(scene, *, laws="all", restitution="0.1:1.0:0.1", friction=None, mu=None,
                dissipation=None, duration=2, timestep=None, max_timestep=None, accuracy=None,
                integrator=None, settle=False, jobs=None, contact_steps=None):
    """The first impact of every law x restitution, as `contactlaws
    restitution` (the paper's Fig. 7).

    Returns its CSV: law, restitution, restitution_post (the first rebound's
    e), impact_velocity (m/s), max_depth (m), max_force (N), contact_duration
    (s); empty where a run has no such value. The options as compare's;
    warns when a first contact did not end within duration.
    """
    options = dict(laws=_text_list(laws), restitution=_numbers(restitution),
                   friction=friction, mu=mu, dissipation=dissipation, duration=duration,
                   timestep=timestep, max_timestep=max_timestep, accuracy=accuracy,
                   integrator=integrator, settle=settle, jobs=jobs, contact_steps=contact_steps)
    result = _contactlaws._restitution(str(scene), options)
    if result["incomplete"]:
        _warnings.warn(f"{scene}: a first contact did not end within the duration",
                       stacklevel=2)
    return _pd.DataFrame(result["table"])


def _data(data):
    """A path as text, or a DataFrame in the measured format (docs/identification.md:
    trajectory, time, then <body>.<quantity> columns, a row per sample) as its columns,
    numbers as float64 arrays: read and checked by the library as a file is, no file written."""
    if not isinstance(data, _pd.DataFrame):
        return str(data)
    names = [str(c) for c in data.columns]
    if names[:2] != ["trajectory", "time"]:
        raise ValueError(f"data: a DataFrame's first columns must be trajectory, time, then "
                         f"<body>.<quantity> columns, not {', '.join(names[:3])}")

    def numbers(column):
        try:
            return data[column].to_numpy(dtype="float64")
        except (TypeError, ValueError) as e:
            raise ValueError(f"data: column {column}: not numbers ({e})") from None

    return {"source": "the DataFrame data", "trajectory": [str(t) for t in data["trajectory"]],
            "time": numbers("time"), "columns": names[2:],
            "values": [numbers(c) for c in data.columns[2:]]}


def _replay_options(data, start, refit_height, refit_lead, refit_min_samples, metric, weights,
                    length, timestep, max_timestep, accuracy, integrator, law, restitution,
                    dissipation, friction, mu, set, jobs):
    return dict(data=_data(data), start=start, refit_height=refit_height, refit_lead=refit_lead,
                refit_min_samples=refit_min_samples, metric=metric, weights=_text_list(weights),
                length=length, timestep=timestep, max_timestep=max_timestep, accuracy=accuracy,
                integrator=integrator, law=law, restitution=restitution,
                dissipation=dissipation, friction=friction, mu=mu,
                set=[set] if isinstance(set, str) else set, jobs=jobs)


class ReplayResult:
    """replay's results: .scores (one row per trajectory, as replay.csv:
    trajectory (its name, text), samples, start, e_q, position_rms m,
    angle_rms rad, joint_rms, weighted, status), .trajectories (the simulated
    samples in the data's own columns and units, as trajectories.csv);
    .report, the printed distributions."""

    def __init__(self, scores, trajectories, report):
        self.scores = scores
        self.trajectories = trajectories
        self.report = report


def _simulated_frame(simulated):
    """The library's simulated samples (python/jobs.cc's
    SimulatedColumns) as trajectories.csv's table."""
    names = _np.asarray(simulated["names"], dtype=object)
    frame = _pd.DataFrame(simulated["values"], columns=simulated["columns"])
    frame.insert(0, "time", simulated["time"])
    frame.insert(0, "trajectory", names[simulated["trajectory"]])
    return frame


def _replay_result(scene, result):
    """ReplayResult of the library's columns (python/jobs.cc)."""
    scores = _pd.DataFrame(result["scores"])
    trajectories = _simulated_frame(result["simulated"])
    if result["diverged"]:
        _warnings.warn(f"{scene}: {result['diverged']}", stacklevel=3)
    if result["settled"]:
        print(f"contactlaws: {scene}: {result['settled']}", file=_sys.stderr)
    return ReplayResult(scores, trajectories, result["report"])


def replay(scene, data, *, start="first", refit_height=None, refit_lead=3, refit_min_samples=4,
           metric="e_q", weights=None, length=None, timestep=None, max_timestep=None,
           accuracy=None, integrator=None, law=None, restitution=None, dissipation=None,
           friction=None, mu=None, set=None, jobs=None):
    """Measured trajectories simulated from their start and scored, as
    `contactlaws replay` (docs/identification.md).

    data: the measured CSV's path, or a DataFrame of the same columns
    (trajectory, time s, positions m, quaternions, velocities m/s, rad/s),
    checked as the file would be and never written. start: "first" or
    "refit" (refit_height m, refit_lead and refit_min_samples samples).
    metric: "e_q", "position_rms" (m), "angle_rms" (rad) or "weighted"
    (weights "P,A[,J]"); length: e_q's L, m. timestep: s or "auto"; law,
    restitution, dissipation (s/m), friction, mu: overrides of every tag;
    set: "KEY=VALUE" or a list of them, on every tag.
    Returns a ReplayResult, computed in memory: no file written. Ctrl-C
    stops the runs after their current step and raises KeyboardInterrupt.
    """
    options = _replay_options(data, start, refit_height, refit_lead, refit_min_samples, metric,
                              weights, length, timestep, max_timestep, accuracy, integrator,
                              law, restitution, dissipation, friction, mu, set, jobs)
    return _replay_result(scene, _contactlaws._replay(str(scene), options))


class FitResult:
    """fit's results, as its files: .ranking (one row per law/friction
    combination, best first: the fitted parameters, train_, validate_ and
    cv_ summaries of the metric with their intervals, evaluations,
    wall_seconds, status), .errors (each trajectory's scores at the fitted
    values), .best_trajectories (the best combination's simulated samples),
    .best_tag (the scene's tag line with the fitted values), .folds (each
    training trajectory's fold, with folds=), .profile (the winner's
    profile, with profile=); .report, the printed ranking."""

    def __init__(self, ranking, errors, best_trajectories, best_tag, report, folds=None,
                 profile=None):
        self.ranking = ranking
        self.errors = errors
        self.best_trajectories = best_trajectories
        self.best_tag = best_tag
        self.report = report
        self.folds = folds
        self.profile = profile


def fit(scene, data, params, *, initial=None, laws=None, frictions=None, validate=None,
        budget=200, folds=None, trim=None, profile=None, profile_points=None,
        profile_budget=None, seed=1, start="first", refit_height=None, refit_lead=3,
        refit_min_samples=4, metric="e_q", weights=None, length=None, timestep=None,
        max_timestep=None, accuracy=None, integrator=None, law=None, restitution=None,
        dissipation=None, friction=None, mu=None, set=None, jobs=None):
    """Tag and model parameters identified from measured trajectories, as
    `contactlaws fit` (docs/identification.md).

    params: "KEY=LO:HI[:log],..." or a list of them (tag keys in their units,
    BODY.mass_scale, GEOM.offset m, mujoco.*). laws, frictions: the
    combinations to fit ("all", names, or lists). validate: trajectories not
    fitted on (a path or a DataFrame, as data). budget: evaluations per
    combination; seed: the search's seed.
    folds: K-fold cross-validation over the trajectories, the ranking by the
    held-out score (ranking's cv_* columns). trim: in [0, 0.5), the share of
    the worst trajectories each score leaves out (a trimmed mean).
    initial: where the search starts, {KEY: VALUE} (or "KEY=VALUE,...") of
    params' keys in their units, the others at their range's middle; every
    combination starts there, and its first evaluation is that point.
    profile: "all", a key of params or a list of them: the winner's profile
    along each (profile_points per parameter, the others re-fitted over
    profile_budget evaluations at each; FitResult.profile).
    The other options as replay's. Returns a FitResult, computed in memory:
    no file written. Ctrl-C stops the search after its current evaluation
    and raises KeyboardInterrupt.
    """
    options = _replay_options(data, start, refit_height, refit_lead, refit_min_samples, metric,
                              weights, length, timestep, max_timestep, accuracy, integrator,
                              law, restitution, dissipation, friction, mu, set, jobs)
    options.update(params=_text_list(params), initial=_assignments(initial),
                   laws=_text_list(laws), frictions=_text_list(frictions),
                   validate=None if validate is None else _data(validate), budget=budget,
                   folds=folds, trim=trim, profile=_text_list(profile),
                   profile_points=profile_points, profile_budget=profile_budget, seed=seed)
    result = _contactlaws._fit(str(scene), options)

    def frame(name):
        return None if result[name] is None else _pd.DataFrame(result[name])

    return FitResult(frame("ranking"), frame("errors"),
                     _simulated_frame(result["best_trajectories"]), result["best_tag"],
                     result["report"], frame("folds"), frame("profile"))


class LawTables:
    """The laws and friction models: .laws (name, formula, parameters,
    reference), .frictions (name, formula, state, parameters, reference),
    .restitution (`laws --format csv`: law, family, restitution,
    hysteresis_coefficient a(e), dimensionless, effective_restitution)."""

    def __init__(self, laws, frictions, restitution):
        self.laws = laws
        self.frictions = frictions
        self.restitution = restitution


def laws(*, restitution=None):
    """The law and friction tables, as `contactlaws laws`, and each law's
    a(e) and rebound per restitution, as `contactlaws laws --format csv`.

    restitution: "E1,E2", "start:stop:step" or a list (default
    0.9,0.7,0.5,0.3,0.1). Returns LawTables.
    """
    tables = _contactlaws._laws(dict(restitution=_numbers(restitution)))
    return LawTables(*(_pd.DataFrame(tables[name])
                       for name in ("laws", "frictions", "effective")))


def check(scene, *, law=None, restitution=None, dissipation=None, friction=None, mu=None,
          timestep=None, accuracy=None, impact_velocity=None):
    """The scene's tags resolved, their contact estimates and the timestep
    they need, as `contactlaws check`: its report, word for word, the
    options it names spelled as the keyword arguments (str).

    law, restitution, dissipation (s/m), friction, mu: overrides of every
    tag; timestep: s or "auto" (accuracy: relative error); impact_velocity:
    m/s, instead of the estimate.
    """
    options = dict(law=law, restitution=restitution, dissipation=dissipation,
                   friction=friction, mu=mu, timestep=timestep, accuracy=accuracy,
                   impact_velocity=impact_velocity)
    return _contactlaws._check(str(scene), options)
