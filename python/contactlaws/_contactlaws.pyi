# Type stubs of the extension module contactlaws._contactlaws (pybind11).
from typing import Dict, List

import numpy as np

def _spelled(message: str) -> str: ...

class Error(ValueError):
    """The command line's message for refused input."""

class _Simulation:
    def __init__(self, scene: str, overrides: dict) -> None: ...
    def reset(self) -> None: ...
    @property
    def time(self) -> float: ...  # s
    @property
    def qpos(self) -> np.ndarray: ...  # writable view of mjData.qpos
    @property
    def qvel(self) -> np.ndarray: ...  # writable view of mjData.qvel
    @property
    def ctrl(self) -> np.ndarray: ...  # writable view of mjData.ctrl
    @property
    def xfrc_applied(self) -> np.ndarray: ...  # writable (nbody, 6): N, N m
    @property
    def xpos(self) -> np.ndarray: ...  # read-only (nbody, 3): m
    @property
    def body_mass(self) -> np.ndarray: ...  # read-only: kg
    @property
    def geom_size(self) -> np.ndarray: ...  # read-only (ngeom, 3): m
    @property
    def body_names(self) -> List[str]: ...
    @property
    def joint_names(self) -> List[str]: ...
    @property
    def geom_names(self) -> List[str]: ...
    def energy(self) -> Dict[str, float]: ...  # J: kinetic, potential, elastic, dissipated, total
