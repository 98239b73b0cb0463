"""The benchmark suite runs end to end, as bench/run runs it: every C++ benchmark binary (built by
scripts/test.sh, found through BONL_BENCH_DIR) for a millisecond a benchmark, the Python baselines
once each, and bench/report.py over their output, which must measure every target of its table.
The figures are not judged (bench/run measures them on a quiet machine); this keeps a benchmark that
throws, reports an error or falls out of the report from going unnoticed. ctest runs each binary
too (bench/smoke/*), with the sanitizer-free release build."""

import json
import os
import pathlib
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
BINARIES = ("bonl_bench", "bonl_bench_plant", "bonl_bench_identify")


@pytest.fixture(scope="module")
def bench_dir():
    path = os.environ.get("BONL_BENCH_DIR")
    if not path:
        pytest.fail("BONL_BENCH_DIR is not set: build the benchmarks (-DBONL_BUILD_BENCH=ON) and point it at "
                    "the build's bench/ folder (scripts/test.sh does)")
    return pathlib.Path(path)


def run_benchmark(binary, out):
    """One binary in smoke mode, its results as Google Benchmark JSON in `out`; fails on an error."""
    result = subprocess.run([str(binary), "--benchmark_min_time=0.001", "--benchmark_format=json",
                             "--benchmark_out_format=json", f"--benchmark_out={out}"],
                            capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, f"{binary.name} exited {result.returncode}:\n{result.stderr[-2000:]}"
    entries = json.loads(out.read_text())["benchmarks"]
    assert entries, f"{binary.name} ran no benchmark"
    errors = [(b["name"], b.get("error_message")) for b in entries if b.get("error_occurred")]
    assert not errors, f"{binary.name}: benchmarks reported errors: {errors}"
    return entries


def test_every_benchmark_runs_and_the_report_measures_every_target(bench_dir, tmp_path):
    entries = {}
    for name in BINARIES:
        binary = bench_dir / name
        assert binary.is_file(), f"{binary} is not built"
        entries[name] = run_benchmark(binary, tmp_path / f"{name}.json")

    # Every model of the library has its update, simulation and (where it has one) inverse rows.
    import bonl

    names = {b["name"] for b in entries["bonl_bench"]}
    for model in bonl.MODELS:
        for sizes in ("fixed", "dynamic"):
            assert f"update/{model.__name__}/{sizes}/double" in names, model.__name__
            assert f"simulate/{model.__name__}/{sizes}/double" in names, model.__name__

    python_json = tmp_path / "python.json"
    subprocess.run([sys.executable, str(ROOT / "bench" / "python_baselines.py"), "--smoke", "--out",
                    str(python_json)], check=True, timeout=600)
    flat_json = tmp_path / "flat.json"
    report = subprocess.run(
        [sys.executable, str(ROOT / "bench" / "report.py"), "--cpp", str(tmp_path / "bonl_bench.json"),
         "--cpp-portable", str(tmp_path / "bonl_bench.json"), "--plant", str(tmp_path / "bonl_bench_plant.json"),
         "--identify", str(tmp_path / "bonl_bench_identify.json"), "--python", str(python_json),
         "--json", str(flat_json)], capture_output=True, text=True, timeout=300)
    assert report.returncode == 0, report.stderr
    flat = json.loads(flat_json.read_text())
    unmeasured = [name for name, target in flat["targets"].items() if target["value"] is None]
    assert not unmeasured, f"targets without a measurement: {unmeasured}"
