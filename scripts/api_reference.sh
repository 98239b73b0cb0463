#!/usr/bin/env bash
# Builds the API reference, offline, warnings as errors: the C++ headers' comments and the
# documentation's pages (docs/) with Doxygen (docs/api/Doxyfile) into build/api/cpp, and the
# installed Python package's docstrings with pdoc into build/api/python. Fails on an undocumented
# public C++ class or member, a function's undocumented parameter or return value, a broken comment,
# or a warning from pdoc. The Python package and pdoc come from build/venv (made here when
# scripts/test.sh has not made it), or
#   PYTHON=/path/to/python scripts/api_reference.sh
# with bonl and pdoc importable by that interpreter.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source scripts/deps.sh
python=${PYTHON:-build/venv/bin/python}

# One command from a fresh clone: the packages (doxygen among them), and, unless PYTHON names an
# interpreter of one's own, build/venv with the package and pdoc as scripts/test.sh makes it.
bonl_ensure_deps
if [[ -z ${PYTHON:-} ]] && ! build/venv/bin/python -c 'import bonl, pdoc' 2>/dev/null; then
  step "Python: the package and pdoc in build/venv"
  bonl_venv_install numpy pdoc==16.0.0
fi
command -v doxygen >/dev/null || { echo "api_reference: doxygen is not installed (scripts/deps.sh)" >&2; exit 1; }
"$python" -c 'import bonl, pdoc' || {
  echo "api_reference: $python cannot import bonl and pdoc (scripts/test.sh installs both)" >&2
  exit 1
}

step "C++ reference: doxygen docs/api/Doxyfile -> build/api/cpp"
rm -rf build/api/cpp
mkdir -p build/api  # Doxygen makes OUTPUT_DIRECTORY's last level only, not build/ in a fresh clone
BONL_VERSION=$(sed -n 's/^#define BONL_VERSION_\(MAJOR\|MINOR\|PATCH\) //p' include/bonl/version.hpp | paste -sd.) \
  doxygen docs/api/Doxyfile

step "Python reference: pdoc bonl -> build/api/python"
rm -rf build/api/python
# pdoc reports a docstring it cannot render or a module it cannot import as a Python warning: -W
# error makes it fail. Any other output (pdoc writes nothing on success) fails too.
log=$(mktemp)
trap 'rm -f "$log"' EXIT
if ! "$python" -W error -m pdoc --docformat numpy --no-show-source -o build/api/python bonl >"$log" 2>&1 || [[ -s $log ]]; then
  cat "$log" >&2
  echo "api_reference: pdoc failed or warned" >&2
  exit 1
fi
step "API reference in build/api/cpp/index.html and build/api/python/index.html"
