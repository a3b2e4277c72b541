"""The Python package against the CLI's JSON, its errors, the GIL, stubs and docstrings."""

import ast
import inspect
import json
import os
import subprocess
import threading
from pathlib import Path

import pytest

import cablenav
from conftest import PRESETS, ROOT


def load(path):
    with open(path) as f:
        return json.load(f)


@pytest.mark.parametrize("path", PRESETS, ids=lambda p: p.name)
def test_verify_equals_the_cli_on_every_preset(cli, path):
    scenario = load(path)
    for trajectory in [t["name"] for t in scenario["trajectories"]]:
        expected = cli("verify", path, "--trajectory", trajectory)
        # The same dict from a path, a pathlib.Path, a dict and a JSON string.
        assert cablenav.verify(str(path), trajectory) == expected
        assert cablenav.verify(path, trajectory) == expected
        assert cablenav.verify(scenario, trajectory) == expected
        assert cablenav.verify(path.read_text(), trajectory) == expected
    assert cablenav.verify(path) == cli("verify", path)
    assert cablenav.verify(path, pointwise=0.01) == cli("verify", path, "--pointwise", "0.01")


@pytest.mark.parametrize("path", PRESETS, ids=lambda p: p.name)
def test_check_and_ray_equal_the_cli_on_every_preset(cli, path):
    for pose, value in load(path)["poses"].items():
        assert cablenav.check(path, pose) == cli("check", path, "--pose", pose)
        x = value["position"][0]
        assert cablenav.ray(path, pose, "x", (x - 1, x + 1)) == cli("ray", path, "--pose", pose, "--vary", "x", "--range", x - 1, x + 1)
        if load(path)["robot"].get("mobility") == "point":
            # a point mass has no orientation: a ray along theta is refused, naming its coordinates
            with pytest.raises(cablenav.ScenarioError, match="its coordinates are x, y, z"):
                cablenav.ray(path, pose, "theta", (-1.0, 1.0))
        else:
            assert cablenav.ray(path, pose, "theta", (-1.0, 1.0)) == cli("ray", path, "--pose", pose, "--vary", "theta", "--range", -1, 1)


def test_envelope_slice_and_plan_equal_the_cli(cli):
    robocrane = ROOT / "static" / "scenarios" / "robocrane.json"
    assert cablenav.envelope(robocrane, samples=20) == cli("envelope", robocrane, "--samples", 20)
    assert cablenav.slice(robocrane, "q1", ("phi", "theta"), 30) == cli("slice", robocrane, "--pose", "q1", "--axes", "phi,theta", "--res", 30)
    box = ROOT / "static" / "scenarios" / "cdpr7-box.json"
    assert cablenav.slice(box, "start", ("x", "y"), 20, ((0, 4), (0, 4))) == cli(
        "slice", box, "--pose", "start", "--axes", "x,y", "--res", 20, "--range", 0, 4, 0, 4
    )
    ours = cablenav.plan(robocrane, "q1-q2", radius=0.3, epsilon=0.3)
    theirs = cli("plan", robocrane, "--query", "q1-q2", "--radius", 0.3, "--epsilon", 0.3)
    assert ours.pop("seconds") >= 0 and theirs.pop("seconds") >= 0  # wall-clock time differs
    assert ours.pop("elapsed_ms") >= 0 and theirs.pop("elapsed_ms") >= 0
    assert ours == theirs and ours["status"] == "found"


def test_timed_trajectories_equal_the_cli(cli):
    timed = ROOT / "static" / "scenarios" / "robocrane-timed.json"
    for trajectory in [t["name"] for t in load(timed)["trajectories"]]:
        report = cablenav.verify(timed, trajectory)
        assert report == cli("verify", timed, "--trajectory", trajectory)
        assert report["seconds"]["duration"] > 0
        for t in (0.0, 0.3, 1.0):
            assert cablenav.check_at(timed, t, trajectory) == cli("check", timed, "--trajectory", trajectory, "--t", t)
    assert cablenav.envelope(timed, "swing", samples=10) == cli("envelope", timed, "--trajectory", "swing", "--samples", 10)
    fastest = cablenav.time(timed, "swing", cells=100)
    assert fastest == cli("time", timed, "--trajectory", "swing", "--cells", 100)
    assert fastest["duration"] >= fastest["uncertified_duration"] > 0
    with pytest.raises(cablenav.ScenarioError) as e:
        cablenav.time(timed, "swing", margin=0.7)
    assert e.value.field == "margin"
    with pytest.raises(cablenav.ScenarioError) as e:
        cablenav.check_at(timed, 1.5)
    assert e.value.field == "t"


def test_plan_takes_the_clis_atlas_options(cli):
    robocrane = ROOT / "static" / "scenarios" / "robocrane.json"
    default = cablenav.plan(robocrane, "q1-q2")
    for keyword, option, value in [("min_radius", "--min-radius", 1.0), ("heuristic_weight", "--heuristic-weight", 1.0)]:
        ours = cablenav.plan(robocrane, "q1-q2", **{keyword: value})
        theirs = cli("plan", robocrane, "--query", "q1-q2", option, value)
        assert ours.pop("seconds") >= 0 and theirs.pop("seconds") >= 0  # wall-clock time differs
        assert ours.pop("elapsed_ms") >= 0 and theirs.pop("elapsed_ms") >= 0
        assert ours == theirs and ours["status"] == "found" and ours["params"][keyword] == value
        # it changes the search: the default (min_radius 0.1, heuristic_weight 1.5) takes 13 charts
        assert ours["charts"] != default["charts"], (keyword, ours["charts"])
    # refused by the core as the CLI refuses them, naming the keyword
    for keyword, value, words in [
        ("min_radius", -1.0, "positive finite"),
        ("min_radius", float("nan"), "positive finite"),
        ("heuristic_weight", 0.5, "≥ 1"),
        ("heuristic_weight", float("inf"), "≥ 1"),
    ]:
        with pytest.raises(cablenav.ScenarioError) as e:
            cablenav.plan(robocrane, "q1-q2", **{keyword: value})
        assert e.value.field == keyword and words in e.value.reason, str(e.value)
        assert str(e.value).startswith(f"{robocrane}: {keyword}: ")


def test_stubs_name_the_parameters_of_every_function():
    stub = ast.parse((Path(cablenav.__file__).parent / "_cablenav.pyi").read_text())
    for f in (n for n in stub.body if isinstance(n, ast.FunctionDef)):
        stubbed = [a.arg for a in f.args.args + f.args.kwonlyargs]
        assert stubbed == list(inspect.signature(getattr(cablenav, f.name)).parameters), f.name


def test_lattice_and_the_lattice_planner_equal_the_cli(cli):
    box = ROOT / "static" / "scenarios" / "cdpr7-box.json"
    ours = cablenav.lattice(box, "start", ("x", "y", "z"), ((0.2, 3.8), (1.1, 2.9), (0.3, 3.7)), 5)
    theirs = cli("lattice", box, "--pose", "start", "--axes", "x,y,z", "--range", 0.2, 3.8, 1.1, 2.9, 0.3, 3.7, "--steps", 5)
    assert ours == theirs and ours["steps"] == [5, 5, 5] and len(ours["rays"]) == 75
    assert cablenav.lattice(box, "start", ["x", "y"], [(0, 4), (0, 4)], [5, 3]) == cli(
        "lattice", box, "--pose", "start", "--axes", "x,y", "--range", 0, 4, 0, 4, "--steps", "5,3"
    )
    ours = cablenav.plan(box, "over-box", planner="lattice", steps=5)
    theirs = cli("plan", box, "--query", "over-box", "--planner", "lattice", "--steps", 5)
    assert ours.pop("seconds") >= 0 and theirs.pop("seconds") >= 0  # wall-clock time differs
    assert ours.pop("elapsed_ms") >= 0 and theirs.pop("elapsed_ms") >= 0
    assert ours == theirs and ours["steps"] == [5, 5, 5]


def test_multi_link_robots_equal_the_cli(cli):
    arm = ROOT / "static" / "multilink" / "bmarm-x4-2.json"
    quarter = 0.7853981633974483
    assert cablenav.check(arm, "fig312") == cli("check", arm, "--pose", "fig312")
    assert cablenav.ray(arm, "below", "alpha", (-quarter, quarter)) == cli("ray", arm, "--pose", "below", "--vary", "alpha", "--range", -quarter, quarter)
    ours = cablenav.lattice(arm, "fig312", ("alpha", "beta"), ((-quarter, quarter), (-quarter, quarter)), 10)
    assert ours == cli("lattice", arm, "--pose", "fig312", "--axes", "alpha,beta", "--range", -quarter, quarter, -quarter, quarter, "--steps", 10)
    assert ours["components"] == 2 and ours["axes"] == ["alpha", "beta"]
    assert cablenav.slice(arm, "fig312", ("alpha", "theta"), 12) == cli("slice", arm, "--pose", "fig312", "--axes", "alpha,theta", "--res", 12)
    assert cablenav.verify(arm, "across the gap") == cli("verify", arm, "--trajectory", "across the gap")
    with pytest.raises(cablenav.ScenarioError) as e:
        cablenav.ray(arm, "fig312", "x", (0, 1))
    assert e.value.field == "vary" and "alpha, beta, gamma, theta" in str(e.value)
    # the atlas planner (the default) refuses a chain, naming the lattice planner in Python's words
    with pytest.raises(cablenav.ScenarioError) as e:
        cablenav.plan(arm, "any")
    assert e.value.field == "plan" and 'planner="lattice"' in str(e.value) and "--planner" not in str(e.value), str(e.value)


def test_an_arm_with_masses_holds_its_weight_as_the_cli_says(cli, tmp_path):
    # CASPR's BMArm imported with its links' masses (format 6, CASPR's gravity, closure left
    # out): static feasibility is checked per configuration and along a path, as the CLI does
    model = ROOT.parent / "shared" / "models" / "caspr" / "BMArm"
    arm = cablenav.import_caspr(model)["scenario"]
    assert arm["format"] == "cablenav-scenario/6" and arm["robot"]["gravity"] == [0.0, 0.0, -9.81]
    assert arm["robot"]["closure"] is False
    assert [link["mass"] for link in arm["robot"]["links"]] == [0.9810187, 0.1313765]
    bent = dict(arm["configurations"]["initial"], theta=-0.95)
    arm["configurations"]["bent"] = bent
    arm["trajectories"] = [{"name": "bend", "through": ["initial", "bent"]}]
    path = tmp_path / "arm.json"
    path.write_text(json.dumps(arm))
    check = cablenav.check(arm, "initial")
    assert check == cli("check", path, "--pose", "initial")
    assert any(c["constraint"] == "static feasibility" and c["distance"] > 0 for c in check["checks"])
    ours = cablenav.verify(arm, "bend")
    assert ours == cli("verify", path, "--trajectory", "bend")
    assert [b["constraint"] for b in ours["boundaries"]] == ["static feasibility"] and not ours["uncertain"]
    bad = json.loads(json.dumps(arm))
    bad["robot"]["links"][1]["mass"] = -1
    with pytest.raises(cablenav.ScenarioError) as e:
        cablenav.verify(bad, "bend")
    assert e.value.field == "robot.links[1].mass" and "positive" in e.value.reason


def test_errors_carry_the_field():
    scenario = load(ROOT / "static" / "scenarios" / "cdpr7.json")
    bad = json.loads(json.dumps(scenario))
    bad["robot"]["cables"][3]["base"] = [0, float("nan"), 4]
    with pytest.raises(cablenav.ScenarioError) as e:
        cablenav.verify(bad)
    assert e.value.field == "robot.cables[3].base[1]" and "finite" in e.value.reason
    bad["robot"]["cables"][3]["base"] = [0, 4]
    with pytest.raises(cablenav.ScenarioError) as e:
        cablenav.verify(json.dumps(bad))
    assert e.value.field == "robot.cables[3].base"
    assert isinstance(e.value, ValueError) and str(e.value).startswith("robot.cables[3].base: ")
    cases = [
        (lambda: cablenav.verify(scenario, "nope"), "trajectory"),
        (lambda: cablenav.verify(scenario, pointwise=0.0), "pointwise"),
        (lambda: cablenav.ray(scenario, "start", "w", (0, 1)), "vary"),
        (lambda: cablenav.ray(scenario, "start", "x", (1, 0)), "range"),
        (lambda: cablenav.check(scenario, "nobody"), "pose"),
        (lambda: cablenav.envelope(scenario, samples=0), "samples"),
        (lambda: cablenav.slice(scenario, "start", ("x", "y"), 10), "range"),
        (lambda: cablenav.slice(scenario, "start", ("phi", "phi"), 10), "axes"),
        (lambda: cablenav.plan(ROOT / "static" / "scenarios" / "robocrane.json", "q1-q2", radius=-1.0), "radius"),
        (lambda: cablenav.plan(ROOT / "static" / "scenarios" / "robocrane.json", "q1-q2", max_charts=0), "max_charts"),
        (lambda: cablenav.plan(scenario, "q1-q2"), "query"),
        (lambda: cablenav.plan(scenario, "q1-q2", planner="rrt"), "planner"),
        (lambda: cablenav.plan(scenario, "q1-q2", steps=5), "steps"),
        (lambda: cablenav.lattice(scenario, "start", ("x", "w"), ((0, 1), (0, 1)), 5), "axes"),
        (lambda: cablenav.lattice(scenario, "start", ("x", "y"), ((0, 1), (0, 1)), 1), "steps"),
        (lambda: cablenav.lattice(scenario, "start", ("x", "y"), ((0, 1),), 5), "ranges"),
    ]
    for call, field in cases:
        with pytest.raises(cablenav.ScenarioError) as e:
            call()
        assert e.value.field == field, (field, e.value.field, str(e.value))
    # `steps` belongs to the lattice planner (the core's one check, in Python's words)
    with pytest.raises(cablenav.ScenarioError) as e:
        cablenav.plan(scenario, "q1-q2", steps=5)
    assert str(e.value) == 'steps: is an option of planner="lattice"'
    # and the atlas options to the atlas planner: refused with the lattice planner, not ignored
    with pytest.raises(cablenav.ScenarioError) as e:
        cablenav.plan(scenario, "q1-q2", planner="lattice", min_radius=0.2)
    assert str(e.value) == 'min_radius: is an option of planner="atlas"'
    with pytest.raises(cablenav.ScenarioError) as e:
        cablenav.verify(ROOT / "no" / "such.json")
    assert e.value.path == str(ROOT / "no" / "such.json") and "cannot read" in e.value.reason
    with pytest.raises(TypeError):
        cablenav.verify(42)


def test_long_calls_release_the_gil():
    """Another Python thread runs while a slice is being computed in the core."""
    robocrane = load(ROOT / "static" / "scenarios" / "robocrane.json")
    started, done, ticks = threading.Event(), threading.Event(), [0]

    def work():
        started.set()
        cablenav.slice(robocrane, "q1", ("phi", "theta"), 400)
        done.set()

    worker = threading.Thread(target=work)
    worker.start()
    started.wait()
    while not done.is_set():
        ticks[0] += 1
    worker.join()
    # Holding the GIL, the core would let this loop run only between Python bytecodes of `work`.
    assert ticks[0] > 1000, ticks[0]


def test_every_function_has_a_docstring_and_a_stub():
    stub = ast.parse((Path(cablenav.__file__).parent / "_cablenav.pyi").read_text())
    stubbed = {n.name for n in stub.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    for name in cablenav.__all__:
        if name == "__version__":
            continue
        assert name in stubbed, name
        assert len(getattr(cablenav, name).__doc__ or "") > 40, name
    assert (Path(cablenav.__file__).parent / "py.typed").exists()


def test_import_caspr_equals_the_cli(cli, tmp_path):
    model = ROOT.parent / "shared" / "models" / "caspr" / "CoGiRo"
    imported = cablenav.import_caspr(model)
    written = tmp_path / "cogiro.json"
    exe = os.environ.get("CABLENAV") or str(ROOT / "target" / "debug" / "cablenav")
    subprocess.run([exe, "import", str(model), "--out", str(written)], check=True, capture_output=True)
    assert imported["scenario"] == json.loads(written.read_text())
    assert [t["name"] for t in imported["scenario"]["trajectories"]][1:] == ["general_1", "general_2", "general_3", "long_stable"]
    report = cablenav.verify(imported["scenario"], "long_stable")
    assert report == cli("verify", written, "--trajectory", "long_stable")
    assert report["seconds"]["duration"] == 18.0 and 0.99 < report["seconds"]["min_time_scale"] < 1.0
    # another trajectories file of the same model, and a directory without a model
    only_first = tmp_path / "first.xml"
    text = (model / "CoGiRo_trajectories.xml").read_text()
    only_first.write_text(text[: text.index('<quintic_spline_trajectory id="general_2"')] + "</joint_trajectories></trajectories>")
    names = [t["name"] for t in cablenav.import_caspr(model, trajectories=only_first, name="c")["scenario"]["trajectories"]]
    assert names == ["hold initial", "general_1"]
    with pytest.raises(cablenav.ScenarioError) as e:
        cablenav.import_caspr(tmp_path)
    assert e.value.field == str(tmp_path) and "bodies" in e.value.reason


def test_import_caspr_picks_a_cable_set(tmp_path):
    model = ROOT.parent / "shared" / "models" / "caspr" / "Example_spatial"
    default = cablenav.import_caspr(model)
    assert len(default["scenario"]["robot"]["cables"]) == 7
    assert any('cable set "basic_7_cables" of 4' in n for n in default["notes"])
    written = tmp_path / "cross.json"
    exe = os.environ.get("CABLENAV") or str(ROOT / "target" / "debug" / "cablenav")
    subprocess.run([exe, "import", str(model), "--cable-set", "cross_8_cables", "--out", str(written)], check=True, capture_output=True)
    assert cablenav.import_caspr(model, cable_set="cross_8_cables")["scenario"] == json.loads(written.read_text())
    with pytest.raises(cablenav.ScenarioError) as e:
        cablenav.import_caspr(model, cable_set="nine")
    assert e.value.field == "cable_set" and "basic_8_cables" in e.value.reason


def test_plan_takes_several_queries_and_paper_coordinates(cli):
    robocrane = ROOT / "static" / "scenarios" / "robocrane.json"
    ours = cablenav.plan(robocrane, ["q1-q2", "q3-q4"])
    theirs = cli("plan", robocrane, "--query", "q1-q2", "--query", "q3-q4")
    assert [r["query"] for r in ours] == ["q1-q2", "q3-q4"]
    for a, b in zip(ours, theirs):
        for key in ("seconds", "elapsed_ms"):
            assert a.pop(key) >= 0 and b.pop(key) >= 0  # wall-clock time differs
    assert ours == theirs and ours[1]["reused_charts"] == ours[0]["charts"]
    assert [r["query"] for r in cablenav.plan(robocrane, ["q3-q4"])] == ["q3-q4"]  # a list gives a list
    paper = cablenav.plan(robocrane, "q3-q4", identify_angles=False)
    assert paper["params"]["identify_angles"] is False and paper["charts"] > 100
    with pytest.raises(cablenav.ScenarioError) as e:
        cablenav.plan(robocrane, "q3-q4", planner="lattice", identify_angles=False)
    assert e.value.field == "identify_angles"
    with pytest.raises(cablenav.ScenarioError) as e:
        cablenav.plan(robocrane, 3)
    assert e.value.field == "query"


def test_plan_saves_and_loads_the_atlas(tmp_path):
    robocrane = ROOT / "static" / "scenarios" / "robocrane.json"
    kept = tmp_path / "crane.atlas"
    first = cablenav.plan(robocrane, "q1-q2", atlas=kept)
    assert kept.read_text().startswith('{"format":"cablenav-atlas/1"')
    again = cablenav.plan(robocrane, "q1-q2", atlas=str(kept))
    assert again["reused_charts"] == first["charts"] == again["charts"] and again["status"] == "found"
    with pytest.raises(cablenav.ScenarioError) as e:
        cablenav.plan(robocrane, "q1-q2", atlas=kept, epsilon=0.3)
    assert e.value.field == "atlas"
