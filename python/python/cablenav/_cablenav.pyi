"""Type stubs of the native module (python/src/lib.rs); see the docstrings there."""

import os
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

Scenario = Union[Dict[str, Any], str, "os.PathLike[str]"]
"""A scenario: a dict, a JSON string (starting with ``{``) or a path to a JSON file."""

Report = Dict[str, Any]
"""A report: exactly the JSON that ``cablenav COMMAND … --json`` prints, parsed."""

__version__: str

class ScenarioError(ValueError):
    """A scenario or an argument the core rejects."""

    field: str
    """Where: a JSON path into the scenario (``robot.cables[3].base``) or an argument (``range``)."""
    reason: str
    """Why."""
    path: Optional[str]
    """The scenario file, when the scenario was given as a path."""

def verify(scenario: Scenario, trajectory: Optional[str] = None, *, pointwise: Optional[float] = None) -> Report:
    """Feasible/infeasible t-sections of a trajectory, exact (``pointwise``: sampled every Δt)."""

def check(scenario: Scenario, pose: str) -> Report:
    """Lengths, clearances, violated conditions and wrench tension ranges at one pose."""

def check_at(scenario: Scenario, t: float, trajectory: Optional[str] = None) -> Report:
    """``check`` where a trajectory is at ``t`` ∈ [0, 1], moving as it moves there if it is timed."""

def import_caspr(model_dir: Union[str, "os.PathLike[str]"], *, trajectories: Union[str, "os.PathLike[str]", None] = None, name: Optional[str] = None, cable_set: Optional[str] = None) -> Dict[str, Any]:
    """A CASPR model directory (bodies, cables and, if there, trajectories XML) as
    ``{"scenario": dict, "notes": [str]}``, as ``cablenav import`` converts it; ``cable_set``
    picks a cable set by its id (as ``--cable-set``; the file's default without it)."""

def ray(scenario: Scenario, pose: str, vary: str, range: Tuple[float, float]) -> Report:
    """Exact feasible intervals of one coordinate (x, y, z, phi, theta, sigma, or a multi-link
    robot's joint coordinate by name, ``pose`` naming a configuration) over ``range``."""

def envelope(scenario: Scenario, trajectory: Optional[str] = None, *, samples: Optional[int] = None) -> Report:
    """Each cable's least and greatest tension over the wrench set along a trajectory."""

def time(scenario: Scenario, trajectory: Optional[str] = None, *, cells: Optional[int] = None, margin: Optional[float] = None) -> Report:
    """The fastest rest-to-rest timing of a trajectory, certified along it (``cablenav time``):
    ``duration``, ``uncertified_duration``, the ``binding`` constraint stretch by stretch, the
    ``profile`` (t, time, rate, speed, tensions) at every grid point."""

def slice(
    scenario: Scenario,
    pose: str,
    axes: Tuple[str, str],
    res: int,
    range: Optional[Tuple[Tuple[float, float], Tuple[float, float]]] = None,
) -> Report:
    """A res × res classified grid over two coordinates and its feasible components."""

def lattice(
    scenario: Scenario,
    pose: str,
    axes: Sequence[str],
    ranges: Sequence[Tuple[float, float]],
    steps: Union[int, Sequence[int]],
) -> Report:
    """The ray lattice over ``axes`` (others from ``pose``): rays' feasible intervals, pieces, components."""

def plan(
    scenario: Scenario,
    query: Union[str, List[str]],
    *,
    planner: str = "atlas",
    steps: Optional[int] = None,
    max_charts: Optional[int] = None,
    radius: Optional[float] = None,
    min_radius: Optional[float] = None,
    heuristic_weight: Optional[float] = None,
    epsilon: Optional[float] = None,
    identify_angles: Optional[bool] = None,
    atlas: Optional[Union[str, "os.PathLike[str]"]] = None,
) -> Union[Report, List[Report]]:
    """A feasible path for a query (a list of queries: one report each, in order, later ones on
    the atlas of earlier ones on the same slice): ``planner`` "atlas" (Henderson atlas + A*, with
    ``max_charts``, ``radius``, ``min_radius``, ``heuristic_weight``, ``epsilon``,
    ``identify_angles`` — False: paper 1's plain coordinates — and ``atlas``, a file to start
    from and save the atlas to) or "lattice" (ray lattice with ``steps`` grid values per free
    coordinate + A* + Bézier), re-verified exactly."""
