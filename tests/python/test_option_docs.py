"""The estimator's and identify's options are documented once (bindings/option_docs.hpp): identify,
Estimator and control.AdaptiveInverse take their entries from that table. Read from the committed
stubs (test_stubs.py keeps them current): an option reads the same in every docstring that has it,
every keyword option of a signature is documented, and each documented default is the signature's."""

import ast
import pathlib
import re

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
STUBS = ROOT / "python" / "bonl" / "_bonl"


def _functions(path, qualname):
    """The definitions (overloads included) of `qualname` ('identify' or 'Class.method') in a stub."""
    body = ast.parse(path.read_text()).body
    *classes, name = qualname.split(".")
    for class_name in classes:
        body = next(n for n in body if isinstance(n, ast.ClassDef) and n.name == class_name).body
    return [n for n in body if isinstance(n, ast.FunctionDef) and n.name == name]


def _class_doc(path, name):
    return ast.get_docstring(next(n for n in ast.parse(path.read_text()).body if isinstance(n, ast.ClassDef) and n.name == name))


# (what, the stub, the function whose signature has the options, where its docstring is)
TAKERS = {
    "identify": (STUBS / "__init__.pyi", "identify", lambda p: ast.get_docstring(_functions(p, "identify")[0])),
    "Estimator": (STUBS / "__init__.pyi", "Estimator.__init__", lambda p: _class_doc(p, "Estimator")),
    "AdaptiveInverse": (STUBS / "control.pyi", "AdaptiveInverse.__init__", lambda p: _class_doc(p, "AdaptiveInverse")),
}


def _entries(doc):
    """The Parameters section's entries: name -> (type line, text)."""
    section = re.split(r"\n[A-Z][a-z]+\n-{3,}\n", doc.split("Parameters\n----------\n", 1)[1])[0]
    entries, name = {}, None
    for line in section.splitlines():
        if line and not line.startswith(" "):
            if " : " not in line and not re.fullmatch(r"[\w, ]+", line):
                break  # a paragraph after the entries
            name, _, kind = line.partition(" : ")
            entries[name] = (kind, [])
        elif name is not None and line.strip():
            entries[name][1].append(line.strip())
    return {name: (kind, " ".join(text)) for name, (kind, text) in entries.items()}


def _keyword_defaults(path, qualname):
    """The keyword-only arguments of the first definition and their defaults, as Python values."""
    arguments = _functions(path, qualname)[0].args
    return {a.arg: ast.literal_eval(d) for a, d in zip(arguments.kwonlyargs, arguments.kw_defaults)}


SHARED = ["method", "forgetting", "p0"]


@pytest.mark.parametrize("option", SHARED + ["c0", "passes", "trace_ceiling", "recover_after", "backlash_hold"])
def test_an_option_reads_the_same_wherever_it_is_taken(option):
    texts = {what: _entries(doc(path)).get(option) for what, (path, _, doc) in TAKERS.items()}
    given = {what: text for what, text in texts.items() if text is not None}
    assert given, f"{option} is documented nowhere"
    assert len(set(given.values())) == 1, f"{option} is documented differently: {given}"
    if option in SHARED:
        assert len(given) == len(TAKERS), f"{option} is not documented by all of {sorted(TAKERS)}: {sorted(given)}"


@pytest.mark.parametrize("what", sorted(TAKERS))
def test_every_option_is_documented_with_the_signatures_default(what):
    path, qualname, doc = TAKERS[what]
    entries = _entries(doc(path))
    names = {n.strip() for key in entries for n in key.split(",")}
    defaults = _keyword_defaults(path, qualname)
    undocumented = sorted(set(defaults) - names)
    assert not undocumented, f"{what}: options without documentation: {undocumented}"
    for name, (kind, _) in entries.items():
        if name not in defaults:
            continue
        stated = re.search(r"default (.+)$", kind)
        if stated:
            assert ast.literal_eval(stated.group(1)) == defaults[name], f"{what}: {name} : {kind} vs {defaults[name]!r}"
        else:
            assert "optional" in kind and defaults[name] is None, f"{what}: {name} : {kind} vs {defaults[name]!r}"
