"""Shared fixtures: the repository root, the presets, and the `cablenav` CLI as the reference."""

import json
import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PRESETS = sorted((ROOT / "static" / "scenarios").glob("*.json"))


@pytest.fixture(scope="session")
def cli():
    """Runs the CLI (CABLENAV, else target/debug/cablenav, built if missing) and parses its JSON."""
    exe = os.environ.get("CABLENAV") or str(ROOT / "target" / "debug" / "cablenav")
    if not Path(exe).exists():
        subprocess.run(["cargo", "build", "-q", "--bin", "cablenav"], cwd=ROOT, check=True)

    def run(*args):
        out = subprocess.run([exe, *map(str, args), "--json"], capture_output=True, text=True, check=True)
        return json.loads(out.stdout)

    return run
