"""cablenav — exact feasibility of cable-driven parallel robot motions, from Python.

Every function takes a scenario as a dict, a JSON string or a path to a
``cablenav-scenario/1`` file (docs/scenario-format.md) and returns plain dicts and
lists: exactly what ``cablenav COMMAND SCENARIO … --json`` prints, parsed.

>>> import cablenav
>>> report = cablenav.verify("static/scenarios/cdpr7.json", "linear")
>>> report["feasible"]
[[0.0, 1.0]]

Errors of the scenario or of an argument raise :class:`ScenarioError`, whose ``field``
is the JSON path (``robot.cables[3].base``) or the argument (``range``). Calls release
the GIL, so threads run them in parallel; :mod:`cablenav.sweep` sweeps candidate
designs with ``concurrent.futures`` or on a Dask cluster.

``lattice`` computes the thesis' ray lattice; ``plan(..., planner="lattice", steps=7)``
plans on it (any robot), ``plan(...)`` with the atlas (6 cables with a wrench set).
"""

from ._cablenav import ScenarioError, __version__, check, check_at, envelope, import_caspr, lattice, plan, ray, slice, time, verify

__all__ = ["ScenarioError", "__version__", "check", "check_at", "envelope", "import_caspr", "lattice", "plan", "ray", "slice", "time", "verify"]
