#!/usr/bin/env bash
# Builds and runs every C++ test, installs bonl and builds examples/consumer against it (core
# alone with Eigen only, then the io and plant components), then
# builds the Python package into build/venv and runs pytest. The venv also gets pdoc, for
# scripts/api_reference.sh.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source scripts/deps.sh
bonl_ensure_deps

# The benchmarks are built here too, and run once in a smoke mode (ctest's bench/smoke/*, pytest's
# test_bench.py: every benchmark for a millisecond, figures not judged), so that one that throws or
# no longer builds fails the CI; bench/run measures them.
# The suites at -O2 (BONL_TEST_CXX_FLAGS); compiled_once's heavy templates, the plant and the
# benchmarks stay at -O3: docs/lab/performance.md, "The CI's build time".
step "configure (build/ci)"
cmake -S . -B build/ci -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DBONL_BUILD_TESTS=ON -DBONL_BUILD_BENCH=ON -DBONL_WARNINGS_AS_ERRORS=ON -DBONL_TEST_CXX_FLAGS=-O2

step "build"
cmake --build build/ci -j2

step "ctest"
status=0
ctest --test-dir build/ci --output-on-failure --no-tests=error -j2 || status=1
bash scripts/check_test_discovery.sh build/ci || status=1

step "install to a temporary prefix, build and run examples/consumer against it"
# bonl::bonl with SUNDIALS and nlohmann_json disabled (Eigen only); COMPONENTS io plant; and
# COMPONENTS plant without SUNDIALS, which must fail to configure with a clear message.
bash examples/consumer/check.sh build/ci

step "Python: build and install the package in a virtual environment (build/venv)"
# The extension links build/ci's plant and experiment libraries rather than compiling them again.
bonl_venv_install --reuse build/ci numpy scipy matplotlib pytest pybind11-stubgen==3.0.0 "dask[distributed]" tqdm padasip pdoc==16.0.0 "$BONL_RUFF"

step "pytest"
pytest_status=0
BONL_MODEL_TOOL="$PWD/build/ci/tests/bonl_model_tool" BONL_BENCH_DIR="$PWD/build/ci/bench" build/venv/bin/python -m pytest tests/python -q -p no:cacheprovider || pytest_status=$?
# pytest exits 5 when it collected nothing: that is a failure here too.
((pytest_status == 0)) || status=1

if ((status != 0)); then
  step "FAILED: some tests failed (see the ctest and pytest summaries above)"
  exit 1
fi
step "all passed"
