"""The committed type stubs (python/bonl/_bonl/*.pyi) are what pybind11-stubgen generates from the
installed extension: regenerate with

    python -m pybind11_stubgen bonl._bonl -o python --numpy-array-remove-parameters

and commit when this test fails."""

import ast
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


def _mentions_any(annotation):
    """True when an annotation names typing.Any (as ``Any`` or ``typing.Any``), anywhere inside it."""
    return any((isinstance(node, ast.Name) and node.id == "Any") or (isinstance(node, ast.Attribute) and node.attr == "Any")
               for node in ast.walk(annotation))


def _any_in_public_signatures(source, path):
    """Every ``Any`` in the public signatures of a stub: the parameters and the return of each function,
    method and property whose name does not start with ``_`` (and of ``__init__`` and ``__call__``), in a
    class whose name does not start with ``_``, and the annotations of public attributes."""
    found = []

    def visit(body, prefix):
        for node in body:
            if isinstance(node, ast.ClassDef):
                if not node.name.startswith("_"):
                    visit(node.body, f"{prefix}{node.name}.")
            elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                if node.name.startswith("_") and node.name not in ("__init__", "__call__"):
                    continue
                arguments = node.args
                for argument in (*arguments.posonlyargs, *arguments.args, *arguments.kwonlyargs, arguments.vararg,
                                 arguments.kwarg):
                    if argument is not None and argument.annotation is not None and _mentions_any(argument.annotation):
                        found.append(f"{path}:{node.lineno} {prefix}{node.name}({argument.arg}: "
                                     f"{ast.unparse(argument.annotation)})")
                if node.returns is not None and _mentions_any(node.returns):
                    found.append(f"{path}:{node.lineno} {prefix}{node.name} -> {ast.unparse(node.returns)}")
            elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
                if not node.target.id.startswith("_") and _mentions_any(node.annotation):
                    found.append(f"{path}:{node.lineno} {prefix}{node.target.id}: {ast.unparse(node.annotation)}")

    visit(ast.parse(source).body, "")
    return found


def _committed_stubs():
    stubs = ROOT / "python" / "bonl" / "_bonl"
    return {str(p.relative_to(ROOT)): p.read_text() for p in sorted(stubs.rglob("*.pyi"))}


def test_no_public_stub_signature_has_any():
    # Every public function takes and returns named types (numpy.typing.ArrayLike in, NDArray out, the
    # model classes, ...): a py::object argument or return in the bindings shows up here as typing.Any.
    found = [offence for path, source in _committed_stubs().items() for offence in _any_in_public_signatures(source, path)]
    assert not found, "typing.Any in public stub signatures:\n" + "\n".join(found)


def test_no_stub_types_a_1d_array_as_an_eigen_column():
    # Eigen's caster names a VectorXd "[m, 1]", a 2-D shape; 1-D arrays are returned as
    # numpy.typing.NDArray[numpy.float64] (bindings/conversions.hpp's Vector).
    found = [f"{path}:{number}" for path, source in _committed_stubs().items()
             for number, line in enumerate(source.splitlines(), 1) if '"[m, 1]"' in line]
    assert not found, "1-D arrays typed as Eigen columns [m, 1] at " + ", ".join(found)


@pytest.mark.parametrize("source, expected", [
    ("def f(x: typing.Any) -> int: ...", ["f(x: typing.Any)"]),
    ("def f(x: int) -> dict[str, typing.Any]: ...", ["f -> dict[str, typing.Any]"]),
    ("class C:\n    @property\n    def p(self) -> Any: ...", ["C.p -> Any"]),
    ("class C:\n    def __init__(self, *, a: typing.Any = None) -> None: ...", ["C.__init__(a: typing.Any)"]),
    ("x: typing.Any", ["x: typing.Any"]),
    ("def _f(x: typing.Any) -> None: ...", []),
    ("class _C:\n    def f(self, x: typing.Any) -> None: ...", []),
    ("class C:\n    def __eq__(self, other: typing.Any) -> bool: ...", []),
])
def test_the_any_check_finds_any_in_public_signatures_only(source, expected):
    found = [offence.split(" ", 1)[1] for offence in _any_in_public_signatures(source, "stub.pyi")]
    assert found == expected
