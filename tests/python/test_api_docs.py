"""Every public name of the bonl package has a docstring (scripts/api_reference.sh renders them with
pdoc): the names of each module's __all__ and the public methods and properties of its classes."""

import enum
import importlib
import inspect

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
