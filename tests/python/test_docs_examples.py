"""The examples of the README and the tutorial run as written: each page's fenced blocks in order, in a
scratch directory whose data/ is the repository's. A ```sh block's `python -m bonl` commands run
through the package's command line (the other shell lines, the setup scripts and pip, are what the
CI itself runs); a ```python block runs with exec and must not raise; a ```cpp block that is a whole
program (it has a main) is compiled against include/ and Eigen, and must build without warnings and
exit 0."""

import json
import os
import pathlib
import re
import shlex
import shutil
import subprocess
import warnings

import pytest

from bonl.__main__ import main

ROOT = pathlib.Path(__file__).resolve().parents[2]
PAGES = [ROOT / "README.md", ROOT / "docs" / "tutorial.md"]
EIGEN = pathlib.Path("/usr/include/eigen3")


def fenced_blocks(page):
    """(language, text) of every fenced block of a page, in order."""
    return re.findall(r"(?ms)^```(\w*)\n(.*?)^```", page.read_text())


def bonl_commands(script):
    """The `python -m bonl` command lines of a shell block, continuation lines joined."""
    lines = script.replace("\\\n", " ").splitlines()
    return [shlex.split(line.split("#")[0])[3:] for line in lines if line.strip().startswith("python -m bonl ")]


def compile_and_run(source, directory):
    compiler = os.environ.get("CXX") or shutil.which("c++")
    if compiler is None or not EIGEN.is_dir():
        pytest.skip("no C++ compiler or Eigen")
    path = directory / "example.cpp"
    path.write_text(source)
    built = subprocess.run([compiler, "-std=c++17", "-O1", "-Wall", "-Wextra", "-Wpedantic", "-Werror",
                            f"-I{ROOT / 'include'}", f"-I{EIGEN}", str(path), "-o", str(directory / "example")],
                           capture_output=True, text=True)
    assert built.returncode == 0, built.stderr
    ran = subprocess.run([str(directory / "example")], capture_output=True, text=True, timeout=120)
    assert ran.returncode == 0, ran.stderr


@pytest.mark.parametrize("page", PAGES, ids=[page.name for page in PAGES])
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
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")  # the examples' extrapolation warnings are part of their output
                exec(compile(text, f"{page.name} example", "exec"), {"__name__": "example"})
            ran.append("python")
        elif language == "cpp" and "int main(" in text:
            compile_and_run(text, tmp_path)
            ran.append("cpp")
    assert "identify" in ran and "python" in ran, f"{page.name}: its identification examples were not found"
    for written in ("model.json", "scores.json", "fit.png", "simulated.csv"):
        assert (tmp_path / written).is_file(), written
    scores = json.loads((tmp_path / "scores.json").read_text())
    assert scores["test_rms"] < scores["linear"]["test_rms"], "the chosen model is not below the linear one on the test"


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
