#!/usr/bin/env bash
# How far the committed figures move when the extension is built by another compiler: builds it with
# $SPREAD_CXX (clang++-14 unless set) and $SPREAD_CXXFLAGS (none unless set) into build/venv-spread
# (its own build folder, build/python-spread), recomputes every figure the committed-figure tests
# compare with build/venv's gcc build (scripts/test.sh) and with that one
# (tests/python/figure_spread.py), and prints the largest relative difference per family.
# tests/python/figures.py's FIGURE_REL, the tests' tolerance, rests on it: re-run this when the
# compiler, the platform or the numerics change. About 10 minutes on 2 cores (the build, 9 of them,
# then 40 s per set of figures).
#
#   bash scripts/figure_spread.sh [--quick]
#
# --quick (the CI's smoke run, 4 s): no second build; build/venv's figures of the two cheapest
# families against themselves, through the same lines, which must be bit-equal (a run that differs
# from itself is nondeterministic, and the tolerance assumes it is not).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source scripts/deps.sh

case ${1:-} in
  --quick) quick=1 ;;
  "") quick=0 ;;
  *) echo "usage: bash scripts/figure_spread.sh [--quick]" >&2; exit 2 ;;
esac
gcc=build/venv/bin/python
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

if ((quick)); then
  other=$gcc families=(--families joint_angle,tracking) limit=(--max 0)
else
  bonl_ensure_packages "${BONL_CLANG_APT_PACKAGES[@]}"
  cxx=${SPREAD_CXX:-clang++-14}
  step "build the extension with $cxx ${SPREAD_CXXFLAGS:-} into build/venv-spread"
  [[ -x build/venv-spread/bin/python ]] || python3 -m venv build/venv-spread
  other=build/venv-spread/bin/python
  mapfile -t build_requires < <("$other" -c \
    'import tomllib; print("\n".join(tomllib.load(open("pyproject.toml", "rb"))["build-system"]["requires"]))')
  # numpy, scipy and pytest: what the recomputed figures import (the EMPS's records, the tests' helpers).
  "$other" -m pip install -q --disable-pip-version-check "${build_requires[@]}" numpy scipy pytest
  # A fresh build folder each time: CMake keeps the compiler a folder was first configured with.
  rm -rf build/python-spread
  CXX=$cxx "$other" -m pip install -q --disable-pip-version-check --no-build-isolation \
    --config-settings=build-dir=build/python-spread \
    --config-settings=cmake.define.CMAKE_CXX_FLAGS="${SPREAD_CXXFLAGS:-}" .
  families=() limit=()
fi

step "the figures with build/venv (gcc)"
"$gcc" tests/python/figure_spread.py --json "$out/gcc.json" "${families[@]}"
step "the figures with $other"
"$other" tests/python/figure_spread.py --json "$out/other.json" "${families[@]}"
step "largest relative difference per family"
"$gcc" tests/python/figure_spread.py --compare "$out/gcc.json" "$out/other.json" "${limit[@]}"
