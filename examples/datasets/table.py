"""The Markdown table of every data set's results file (docs/results/datasets/*.json): the test RMS
of each model family's chosen structure, with the published figures beside it.

    python examples/datasets/table.py docs/results/datasets/*.json > docs/results/datasets_summary.md
"""

import json
import pathlib
import sys


def _figure(value):
    return f"{value:.3g}" if abs(value) < 1e3 else f"{value:.3g} (diverges)"


def table(results):
    tests = [test["name"] for test in results["tests"]]
    lines = [f"**{results['data_set']}** (test RMS, {results['unit']})", "",
             "| model | orders chosen | " + " | ".join(tests) + " |",
             "|---|---|" + "---|" * len(tests)]
    for row in results["rows"]:
        orders = " ".join(f"{k}={v}" for k, v in row["orders"].items())
        options = ", ".join(f"{k}={v}" for k, v in row.get("identify", {}).items())
        rest = row.get("test_rms_from_rest", {})
        cells = [_figure(row["test_rms"][name]) + (f" (from rest {_figure(rest[name])})" if name in rest else "")
                 for name in tests]
        lines.append(f"| {row['model']} | {orders}{', ' + options if options else ''} | " + " | ".join(cells) + " |")
    for family, why in results.get("no_model", {}).items():
        lines.append(f"| {family} | none chosen: {why} |" + " |" * len(tests))
    if any(test["window"] for test in results["tests"]):
        lines += ["", "(from rest: the same samples with the whole test record simulated from rest at the "
                  "operating point instead of after the initial-state window)"]
    published = results["published"]
    lines += ["", "Published: " + ("; ".join(f"{what}: {figure}" for what, figure in published) if published
                                    else "none in SOURCE.md for this split") + "."]
    return "\n".join(lines)


def main(paths):
    print("\n\n".join(table(json.loads(pathlib.Path(p).read_text())) for p in paths))


if __name__ == "__main__":
    main(sys.argv[1:])
