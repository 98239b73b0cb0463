"""What the fuzz_model_json target starts from covers every model: its libFuzzer dictionary
(fuzz/model_json.dict) holds each model's name and every key of its files (its orders, its
parameters, the operating point and the input range), read from the known systems' model files of
every model (tests/data) and from the seeds, and its committed seeds (fuzz/corpus/fuzz_model_json)
hold a file of every model and of every format version, each of which loads. A new model's keys and
files reach the fuzzer without anyone remembering them."""

import json
import pathlib

import bonl
from conftest import KNOWN_SYSTEMS

FUZZ = pathlib.Path(__file__).resolve().parents[2] / "fuzz"
DICTIONARY = FUZZ / "model_json.dict"
SEEDS = FUZZ / "corpus" / "fuzz_model_json"


def _entries():
    """The dictionary's entries, decoded: a line `"\\"ARX\\""` is the token `"ARX"`."""
    entries = set()
    for line in DICTIONARY.read_text().splitlines():
        if line.startswith('"') and line.endswith('"'):
            entries.add(json.loads(line))
    return entries


def _keys(document):
    """Every object key of a JSON document, at any depth."""
    if isinstance(document, dict):
        for key, value in document.items():
            yield key
            yield from _keys(value)
    elif isinstance(document, list):
        for value in document:
            yield from _keys(value)


def test_the_fuzz_dictionary_holds_every_models_name_and_every_key_of_its_files():
    systems = json.loads(KNOWN_SYSTEMS.read_text())
    documents = [document for name in ("paper_orders", "small") for document in systems[name].values()]
    documents += [json.loads(path.read_text()) for path in sorted(SEEDS.glob("*.json"))]
    assert {document["model"] for document in documents} == {model.__name__ for model in bonl.MODELS}
    words = {document["model"] for document in documents} | {key for d in documents for key in _keys(d)}
    entries = _entries()
    missing = sorted(word for word in words if json.dumps(word) not in entries)
    assert not missing, "fuzz/model_json.dict lacks " + ", ".join(missing)


def test_the_fuzz_seeds_hold_a_model_file_of_every_model_and_of_every_format_version():
    texts = [path.read_text() for path in sorted(SEEDS.glob("*.json"))]
    loaded = [bonl.load_model(text) for text in texts]
    assert {type(model).__name__ for model in loaded} == {model.__name__ for model in bonl.MODELS}
    # The version this bonl writes is the newest it reads; every one from 1 on has a seed.
    newest = json.loads(bonl.MODELS[0](na=1, nb=0, nk=0).to_json())["version"]
    assert {json.loads(text)["version"] for text in texts} == set(range(1, newest + 1))
