"""Merges the benchmark results (run by bench/run) into one table, checks the targets, writes JSON.

Inputs: Google Benchmark JSON of bonl_bench and bonl_bench_plant, and the JSON printed by
bench/python_baselines.py. Prints the tables (Markdown) to stdout; --json FILE writes the flat
numbers; --results-md FILE writes them with the machine's description (bench/RESULTS.md).

C++ times are Google Benchmark's CPU time per iteration (the fastest repetition when there are
several, like the Python best-of-repeats: on a shared machine noise only adds time), which leaves
out the time the process was preempted; the plant's real-time factor is
wall-clock. Python times are the best wall time of several repeats.
"""

from __future__ import annotations

import argparse
import datetime
import json
import math
import platform
import subprocess
import sys

PHW_PARAMS = 14
# The models are those the benchmarks name (update/<Model::kName>/...), in the order they ran. The
# --json key <model>_update_ns is the equation-error update (the target's fixed-size figure); the
# output-error method, the default, adds <model>_update_output_error_ns.
PHW = "PseudoHammersteinWiener"
METHODS = (("", "output_error"), ("/equation_error", "equation_error"), ("/paper", "paper"))
# Records the P-H-W structure does not fit (bench_data.hpp, update/<P-H-W>/<sizes>/double/<data>).
MISMATCHES = ("delayed_fir", "integrator")


def load_gbench(path: str) -> tuple[dict, dict]:
    """{name: entry}, the fastest repetition when the run had several, and the context."""
    with open(path, encoding="utf-8") as f:
        data = json.load(f)
    entries: dict = {}
    for b in data["benchmarks"]:
        name = b["run_name"] if "run_name" in b else b["name"]
        if b.get("run_type") == "aggregate":
            continue
        if b.get("error_occurred"):
            entries[name] = b
        elif name not in entries or (not entries[name].get("error_occurred") and
                                     ns(b) < ns(entries[name])):
            entries[name] = b
    return entries, data["context"]


def ns(entry: dict, key: str = "cpu_time") -> float:
    scale = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}[entry.get("time_unit", "ns")]
    return entry[key] * scale


def fmt_ns(value: float | None) -> str:
    if value is None or not math.isfinite(value):
        return "-"
    return f"{value:,.0f}" if value >= 1000 else f"{value:.1f}"


def fmt_ratio(baseline: float | None, ours: float | None) -> str:
    if not baseline or not ours:
        return "-"
    ratio = baseline / ours
    return f"{ratio:,.0f}x" if ratio >= 100 else (f"{ratio:.1f}x" if ratio >= 1 else f"{ratio:.2f}x")


def table(header: list[str], rows: list[list[str]], align: str | None = None) -> str:
    align = align or "l" + "r" * (len(header) - 1)
    widths = [max(len(str(r[i])) for r in [header] + rows) for i in range(len(header))]

    def line(cells: list[str]) -> str:
        out = []
        for cell, width, a in zip(cells, widths, align):
            out.append(str(cell).rjust(width) if a == "r" else str(cell).ljust(width))
        return "| " + " | ".join(out) + " |"

    sep = "|" + "|".join(("-" * (w + 1) + ":") if a == "r" else ("-" * (w + 2)) for w, a in zip(widths, align)) + "|"
    return "\n".join([line(header), sep] + [line(r) for r in rows])


def sh(*cmd: str) -> str:
    try:
        return subprocess.run(cmd, capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return ""


def machine(compiler: str, context: dict) -> dict:
    model = ""
    for line in sh("lscpu").splitlines():
        if line.startswith("Model name:"):
            model = line.split(":", 1)[1].strip()
    return {
        "cpu": model or platform.processor(),
        "cores": context.get("num_cpus"),
        "mhz": context.get("mhz_per_cpu"),
        "compiler": compiler,
        "os": platform.platform(),
        "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
        "git": sh("git", "rev-parse", "--short", "HEAD") + (" (with local changes)" if sh("git", "status", "--porcelain") else ""),
        "load_avg_at_start": context.get("load_avg"),
    }


def summary(flat: dict) -> str:
    """The headline figures of a full run, for the pages that quote it (docs/lab/performance.md,
    between <!-- bench_summary --> markers): made from the flat results alone, so that a test can
    render it again from the committed bench/RESULTS.json."""
    models = list(dict.fromkeys(key.split("_update_fixed_double_")[0] for key in flat
                                if "_update_fixed_double_" in key))

    def ratios(pairs) -> str:
        values = [a / b for a, b in pairs if a and b]
        return f"{min(values):.2f} to {max(values):.2f} times" if values else "-"

    methods = [m for _, m in METHODS]
    runtime = ratios((flat.get(f"{m}_update_dynamic_double_{method}_ns"), flat.get(f"{m}_update_fixed_double_{method}_ns"))
                     for m in models for method in methods)
    rls = ratios((v["bonl_dynamic"], v["bonl_fixed"]) for v in flat["rls_sweep_ns"].values())
    python = ratios((flat.get(f"{m}_update_record_python_{method}_ns"), flat.get(f"{m}_update_dynamic_portable_{method}_ns"))
                    for m in models for method in methods)
    machine = flat["machine"]

    def update(model: str, method: str, sizes: str = "fixed") -> str:
        return fmt_ns(flat.get(f"{model}_update_{sizes}_double_{method}_ns")) + " ns"

    phw_fixed = flat.get(f"{PHW}_update_fixed_double_output_error_ns")
    mismatch = "; ".join(
        f"{data.replace('_', ' ')}: {update(PHW, 'output_error_' + data)} fixed, "
        f"{update(PHW, 'output_error_' + data, 'dynamic')} run-time"
        for data in MISMATCHES if flat.get(f"{PHW}_update_fixed_double_output_error_{data}_ns"))
    rows = [
        ["P-H-W update with the defaults (the window refinement from two starts), 1e6 updates, least of 3 "
         "identical runs: mean; worst single update",
         f"{fmt_ns(flat.get(f'{PHW}_update_window_mean_ns'))} ns; "
         f"{fmt_ns(flat.get(f'{PHW}_update_window_worst_ns'))} ns"],
        ["one update, fixed sizes, double, output_error, the recursion alone (window off)",
         ", ".join(f"{m} {update(m, 'output_error')}" for m in models)],
        ["one update, fixed sizes, double, equation_error", ", ".join(f"{m} {update(m, 'equation_error')}" for m in models)],
        ["P-H-W output_error update against the textbook Eigen RLS and padasip at 14 parameters",
         f"{fmt_ratio(flat['naive_rls_ns'], phw_fixed)} and {fmt_ratio(flat['padasip_rls_ns'], phw_fixed)} faster"],
        ["P-H-W output_error update on data it does not fit (bench_data.hpp)", mismatch or "-"],
        ["run-time sizes over fixed sizes: estimator update, RLS core (4 to 32 parameters)", f"{runtime}; {rls}"],
        ["Python `Estimator.update` over a record, over the C++ run-time-size update built alike", python],
        ["`bonl.identify`, P-H-W, 5000 samples: recursive paper method; output_error with its refinement",
         f"{flat['python_identify_5000_ms']:.2f} ms; {flat['python_identify_output_error_5000_ms']:.1f} ms"],
        ["plant: 50 s of the paper's experiment", f"{flat['plant_simulate_50s_ms']:.1f} ms, "
         f"{flat['plant_realtime_factor']:,.0f} times real time"],
    ]
    head = (f"Latest full `bench/run` (`bench/RESULTS.md` names its commit; {machine['cpu']}, "
            f"{machine['cores']} cores, {machine['compiler']}; C++ figures are CPU time, the fastest of "
            f"5 repetitions):")
    return head + "\n\n" + table(["what", "measured"], rows, "ll") + "\n"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cpp", required=True, help="Google Benchmark JSON of bonl_bench")
    parser.add_argument("--plant", required=True, help="Google Benchmark JSON of bonl_bench_plant")
    parser.add_argument("--identify", help="Google Benchmark JSON of bonl_bench_identify")
    parser.add_argument("--python", required=True, help="JSON of bench/python_baselines.py")
    parser.add_argument("--cpp-portable",
                        help="Google Benchmark JSON of bonl_bench built as the Python extension is (no -march=native)")
    parser.add_argument("--json", help="write the flat results here")
    parser.add_argument("--results-md", help="write the tables and the machine here (bench/RESULTS.md)")
    parser.add_argument("--summary", help="write the headline figures here (docs/results/bench_summary.md)")
    parser.add_argument("--command", default="bench/run", help="the command that produced the results")
    parser.add_argument("--compiler", default="", help="compiler and version")
    parser.add_argument("--flags", default="", help="build flags")
    parser.add_argument("--elapsed", type=float, help="seconds bench/run took up to the report")
    args = parser.parse_args()
    cpp, context = load_gbench(args.cpp)
    portable = load_gbench(args.cpp_portable)[0] if args.cpp_portable else {}
    plant, _ = load_gbench(args.plant)
    with open(args.python, encoding="utf-8") as f:
        py = json.load(f)

    def cpp_ns(name: str) -> float | None:
        entry = cpp.get(name)
        if entry is None or entry.get("error_occurred"):
            return None
        return ns(entry)

    textbook = {int(name.rsplit("/", 1)[1]): cpp_ns(name) for name in cpp if name.startswith("textbook_rls/")}
    padasip = {int(n): v for n, v in py["rls"]["padasip"].items()}
    numpy_rls = {int(n): v for n, v in py["rls"]["numpy"].items()}

    flat: dict = {}
    notes: list[str] = []

    models = list(dict.fromkeys(name.split("/")[1] for name in cpp if name.startswith(("update/", "simulate/"))))

    # --- Estimator updates -------------------------------------------------------------------------
    rows = []
    for sizes in ("fixed", "dynamic"):
        for scalar in ("double", "float"):
            for key in models:
                for suffix, method in METHODS:
                    name = f"update/{key}/{sizes}/{scalar}{suffix}"
                    if name not in cpp:
                        continue
                    entry = cpp[name]
                    value = cpp_ns(name)
                    n = int(entry.get("params", 0))
                    updated = entry.get("updated", 1.0)
                    rows.append([f"{key} update, {sizes}, {scalar}, {method} method", str(n), fmt_ns(value),
                                 fmt_ratio(textbook.get(n), value), fmt_ratio(padasip.get(n), value),
                                 f"{updated:.2f}"])
                    flat[f"{key}_update_{sizes}_{scalar}_{method}_ns"] = value
                    if sizes == "fixed" and scalar == "double" and method == "equation_error":
                        flat[f"{key}_update_ns"] = value
                    if sizes == "fixed" and scalar == "double" and method == "output_error":
                        flat[f"{key}_update_output_error_ns"] = value
                    if updated < 0.5:
                        notes.append(f"{name}: only {updated:.0%} of the samples ran the RLS step; its time is "
                                     "mostly that of a refused update.")
    update_table = table(["per-sample estimator update (C++)", "params", "ns/sample", "vs textbook RLS",
                          "vs padasip", "updated"], rows)

    # --- Where the structure does not fit the data --------------------------------------------------
    # The default (output_error) P-H-W update on records it does not fit (bench_data.hpp), where the
    # trace ceiling limits the forgetting or the stability projection shortens the step on most
    # samples, against the same update on the known system's record.
    rows = []
    for sizes in ("fixed", "dynamic"):
        known = cpp_ns(f"update/{PHW}/{sizes}/double")
        for data in MISMATCHES:
            name = f"update/{PHW}/{sizes}/double/{data}"
            if name not in cpp:
                continue
            entry, value = cpp[name], cpp_ns(name)
            flat[f"{PHW}_update_{sizes}_double_output_error_{data}_ns"] = value
            rows.append([f"{data}, {sizes}", fmt_ns(value), f"{value / known:.2f}x" if (value and known) else "-",
                         f"{entry.get('limited', 0.0):.2f}", f"{entry.get('projected', 0.0):.2f}"])
    mismatch_table = table(["P-H-W update, output_error, double, on data it does not fit", "ns/sample",
                            "vs the known system", "ceiling limited", "step shortened"], rows)

    # --- Run-time sizes and the Python streaming call ------------------------------------------------
    # Per model and method (double): the fixed-size update, the run-time-size one and their ratio; the
    # Python call over a whole record (Estimator.update(u_array, y_array)) per sample, and its ratio to
    # the C++ run-time-size update (Python always uses run-time sizes). The extension is compiled
    # portable (no -march=native), so the call's own cost is the ratio to the C++ update compiled the
    # same way (bonl_bench in build/bench-portable); the ratio to the native build adds the instruction set.
    streaming = py["bonl"].get("estimator_update_record_ns", {})

    def portable_ns(name: str) -> float | None:
        entry = portable.get(name)
        return None if entry is None or entry.get("error_occurred") else ns(entry)

    rows = []
    worst_sizes = worst_streaming = None
    for key in models:
        for suffix, method in METHODS:
            fixed = cpp_ns(f"update/{key}/fixed/double{suffix}")
            dynamic = cpp_ns(f"update/{key}/dynamic/double{suffix}")
            dynamic_portable = portable_ns(f"update/{key}/dynamic/double{suffix}")
            python = streaming.get(f"{key}/{method}")
            sizes_ratio = dynamic / fixed if (fixed and dynamic) else None
            python_ratio = python / dynamic_portable if (python and dynamic_portable) else None
            native_ratio = python / dynamic if (python and dynamic) else None
            if sizes_ratio is not None:
                worst_sizes = max(worst_sizes or 0.0, sizes_ratio)
            if python_ratio is not None:
                worst_streaming = max(worst_streaming or 0.0, python_ratio)
            flat[f"{key}_update_record_python_{method}_ns"] = python
            flat[f"{key}_update_dynamic_portable_{method}_ns"] = dynamic_portable
            rows.append([f"{key}, {method}", fmt_ns(fixed), fmt_ns(dynamic),
                         f"{sizes_ratio:.2f}x" if sizes_ratio else "-", fmt_ns(dynamic_portable), fmt_ns(python),
                         f"{python_ratio:.2f}x" if python_ratio else "-",
                         f"{native_ratio:.2f}x" if native_ratio else "-"])
    sizes_table = table(["update per sample, double", "fixed size", "run-time size", "run-time / fixed",
                         "run-time, portable build", "Python, whole record per call", "Python / portable",
                         "Python / native"], rows)
    flat["worst_runtime_over_fixed"] = worst_sizes
    flat["worst_python_record_over_runtime"] = worst_streaming

    # --- Free-run simulation -----------------------------------------------------------------------
    rows = []
    for sizes in ("fixed", "dynamic"):
        for key in models:
            name = f"simulate/{key}/{sizes}/double"
            if name in cpp:
                value = cpp[name]["per_sample"] * 1e9
                rows.append([f"{key} free-run simulation, {sizes}, double", fmt_ns(value)])
                flat[f"{key}_simulate_{sizes}_ns"] = value
    simulate_table = table(["free-run simulation (C++, 4096 samples)", "ns/sample"], rows)

    # --- Baselines and Python ----------------------------------------------------------------------
    bonl_py = py["bonl"]
    flat["naive_rls_ns"] = textbook.get(PHW_PARAMS)
    flat["naive_rls_literal_ns"] = cpp_ns(f"textbook_rls_literal/{PHW_PARAMS}")
    flat["padasip_rls_ns"] = padasip.get(PHW_PARAMS)
    flat["numpy_rls_ns"] = numpy_rls.get(PHW_PARAMS)
    flat["rls_core_fixed_14_ns"] = cpp_ns(f"rls/fixed/{PHW_PARAMS}")
    flat["rls_core_dynamic_14_ns"] = cpp_ns(f"rls/dynamic/{PHW_PARAMS}")
    flat["python_identify_5000_ms"] = bonl_py["identify_paper_5000_ms"]
    flat["python_identify_recursive_output_error_5000_ms"] = bonl_py["identify_output_error_refine0_5000_ms"]
    flat["python_identify_output_error_5000_ms"] = bonl_py["identify_output_error_5000_ms"]
    flat["python_estimator_update_call_ns"] = bonl_py["estimator_update_call_ns"]
    flat["python_estimator_update_call_numpy_scalars_ns"] = bonl_py["estimator_update_call_numpy_scalars_ns"]
    phw = flat.get(f"{PHW}_update_ns")
    phw_output_error = flat.get(f"{PHW}_update_output_error_ns")
    tb, pa = flat["naive_rls_ns"], flat["padasip_rls_ns"]
    # The output-error update with its defaults (the window refinement from two starts): its mean over
    # first passes, and over 1e6 single updates, each the least of three timings of the same update in
    # identical runs (its own work; the machine's pauses fall elsewhere in each run), their mean and
    # worst, beside the largest single timing with and without the window (those pauses).
    window = cpp_ns(f"update/{PHW}/fixed/double/window")

    def worst_counters(prefix: str) -> dict:
        # Google Benchmark names a benchmark with a fixed iteration count ".../iterations:1".
        entry = next((entry for name, entry in cpp.items() if name == f"{prefix}/iterations:1"), None)
        return entry if entry and not entry.get("error_occurred") else {}

    window_worst_entry = worst_counters(f"update_worst/{PHW}/fixed/double/window")
    plain_worst_entry = worst_counters(f"update_worst/{PHW}/fixed/double")
    window_worst = window_worst_entry.get("worst_ns")
    flat[f"{PHW}_update_window_ns"] = window
    flat[f"{PHW}_update_window_worst_ns"] = window_worst
    window_mean = window_worst_entry.get("mean_ns")
    flat[f"{PHW}_update_window_mean_ns"] = window_mean
    flat[f"{PHW}_update_window_raw_worst_ns"] = window_worst_entry.get("raw_worst_ns")
    flat[f"{PHW}_update_output_error_worst_ns"] = plain_worst_entry.get("worst_ns")
    flat[f"{PHW}_update_output_error_raw_worst_ns"] = plain_worst_entry.get("raw_worst_ns")

    window_worst_shown = "-"
    if window_worst:
        window_worst_shown = f"{window_worst / 1000:.1f} us"
        raw, raw_plain = window_worst_entry.get("raw_worst_ns"), plain_worst_entry.get("raw_worst_ns")
        if raw and raw_plain:  # the machine's pauses, with the window and without it
            window_worst_shown += f" (one timing: {raw / 1e6:.2f} ms; without the window {raw_plain / 1e6:.2f} ms)"

    def row(label: str, value: float | None, vs: bool = True) -> list[str]:
        return [label, fmt_ns(value), fmt_ratio(tb, value) if vs else "-", fmt_ratio(pa, value) if vs else "-"]

    rows = [
        row("P-H-W update (bonl, fixed, double, output_error method, window off)", phw_output_error),
        row("P-H-W update (bonl, fixed, double, equation_error method)", phw),
        row("bonl::Rls<double, 14> alone (fixed size)", flat["rls_core_fixed_14_ns"]),
        row("bonl::Rls<double> alone (run-time size 14)", flat["rls_core_dynamic_14_ns"]),
        row("textbook RLS in Eigen, dynamic, O(n^2) P update", tb),
        row("textbook RLS in Eigen, literal `P - K*phi'*P` (O(n^3))", flat["naive_rls_literal_ns"]),
        row("padasip FilterRLS.run (Python)", pa),
        row("numpy RLS loop (Python)", flat["numpy_rls_ns"]),
        row("bonl.Estimator.update (output_error, window off) from a Python loop, per call (Python floats)",
            flat["python_estimator_update_call_ns"]),
        row("bonl.Estimator.update (output_error, window off) from a Python loop, per call (numpy scalars)",
            flat["python_estimator_update_call_numpy_scalars_ns"]),
        row("bonl.identify, recursive (paper method / refine_iterations=0), per sample",
            flat["python_identify_5000_ms"] * 1e6 / 5000),
        row("bonl.identify, recursive (output_error method, refine_iterations=0), per sample",
            flat["python_identify_recursive_output_error_5000_ms"] * 1e6 / 5000),
        row("bonl.identify, output_error (recursive + Levenberg-Marquardt), per sample",
            flat["python_identify_output_error_5000_ms"] * 1e6 / 5000),
    ]
    baseline_table = table([f"at {PHW_PARAMS} parameters (P-H-W)", "ns/sample", "vs textbook RLS", "vs padasip"], rows)

    whole = [
        ["bonl.identify, P-H-W, 5000 samples, recursive (paper method / refine_iterations=0)",
         f"{flat['python_identify_5000_ms']:.3f} ms"],
        ["bonl.identify, P-H-W, 5000 samples, recursive (output_error method, refine_iterations=0)",
         f"{flat['python_identify_recursive_output_error_5000_ms']:.3f} ms"],
        ["bonl.identify, P-H-W, 5000 samples, output_error (recursive + LM refinement)",
         f"{flat['python_identify_output_error_5000_ms']:.1f} ms"],
    ]
    plant_entry = next(iter(plant.values()))
    rtf = plant_entry.get("realtime_factor")
    flat["plant_realtime_factor"] = rtf
    flat["plant_simulate_50s_ms"] = ns(plant_entry, "real_time") / 1e6
    flat["plant_cvode_steps"] = plant_entry.get("steps")
    whole.append(["plant: bonl::plant::simulate, paper multi-sine, 50 s simulated",
                  f"{flat['plant_simulate_50s_ms']:.1f} ms wall, real-time factor {rtf:,.0f}, "
                  f"{flat['plant_cvode_steps']:,.0f} CVODE steps"])
    if args.identify:
        identify, _ = load_gbench(args.identify)
        for name, entry in identify.items():
            flat[name] = ns(entry) / 1e6
            whole.append([f"bonl::identify, H-W (6, 5, 1, 3, 3), run-time orders, {name.split('/')[2]} samples",
                          f"{flat[name]:.0f} ms CPU"])
    whole_table = table(["whole record", "time"], whole, "ll")

    # --- RLS sweep ---------------------------------------------------------------------------------
    rows = []
    sweep = {}
    worst_rls = None
    for n in sorted(textbook):
        fixed, dynamic = cpp_ns(f"rls/fixed/{n}"), cpp_ns(f"rls/dynamic/{n}")
        sweep[str(n)] = {"bonl_fixed": fixed, "bonl_dynamic": dynamic, "textbook": textbook[n],
                         "padasip": padasip.get(n), "numpy": numpy_rls.get(n)}
        ratio = dynamic / fixed if (fixed and dynamic) else None
        if ratio is not None:
            worst_rls = max(worst_rls or 0.0, ratio)
        rows.append([str(n), fmt_ns(fixed), fmt_ns(dynamic), f"{ratio:.2f}x" if ratio else "-", fmt_ns(textbook[n]),
                     fmt_ns(padasip.get(n)), fmt_ns(numpy_rls.get(n)), f"{fixed / n**2:.3f}" if fixed else "-",
                     fmt_ratio(padasip.get(n), fixed)])
    flat["rls_sweep_ns"] = sweep
    flat["worst_rls_runtime_over_fixed"] = worst_rls
    sweep_table = table(["n", "Rls<double, n>", "Rls<double> (run-time n)", "run-time / fixed", "textbook Eigen",
                         "padasip", "numpy", "fixed ns/n^2", "fixed vs padasip"], rows)

    # --- Targets -----------------------------------------------------------------------------------
    speedup = pa / phw if (pa and phw) else None
    flat["phw_vs_padasip"] = speedup
    flat["phw_vs_textbook"] = tb / phw if (tb and phw) else None
    targets = [
        ("P-H-W update, equation_error (fixed, double)", phw, "<= 60 ns", phw is not None and phw <= 60,
         f"{phw:.1f} ns"),
        ("P-H-W update, output_error, as a multiple of equation_error",
         phw_output_error / phw if (phw and phw_output_error) else None, "<= 2x",
         phw is not None and phw_output_error is not None and phw_output_error <= 2 * phw,
         f"{phw_output_error / phw:.2f}x ({phw_output_error:.1f} ns)" if (phw and phw_output_error) else "-"),
        ("P-H-W update with the defaults (the window refinement), mean of 1e6 updates (least of 3 identical runs)",
         window_mean, "<= 2 us", window_mean is not None and window_mean <= 2000,
         f"{window_mean / 1000:.2f} us" if window_mean else "-"),
        ("P-H-W update with the window refinement, worst single update of 1e6 (least of 3 identical runs)",
         window_worst, "<= 20 us", window_worst is not None and window_worst <= 20000,
         window_worst_shown),
        ("P-H-W update vs padasip at 14 parameters", speedup, ">= 200x", speedup is not None and speedup >= 200,
         f"{speedup:,.0f}x" if speedup else "-"),
        ("Python identify, 5000 samples (paper method)", flat["python_identify_5000_ms"], "<= 2 ms",
         flat["python_identify_5000_ms"] <= 2.0, f"{flat['python_identify_5000_ms']:.3f} ms"),
        ("plant real-time factor", rtf, ">= 1000", rtf is not None and rtf >= 1000, f"{rtf:,.0f}"),
        ("estimator update, run-time over fixed size, worst model and method", worst_sizes, "<= 1.3x",
         worst_sizes is not None and worst_sizes <= 1.3, f"{worst_sizes:.2f}x" if worst_sizes else "-"),
        ("RLS core, run-time over fixed size, worst of 4 to 32 parameters", worst_rls, "<= 1.3x",
         worst_rls is not None and worst_rls <= 1.3, f"{worst_rls:.2f}x" if worst_rls else "-"),
        ("Python update over a record per sample, over the C++ run-time-size update built alike, worst",
         worst_streaming, "<= 1.2x", worst_streaming is not None and worst_streaming <= 1.2,
         f"{worst_streaming:.2f}x" if worst_streaming else "-"),
    ]
    flat["targets"] = {name: {"value": value, "target": target, "met": bool(met)}
                       for name, value, target, met, _ in targets}
    target_table = table(["target", "measured", "required", "met"],
                         [[name, shown, target, "yes" if met else "NO"] for name, _, target, met, shown in targets],
                         "lrrl")
    if not all(met for _, _, _, met, _ in targets):
        target_table += ("\n\nA missed target: where the time goes, what was tried and what is left are in "
                         "`docs/lab/performance.md`.")

    info = machine(args.compiler, context)
    info["flags"] = args.flags
    flat["machine"] = info
    flat["command"] = args.command
    if args.elapsed is not None:
        flat["elapsed_s"] = args.elapsed

    sections = [
        ("Targets", target_table),
        ("Per-sample estimator update", update_table),
        ("Where the structure does not fit the data", mismatch_table),
        ("Run-time sizes and the Python call over a record", sizes_table),
        ("Baselines at the P-H-W parameter count", baseline_table),
        ("Whole record", whole_table),
        ("Free-run simulation", simulate_table),
        ("RLS core against the baselines, by parameter count (ns per sample)", sweep_table),
    ]
    legend = (
        "`vs textbook RLS` and `vs padasip`: the baseline's time divided by this row's time, at the same "
        "parameter count (how many times faster this row is). `updated`: fraction of the samples that ran the "
        "RLS step (the P-H-W equation_error method skips samples inside the backlash gap; output_error updates on every sample). "
        "`ceiling limited` and `step shortened`: fractions of the samples whose forgetting the trace ceiling limited and "
        "whose step the stability projection shortened (bench/bench_data.hpp describes the records). C++: CPU time per sample "
        "(fastest of 5 repetitions); Python: best wall time of several repeats. Same random regressors, "
        "forgetting factor 0.99 and P(0) = 1e3 I for every RLS baseline; float equation_error and paper estimators use P(0) = 1e4 I."
    )
    text = "\n\n".join(f"### {title}\n\n{body}" for title, body in sections) + "\n\n" + legend + "\n"
    if notes:
        text += "\n" + "\n".join(f"- {n}" for n in notes) + "\n"
    print(text)

    if args.json:
        with open(args.json, "w", encoding="utf-8") as f:
            json.dump(flat, f, indent=2)
            f.write("\n")
    if args.summary:
        with open(args.summary, "w", encoding="utf-8") as f:
            f.write(summary(flat))
    if args.results_md:
        header = [
            "# Benchmark results",
            "",
            f"Written by `{args.command}` on {info['date']} (commit {info['git']}).",
            "",
            f"- CPU: {info['cpu']}, {info['cores']} cores ({info['mhz']} MHz as Google Benchmark reads it)",
            f"- compiler: {info['compiler']}; flags: {info['flags']}",
            f"- OS: {info['os']}; Python {py['python']}, numpy {py['numpy_version']}, "
            f"padasip {py['rls']['padasip_version']}",
            f"- load average at the start of the C++ run: {info['load_avg_at_start']}",
        ]
        if args.elapsed is not None:
            header.append(f"- bench/run took {args.elapsed:.0f} s up to this report (build included)")
        with open(args.results_md, "w", encoding="utf-8") as f:
            f.write("\n".join(header) + "\n\n" + text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
