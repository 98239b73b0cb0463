"""Every public name of the bonl package has a docstring (scripts/api_reference.sh renders them with
pdoc): the names of each module's __all__ and the public methods and properties of its classes; and
every public function and method has numpydoc Parameters and Returns sections where it takes
parameters or returns something."""

import ast
import enum
import importlib
import inspect
import re
import textwrap

MODULES = ["bonl", "bonl.control", "bonl.experiment", "bonl.metrics", "bonl.plant"]
# What pybind11 and enum give every enumeration, documented by them and not by bonl.
GENERATED = {"name", "value"}


def public_names():
    """(qualified name, object) for every public name of MODULES and every public member of their
    classes."""
    for module_name in MODULES:
        module = importlib.import_module(module_name)
        for name in module.__all__:
            obj = getattr(module, name)
            if inspect.ismodule(obj):
                continue
            yield f"{module_name}.{name}", obj
            if inspect.isclass(obj) and not issubclass(obj, BaseException):
                for member_name, member in vars(obj).items():
                    if member_name.startswith("_") or member_name in GENERATED:
                        continue
                    if isinstance(member, type(obj)) or isinstance(member, enum.Enum):
                        continue  # an enumeration's values: their class is documented
                    if isinstance(member, (staticmethod, classmethod)):
                        member = member.__func__  # the function, not the wrapper (whose docstring is Python's)
                    yield f"{module_name}.{name}.{member_name}", member


def test_every_public_name_has_a_docstring():
    names = list(public_names())
    missing = [name for name, obj in names if not (inspect.getdoc(obj) or "").strip()]
    assert not missing, "no docstring: " + ", ".join(missing)
    # The walk found the package's names (it cannot pass on an empty list): some 450 today.
    assert len(names) > 300, len(names)


def signature_of(function):
    """(parameter names, whether it returns something) of a public function or method: from Python's
    signature, or from the first line pybind11 writes, `name(self: T, x: float, ...) -> R`."""
    try:
        signature = inspect.signature(function)
    except (TypeError, ValueError):
        doc = inspect.getdoc(function) or ""
        # One line per overload ("1. name(...) -> R") after "name(*args, **kwargs)", or one line.
        lines = [line.split(". ", 1)[1] for line in doc.splitlines() if re.match(r"\d+\. \w+\(", line)] or doc.splitlines()[:1]
        names, returns = [], False
        for line in lines:
            match = re.match(r"\w+\((.*)\)\s*->\s*(.+)", line)
            assert match, f"no signature line: {line!r}"
            arguments = re.split(r",\s*(?![^\[]*\])", match.group(1))
            names += [a.split(":")[0].strip() for a in arguments if a.strip() and not a.strip().startswith("*")]
            returns = returns or match.group(2).strip() != "None"
        return [n for n in dict.fromkeys(names) if n != "self"], returns
    names = [name for name, p in signature.parameters.items()
             if name not in ("self", "cls") and p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD)]
    returned = signature.return_annotation
    if returned is inspect.Signature.empty:
        return names, returns_a_value(function)
    return names, returned not in (None, "None")


def returns_a_value(function):
    """Whether a function without a return annotation returns something: a `return` with a value
    (not None) or a `yield` in its own body."""
    try:
        source = textwrap.dedent(inspect.getsource(function))
    except (OSError, TypeError):
        return False
    nodes = list(ast.iter_child_nodes(ast.parse(source).body[0]))
    while nodes:
        node = nodes.pop()
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda, ast.ClassDef)):
            continue  # a nested function's returns are its own
        if isinstance(node, (ast.Yield, ast.YieldFrom)):
            return True
        if isinstance(node, ast.Return) and node.value is not None and not (
                isinstance(node.value, ast.Constant) and node.value.value is None):
            return True
        nodes.extend(ast.iter_child_nodes(node))
    return False


def numpydoc_section(doc, title):
    """The body of a numpydoc section (`title` underlined with dashes), or None where there is none."""
    match = re.search(r"^%s\n-{3,}\n(.*?)(?=^\w[\w ]*\n-{3,}$|\Z)" % title, doc, re.M | re.S)
    return match.group(1) if match else None


def test_every_public_function_has_parameters_and_returns_sections():
    """Each public function and method that takes parameters has a numpydoc Parameters section naming
    every one of them, and each that returns something a Returns (or Yields) section."""
    checked, problems = 0, []
    for name, obj in public_names():
        if isinstance(obj, property) or inspect.isclass(obj) or not callable(obj):
            continue
        doc = inspect.getdoc(obj) or ""
        parameters, returns = signature_of(obj)
        section = numpydoc_section(doc, "Parameters")
        if parameters and section is None:
            problems.append(f"{name}: no Parameters section")
        elif parameters:
            described = set(re.findall(r"^(\w+(?:, \w+)*)(?: :|$)", section, re.M))
            names = {n for entry in described for n in entry.split(", ")}
            missing = [p for p in parameters if p not in names]
            if missing:
                problems.append(f"{name}: {missing} not in its Parameters section")
        if returns and numpydoc_section(doc, "Returns") is None and numpydoc_section(doc, "Yields") is None:
            problems.append(f"{name}: no Returns section")
        checked += 1
    assert not problems, f"{len(problems)} problems:\n" + "\n".join(problems)
    assert checked > 80, checked
