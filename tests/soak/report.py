"""Gathers bonl_soak runs (their --json files, scripts/soak.sh) into docs/results/soak.json and the
table docs/lab/reliability.md quotes (docs/results/soak_summary.md).

    python3 tests/soak/report.py --runs DIR --json FILE --markdown FILE [--command TEXT]

DIR holds seed_<S>.json (the output-error method's recursion alone, bonl_soak --no-window) and
seed_<S>_window.json (its defaults: with the window refinement) for S = 1..N, the same N for both. tests/python/test_published_figures.py renders the
committed JSON with summary() and compares it with the committed table."""

import argparse
import json
import pathlib
import re
import statistics
import sys

#: The configurations, as scripts/soak.sh names their files, and the table's column for each.
CONFIGURATIONS = (("output_error", "", "the recursion alone"),
                  ("output_error_window", "_window", "with the window refinement"))


def gather(runs_dir):
    """The runs of DIR by configuration, each list in seed order. Raises ValueError when a
    configuration's seeds are not 1..N or differ from the other's."""
    runs = {}
    for name, suffix, _ in CONFIGURATIONS:
        pattern = re.compile(r"seed_(\d+)%s\.json$" % suffix)
        found = {}
        for path in pathlib.Path(runs_dir).glob("seed_*.json"):
            match = pattern.fullmatch(path.name)
            if match:
                found[int(match.group(1))] = json.loads(path.read_text())
        if not found or sorted(found) != list(range(1, len(found) + 1)):
            raise ValueError("%s: the runs of %s are not seeds 1..N: %s" % (runs_dir, name, sorted(found)))
        runs[name] = [found[seed] for seed in sorted(found)]
    counts = {len(v) for v in runs.values()}
    if len(counts) != 1:
        raise ValueError("%s: the configurations have different numbers of seeds" % runs_dir)
    return runs


def count(n):
    return "{:,}".format(int(n))


def column(runs):
    """One configuration's cells, by row."""
    failed = [run["seed"] for run in runs if not run["pass"]]
    cells = {}
    cells["result"] = "%d of %d pass%s" % (
        len(runs) - len(failed), len(runs), "; fail: seeds " + ", ".join(map(str, failed)) if failed else "")
    cells["rich phases not recovered within their first half"] = "%s of %s" % (
        count(sum(run["not_recovered"] for run in runs)), count(sum(run["rich_phases_after_poor"] for run in runs)))
    for after in ("constant", "zero"):
        recovered = [run["recovery_after_" + after] for run in runs if run["recovery_after_" + after]]
        medians = [r["median"] for r in recovered]
        largest = max(recovered, key=lambda r: r["max"]) if recovered else None
        cells["recovery after %s input: runs' medians; slowest recovered" % after] = (
            "%s to %s; %s samples" % (count(min(medians)), count(max(medians)), count(largest["max"]))
            if recovered else "-")
    cells["updates / numerical failures / stalled rich phases"] = "%s per run / %s / %s" % (
        count(statistics.median(run["updated"] for run in runs)), count(sum(run["numerical_failures"] for run in runs)),
        count(sum(run["stalled_rich_phases"] for run in runs)))
    cells["smallest eigenvalue of P (every 10,000 samples)"] = "%.1e at the lowest" % min(
        run["smallest_eigenvalue"] for run in runs)
    thetas = [run["largest_abs_theta"] for run in runs]
    plant = runs[0]["plant_largest_abs_theta"]
    cells["largest \\|theta\\| entry: median of the runs; runs above 10 times the plant's; largest"] = (
        "%.3g; %d; %.3g (seed %d); the plant's %.3g" % (
            statistics.median(thetas), sum(t > 10 * plant for t in thetas), max(thetas),
            runs[thetas.index(max(thetas))]["seed"], plant))
    returns = [run["checkpoint_returns"] for run in runs]
    cells["returns to the checkpoint per run: median (fewest to most)"] = "%s (%s to %s)" % (
        count(statistics.median(returns)), count(min(returns)), count(max(returns)))
    swaps = [run["window_counts"]["swaps"] for run in runs if "window_counts" in run]
    cells["window swaps per run: median (fewest to most)"] = "%s (%s to %s)" % (
        count(statistics.median(swaps)), count(min(swaps)), count(max(swaps))) if swaps else "-"
    seconds = [run["seconds"] for run in runs]
    cells["wall time per run (two runs share the two cores)"] = "%.3g to %.3g s" % (min(seconds), max(seconds))
    return cells


def summary(results):
    """The markdown table of a soak.json."""
    columns = [column(results["runs"][name]) for name, _, _ in CONFIGURATIONS]
    header = "| %s seeds, %s samples each | %s |" % (
        len(results["seeds"]), count(results["samples"]), " | ".join(title for _, _, title in CONFIGURATIONS))
    lines = [header, "|---" * (len(CONFIGURATIONS) + 1) + "|"]
    for row in columns[0]:
        lines.append("| %s | %s |" % (row, " | ".join(cells[row] for cells in columns)))
    return "\n".join(lines) + "\n"


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--runs", required=True, help="the folder of bonl_soak --json files")
    parser.add_argument("--json", required=True, type=pathlib.Path, help="write the gathered runs here")
    parser.add_argument("--markdown", required=True, type=pathlib.Path, help="write the table here")
    parser.add_argument("--command", default="tests/soak/report.py", help="what wrote the runs, for the record")
    args = parser.parse_args(argv)
    try:
        runs = gather(args.runs)
    except ValueError as error:
        parser.error(str(error))
    first = runs[CONFIGURATIONS[0][0]][0]
    if any(run["samples"] != first["samples"] for group in runs.values() for run in group):
        parser.error("the runs have different lengths")
    results = {"generated_by": args.command, "samples": first["samples"],
               "seeds": [run["seed"] for run in runs[CONFIGURATIONS[0][0]]], "runs": runs}
    args.json.write_text(json.dumps(results, indent=1) + "\n")
    args.markdown.write_text(summary(results))


if __name__ == "__main__":
    main(sys.argv[1:])
