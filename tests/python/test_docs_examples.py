"""The examples of the README and of every page under docs/ run as written: each page's fenced blocks in
order, in a scratch directory whose data/ is the repository's. A ```sh block's `python -m bonl`
commands run through the package's command line (the other shell lines, the setup scripts and pip,
are what the CI itself runs); a ```python block runs with exec and must not raise; a ```json block is
a model file that loads; a ```cpp block is compiled against include/ and Eigen without warnings and
run, exit 0. A block that is a fragment (a synopsis of calls on a model the page has already made)
runs after the page's PRELUDE below, which makes the names it assumes."""

import json
import os
import pathlib
import re
import shlex
import shutil
import subprocess
import warnings

import pytest

import bonl
from bonl.__main__ import main

ROOT = pathlib.Path(__file__).resolve().parents[2]
PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").rglob("*.md"))]
IDENTIFYING = {"README.md", "tutorial.md"}  # the pages whose commands identify from a CSV file

MACHINE_PY = """
import numpy as np
import bonl
model = bonl.PseudoHammersteinWiener(3, 2, 8, 3, f=[0.002, 0.06, 0.02, -0.01], p=[-0.003, -0.02, -0.03, 0.015],
                                     b=[1.0, 0.5, 0.2], a=[-1.7, 1.04, -0.238], c=0.1)
model.input_range = (-1.0, 1.0)
r = 0.5 * np.sin(np.linspace(0, 6 * np.pi, 600))
r_ahead, u_applied, y_measured = 0.1, 0.2, 0.01
"""

MACHINE_CPP = """
  bonl::PaperPseudoHammersteinWiener model(3, 2, 8, 3);
  model.set_f((Eigen::VectorXd(4) << 0.002, 0.06, 0.02, -0.01).finished());
  model.set_p((Eigen::VectorXd(4) << -0.003, -0.02, -0.03, 0.015).finished());
  model.set_b((Eigen::VectorXd(3) << 1.0, 0.5, 0.2).finished());
  model.set_a((Eigen::VectorXd(3) << -1.7, 1.04, -0.238).finished());
  model.set_c(0.1);
  model.set_input_range(-1.0, 1.0);
  const auto identified = model;
  const Eigen::VectorXd r = 0.5 * Eigen::VectorXd::LinSpaced(600, 0.0, 6 * 3.141592653589793).array().sin();
  const double r_ahead = 0.1, u_applied = 0.2, y_measured = 0.01;
"""

RECORDS_CPP = MACHINE_CPP.replace("  bonl::PaperPseudoHammersteinWiener model(", "  bonl::PaperPseudoHammersteinWiener machine(").replace(
    "  model.", "  machine.").replace("const auto identified = model;", "") + """
  const Eigen::VectorXd u = bonl::signals::random_levels(4000, 5, 1.0, 1), y = machine.simulate(u);
  const Eigen::VectorXd u1 = u.head(2000), y1 = y.head(2000), u2 = u.tail(2000), y2 = machine.simulate(u2);
  const Eigen::VectorXd u_val = bonl::signals::random_levels(1000, 5, 0.9, 2), y_val = machine.simulate(u_val);
  const Eigen::VectorXd u_past = u_val.head(50), y_past = y_val.head(50), u_rest = u_val.tail(950);
  const bonl::Records<double> records{{u1, y1}, {u2, y2}};
  const double u_k = u[0], y_k = y[0];
"""

#: the names a page's fragments assume, by page and language
PRELUDE = {
    ("control.md", "python"): MACHINE_PY,
    ("control.md", "cpp"): MACHINE_CPP,
    ("use_from_cpp.md", "cpp"): RECORDS_CPP,
}
EIGEN = pathlib.Path("/usr/include/eigen3")


def fenced_blocks(page):
    """(language, text) of every fenced block of a page, in order."""
    return re.findall(r"(?ms)^```(\w*)\n(.*?)^```", page.read_text())


def bonl_commands(script):
    """The `python -m bonl` command lines of a shell block, continuation lines joined."""
    lines = script.replace("\\\n", " ").splitlines()
    return [shlex.split(line.split("#")[0])[3:] for line in lines if line.strip().startswith("python -m bonl ")]


def whole_program(source, prelude):
    """A fragment as a program: its includes first, then its statements in main after the prelude."""
    if "int main(" in source:
        return source, []
    includes = [line for line in source.splitlines() if line.startswith("#include")]
    body = "\n".join(line for line in source.splitlines() if not line.startswith("#include"))
    program = "\n".join(["#include <bonl/bonl.hpp>", "#include <bonl/control.hpp>", *includes,
                          "int main() {", prelude, body, "  return 0;", "}"])
    return program, ["-Wno-unused-variable", "-Wno-unused-but-set-variable"]  # a synopsis names what it makes


def compile_and_run(source, directory, prelude=""):
    compiler = os.environ.get("CXX") or shutil.which("c++")
    if compiler is None or not EIGEN.is_dir():
        pytest.skip("no C++ compiler or Eigen")
    program, flags = whole_program(source, prelude)
    path = directory / "example.cpp"
    path.write_text(program)
    built = subprocess.run([compiler, "-std=c++17", "-O1", "-Wall", "-Wextra", "-Wpedantic", "-Werror", *flags,
                            f"-I{ROOT / 'include'}", f"-I{EIGEN}", str(path), "-o", str(directory / "example")],
                           capture_output=True, text=True)
    assert built.returncode == 0, built.stderr
    ran = subprocess.run([str(directory / "example")], capture_output=True, text=True, timeout=120)
    assert ran.returncode == 0, ran.stderr


EXAMPLE_PAGES = [page for page in PAGES if fenced_blocks(page)]


@pytest.mark.parametrize("page", EXAMPLE_PAGES, ids=[str(page.relative_to(ROOT)) for page in EXAMPLE_PAGES])
def test_the_pages_examples_run_as_written(page, tmp_path, monkeypatch, capsys):
    (tmp_path / "data").symlink_to(ROOT / "data")
    monkeypatch.chdir(tmp_path)
    ran = []
    for language, text in fenced_blocks(page):
        if language == "sh":
            for command in bonl_commands(text):
                assert main(command) == 0, command
                ran.append(command[0])
        elif language == "python":
            scope = {"__name__": "example"}
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")  # the examples' extrapolation warnings are part of their output
                exec(PRELUDE.get((page.name, "python"), ""), scope)
                exec(compile(text, f"{page.name} example", "exec"), scope)
            ran.append("python")
        elif language == "json":
            assert bonl.load_model(text).to_json()
            ran.append("json")
        elif language == "cpp":
            compile_and_run(text, tmp_path, PRELUDE.get((page.name, "cpp"), ""))
            ran.append("cpp")
    assert ran or all(language in ("sh", "text", "cmake") for language, _ in fenced_blocks(page)), page.name
    if page.name not in IDENTIFYING:
        return
    assert "identify" in ran and "python" in ran, f"{page.name}: its identification examples were not found"
    for written in ("model.json", "scores.json", "fit.png", "simulated.csv"):
        assert (tmp_path / written).is_file(), written
    scores = json.loads((tmp_path / "scores.json").read_text())
    (test,), (linear,) = scores["tests"], scores["linear"]["tests"]
    assert test["rms"] < linear["rms"], "the chosen model is not below the linear one on the test"


def test_every_relative_link_of_the_documentation_resolves():
    """A link of the README or of a page under docs/ to a file of the repository points at one that
    exists (the pages move as the documentation is reorganised; anchors are not checked)."""
    pages = [ROOT / "README.md", ROOT / "CHANGELOG.md", *sorted((ROOT / "docs").rglob("*.md"))]
    broken = []
    for page in pages:
        prose = re.sub(r"(?ms)^```.*?^```|`[^`\n]*`", "", page.read_text())  # code is not links
        for target in re.findall(r"\]\(([^)\s]+)\)", prose):
            if re.match(r"[a-z]+:", target) or target.startswith("#") or not re.search(r"[./]", target):
                continue
            if not (page.parent / target.split("#")[0]).exists():
                broken.append(f"{page.relative_to(ROOT)}: {target}")
    assert not broken, "links to nothing:\n" + "\n".join(broken)


def test_the_documentation_names_no_issues():
    """The README, the pages under docs/ and the benchmark report say what things are, not which issue
    asked for them: an issue number belongs in a commit message (CHANGELOG.md takes the history)."""
    texts = [ROOT / "README.md", *sorted((ROOT / "docs").rglob("*.md")), ROOT / "bench" / "RESULTS.md",
             ROOT / "bench" / "RESULTS.json", ROOT / "bench" / "report.py"]
    named = [f"{path.relative_to(ROOT)}: {match.group(0)}" for path in texts
             for match in re.finditer(r"(?i)\bissues? \d+|\(issue\b|(?<![\w&])#\d+\b", path.read_text())]
    assert not named, "issue numbers in the documentation:\n" + "\n".join(named)
