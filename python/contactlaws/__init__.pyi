# Type stubs of the package contactlaws (python/contactlaws/__init__.py and
# commands.py): what editors complete. Units: s, m, m/s, N, J, s/m.
from os import PathLike
from typing import Dict, List, Literal, Optional, Sequence, Union

import numpy as np
import pandas as pd

from ._contactlaws import Error as Error
from ._contactlaws import _Simulation
from .commands import CompareResult as CompareResult
from .commands import FitResult as FitResult
from .commands import LawTables as LawTables
from .commands import ReplayResult as ReplayResult
from .commands import check as check
from .commands import compare as compare
from .commands import fit as fit
from .commands import laws as laws
from .commands import replay as replay
from .commands import restitution as restitution

Scene = Union[str, PathLike]
Number = Union[float, int, str]

class RunResult:
    trajectory: pd.DataFrame  # the --output CSV: time s, positions m, velocities m/s, N, J
    impacts: pd.DataFrame  # the --impacts CSV, one row per impact of a pair
    summary: pd.DataFrame  # the printed table, one row per tagged pair
    divergence: Optional[str]  # the message, or None

def run(scene: Scene, *, law: Optional[str] = ..., restitution: Optional[Number] = ...,
        friction: Optional[str] = ..., mu: Optional[Number] = ...,
        dissipation: Optional[Number] = ..., duration: Number = ...,
        timestep: Union[Number, Literal["auto"], None] = ..., max_timestep: Optional[Number] = ...,
        accuracy: Optional[Number] = ..., integrator: Optional[str] = ...,
        sample_rate: Number = ..., columns: Optional[str] = ..., settle: bool = ...,
        contact_steps: Union[int, Literal["auto"], None] = ...) -> RunResult: ...

class Simulation(_Simulation):
    def __init__(self, scene: Scene, *, law: Optional[str] = ...,
                 restitution: Optional[Number] = ..., friction: Optional[str] = ...,
                 mu: Optional[Number] = ..., timestep: Optional[Number] = ...) -> None: ...
    @property
    def timestep(self) -> float: ...  # s
    @timestep.setter
    def timestep(self, value: Number) -> None: ...
    def step(self) -> None: ...
    def advance(self, t: float) -> None: ...  # to time t, s
    def contacts(self) -> pd.DataFrame: ...
    def impacts(self) -> pd.DataFrame: ...
