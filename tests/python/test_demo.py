"""``python -m bonl``: the command line and its ``demo`` subcommand (bonl.demo)."""

import json
import math
import subprocess
import sys

import pytest

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
MODEL_KEYS = {"ARX", "Hammerstein", "HammersteinWiener", "PrandtlIshlinskiiHammerstein", "PseudoHammersteinWiener"}


def run_bonl(*args, cwd=None):
    return subprocess.run(
        [sys.executable, "-m", "bonl", *args], capture_output=True, text=True, timeout=300, cwd=cwd, check=False
    )


def test_help_lists_the_demo_subcommand():
    result = run_bonl("--help")
    assert result.returncode == 0, result.stderr
    assert "demo" in result.stdout
    result = run_bonl("demo", "--help")
    assert result.returncode == 0, result.stderr
    assert "--out" in result.stdout and "--method" in result.stdout


def test_usage_errors():
    assert run_bonl().returncode == 2
    assert run_bonl("demo", "--method", "mrlsa").returncode == 2
    assert run_bonl("no-such-command").returncode == 2


def test_demo_writes_figures_tables_and_results(tmp_path):
    pytest.importorskip("matplotlib")
    out = tmp_path / "demo"
    result = run_bonl("demo", "--out", str(out), "--method", "paper")
    assert result.returncode == 0, result.stderr
    for table in ("Table 1. Identification results (method: paper)", "Table 1. Identification results (method: output_error)"):
        assert table in result.stdout
    assert result.stdout.count("Table 2. MSE of the identified models") == 2

    for name in ("fig11_velocity.png", "fig12_residuals.png"):
        data = (out / name).read_bytes()
        assert len(data) > 10000 and data.startswith(PNG_SIGNATURE), name
    assert "Table 2" in (out / "tables.txt").read_text()

    results = json.loads((out / "results.json").read_text())
    assert results["method"] == "paper"
    assert set(results["mse"]) == MODEL_KEYS
    assert results["mse"] == results["methods"]["paper"]["mse"]
    for method in ("output_error", "paper"):
        mse = results["methods"][method]["mse"]
        assert set(mse) == MODEL_KEYS
        assert all(isinstance(v, float) and math.isfinite(v) and v > 0 for v in mse.values())
        params = results["methods"][method]["params"]
        assert set(params) == MODEL_KEYS and isinstance(params["PseudoHammersteinWiener"]["c"], float)
    # The printed Table 2 carries the same numbers.
    assert "%12.4e" % results["mse"]["PseudoHammersteinWiener"] in result.stdout
