#!/usr/bin/env bash
# Installs a configured bonl build into a temporary prefix and builds this consumer against it:
#  1. find_package(bonl) + bonl::bonl with SUNDIALS and nlohmann_json disabled: the core needs Eigen only;
#  2. find_package(bonl COMPONENTS io plant experiment) with both found: bonl::io, bonl::plant and
#     bonl::experiment link and run;
#  3. the same with SUNDIALS disabled: the configure must fail, saying that plant needs SUNDIALS.
# Usage: examples/consumer/check.sh <bonl build dir> (scripts/test.sh passes build/ci).
set -euo pipefail
build=$(cd "$1" && pwd)
cd "$(dirname "${BASH_SOURCE[0]}")"
say() { printf '\n--> consumer: %s\n' "$*"; }
# A fixed folder inside the bonl build, not a random one: the compiler cache (scripts/deps.sh) hits
# only on paths that are the same, relative to the clone, from one run to the next.
tmp="$build/consumer_check"
rm -rf "$tmp"
mkdir -p "$tmp"
trap 'rm -rf "$tmp"' EXIT
configure=(cmake -S . -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$tmp/prefix")
no_deps=(-DCMAKE_DISABLE_FIND_PACKAGE_SUNDIALS=ON -DCMAKE_DISABLE_FIND_PACKAGE_nlohmann_json=ON)

say "install $build to a temporary prefix"
cmake --install "$build" --prefix "$tmp/prefix" >/dev/null
targets="$tmp/prefix/lib/cmake/bonl/bonlTargets.cmake"
[[ -f $targets ]] || targets=$(find "$tmp/prefix" -name bonlTargets.cmake -print -quit)
if grep -Eiq 'sundials|nlohmann' "$targets"; then
  echo "FAILED: $targets names SUNDIALS or nlohmann_json" >&2
  exit 1
fi

# CMake then warns that the two CMAKE_DISABLE_FIND_PACKAGE_* were unused: bonl never looked for either.
say "core only (bonl::bonl), SUNDIALS and nlohmann_json disabled"
"${configure[@]}" -B "$tmp/core" "${no_deps[@]}"
cmake --build "$tmp/core" -j2
"$tmp/core/consumer"

say "COMPONENTS io plant experiment (bonl::io, bonl::plant, bonl::experiment)"
"${configure[@]}" -B "$tmp/components" -DBONL_CONSUMER_COMPONENTS=ON
cmake --build "$tmp/components" -j2 --target consumer_components
"$tmp/components/consumer_components"

say "COMPONENTS io plant experiment with SUNDIALS disabled: the configure must fail"
if "${configure[@]}" -B "$tmp/no_sundials" -DBONL_CONSUMER_COMPONENTS=ON \
    -DCMAKE_DISABLE_FIND_PACKAGE_SUNDIALS=ON >"$tmp/no_sundials.log" 2>&1; then
  cat "$tmp/no_sundials.log"
  echo "FAILED: the configure succeeded without SUNDIALS" >&2
  exit 1
fi
# CMake wraps long messages: compare with whitespace squeezed.
if ! tr -s ' \n' '  ' <"$tmp/no_sundials.log" | grep -q 'component plant (bonl::plant) needs SUNDIALS 6'; then
  cat "$tmp/no_sundials.log"
  echo "FAILED: the configure failed, but without saying that plant needs SUNDIALS" >&2
  exit 1
fi
grep -A4 'Reason given by package' "$tmp/no_sundials.log"
say "all three passed"
