"""The committed type stubs (python/bonl/_bonl/*.pyi) are what pybind11-stubgen generates from the
installed extension: regenerate with

    python -m pybind11_stubgen bonl._bonl -o python --numpy-array-remove-parameters

and commit when this test fails."""

import pathlib
import subprocess
import sys

import pytest

import bonl

ROOT = pathlib.Path(__file__).resolve().parents[2]


def test_stubs_are_current(tmp_path):
    subprocess.run(
        [sys.executable, "-m", "pybind11_stubgen", "bonl._bonl", "-o", str(tmp_path),
         "--numpy-array-remove-parameters"],
        check=True, capture_output=True, text=True)
    generated = {p.relative_to(tmp_path): p.read_text() for p in tmp_path.rglob("*.pyi")}
    committed = {p.relative_to(ROOT / "python"): p.read_text() for p in (ROOT / "python" / "bonl" / "_bonl").rglob("*.pyi")}
    assert generated, "pybind11-stubgen generated nothing"
    assert sorted(generated) == sorted(committed), "stub files differ: regenerate them (see this test's docstring)"
    stale = [str(path) for path in generated if generated[path] != committed[path]]
    assert not stale, f"stale stubs: {stale}; regenerate them (see this test's docstring)"


@pytest.mark.parametrize("name", ["experiment", "metrics", "plant"])
def test_the_package_exposes_its_python_modules_not_the_bare_cpp_submodules(name):
    # bonl.<name> is python/bonl/<name>.py (its docstring, its additions), which re-exports the C++
    # submodule bonl._bonl.<name>.
    module = getattr(bonl, name)
    assert module.__name__ == f"bonl.{name}"
    assert module.__file__.endswith(f"{name}.py")
