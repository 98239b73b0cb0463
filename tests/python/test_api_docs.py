"""Every public name of the bonl package has a docstring (scripts/api_reference.sh renders them with
pdoc): the names of each module's __all__ and the public methods and properties of its classes."""

import enum
import importlib
import inspect
import re

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
    return names, returned not in (None, "None", inspect.Signature.empty)


def test_every_public_function_documents_its_parameters_and_what_it_returns():
    """Each public function and method names every parameter in its docstring (a numpydoc section or
    the prose), and one that returns something says what: a Returns section, the word "return", or the
    `-> type` of pybind11's signature line."""
    checked, problems = 0, []
    for name, obj in public_names():
        if isinstance(obj, property) or inspect.isclass(obj) or not callable(obj):
            continue
        doc = inspect.getdoc(obj) or ""
        text = "\n".join(line for line in doc.splitlines()  # the prose, not the signature lines
                         if not re.match(r"(\d+\. )?\w+\(.*\)( -> .*)?$", line))
        parameters, returns = signature_of(obj)
        missing = [p for p in parameters if not re.search(r"\b%s\b" % re.escape(p), text)]
        if missing:
            problems.append(f"{name}: parameters {missing} not described")
        if returns and not re.search(r"(?i)\breturn|->", doc):
            problems.append(f"{name}: what it returns is not said")
        checked += 1
    assert not problems, "\n".join(problems)
    assert checked > 80, checked  # the walk found the package's functions
