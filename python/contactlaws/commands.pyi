# Type stubs of contactlaws.commands: compare, restitution, replay, fit, laws
# and check. Units: s, m, m/s, N, J, s/m.
from os import PathLike
from typing import List, Literal, Mapping, Optional, Sequence, Union

import pandas as pd

Scene = Union[str, PathLike]
# measured trajectories: a CSV's path, or a DataFrame of its columns
Data = Union[str, PathLike, pd.DataFrame]
Number = Union[float, int, str]
Names = Union[str, Sequence[str]]
Restitutions = Union[Number, Sequence[float], None]

class CompareResult:
    trajectories: pd.DataFrame
    impacts: pd.DataFrame
    summary: pd.DataFrame
    report: str

class ReplayResult:
    scores: pd.DataFrame
    trajectories: pd.DataFrame
    report: str

class FitResult:
    ranking: pd.DataFrame
    errors: pd.DataFrame
    best_trajectories: pd.DataFrame
    best_tag: str
    report: str
    folds: Optional[pd.DataFrame]
    profile: Optional[pd.DataFrame]

class LawTables:
    laws: pd.DataFrame
    frictions: pd.DataFrame
    restitution: pd.DataFrame

def compare(scene: Scene, *, laws: Names = ..., restitution: Restitutions = ...,
            frictions: Optional[Names] = ..., friction: Optional[str] = ...,
            mu: Optional[Number] = ..., dissipation: Optional[Number] = ...,
            duration: Number = ..., timestep: Union[Number, Literal["auto"], None] = ...,
            max_timestep: Optional[Number] = ..., accuracy: Optional[Number] = ...,
            integrator: Optional[str] = ..., sample_rate: Number = ...,
            columns: Optional[str] = ..., settle: bool = ..., jobs: Optional[int] = ...,
            impacts_per_point: bool = ...,
            contact_steps: Union[int, Literal["auto"], None] = ...) -> CompareResult: ...

def restitution(scene: Scene, *, laws: Names = ..., restitution: Restitutions = ...,
                friction: Optional[str] = ..., mu: Optional[Number] = ...,
                dissipation: Optional[Number] = ..., duration: Number = ...,
                timestep: Union[Number, Literal["auto"], None] = ...,
                max_timestep: Optional[Number] = ..., accuracy: Optional[Number] = ...,
                integrator: Optional[str] = ..., settle: bool = ...,
                jobs: Optional[int] = ...,
                contact_steps: Union[int, Literal["auto"], None] = ...) -> pd.DataFrame: ...

def replay(scene: Scene, data: Data, *, start: Literal["first", "refit"] = ...,
           refit_height: Optional[Number] = ..., refit_lead: int = ...,
           refit_min_samples: int = ..., metric: str = ..., weights: Optional[Names] = ...,
           length: Optional[Number] = ..., timestep: Union[Number, Literal["auto"], None] = ...,
           max_timestep: Optional[Number] = ..., accuracy: Optional[Number] = ...,
           integrator: Optional[str] = ..., law: Optional[str] = ...,
           restitution: Optional[Number] = ..., dissipation: Optional[Number] = ...,
           friction: Optional[str] = ..., mu: Optional[Number] = ...,
           set: Optional[Names] = ..., jobs: Optional[int] = ...) -> ReplayResult: ...

def fit(scene: Scene, data: Data, params: Names, *,
        initial: Union[Mapping[str, Number], Names, None] = ..., laws: Optional[Names] = ...,
        frictions: Optional[Names] = ..., validate: Optional[Data] = ..., budget: int = ...,
        folds: Optional[int] = ..., trim: Optional[Number] = ...,
        profile: Optional[Names] = ..., profile_points: Optional[int] = ...,
        profile_budget: Optional[int] = ..., seed: int = ...,
        start: Literal["first", "refit"] = ...,
        refit_height: Optional[Number] = ..., refit_lead: int = ...,
        refit_min_samples: int = ..., metric: str = ..., weights: Optional[Names] = ...,
        length: Optional[Number] = ..., timestep: Union[Number, Literal["auto"], None] = ...,
        max_timestep: Optional[Number] = ..., accuracy: Optional[Number] = ...,
        integrator: Optional[str] = ..., law: Optional[str] = ...,
        restitution: Optional[Number] = ..., dissipation: Optional[Number] = ...,
        friction: Optional[str] = ..., mu: Optional[Number] = ...,
        set: Optional[Names] = ..., jobs: Optional[int] = ...) -> FitResult: ...

def laws(*, restitution: Restitutions = ...) -> LawTables: ...

def check(scene: Scene, *, law: Optional[str] = ..., restitution: Optional[Number] = ...,
          dissipation: Optional[Number] = ..., friction: Optional[str] = ...,
          mu: Optional[Number] = ..., timestep: Union[Number, Literal["auto"], None] = ...,
          accuracy: Optional[Number] = ..., impact_velocity: Optional[Number] = ...) -> str: ...
