# Sourced by scripts/test.sh, scripts/demo.sh and .ci/run: the Debian 12 packages bonl needs
# (doxygen for scripts/api_reference.sh's C++ reference, ccache for the compiler cache below).
BONL_APT_PACKAGES=(build-essential cmake ninja-build libeigen3-dev libsundials-dev catch2 libbenchmark-dev nlohmann-json3-dev python3 python3-pip python3-venv doxygen ccache)
# scripts/fuzz.sh only: clang and its runtimes (libclang_rt.fuzzer, asan, ubsan).
BONL_FUZZ_APT_PACKAGES=(clang-14 libclang-rt-14-dev)
# scripts/sanitize.sh and scripts/figure_spread.sh: clang, its sanitizer runtimes, and the OpenMP
# that Debian's SUNDIALSConfig.cmake looks for.
BONL_CLANG_APT_PACKAGES=(clang-14 libclang-rt-14-dev libomp-14-dev)
# scripts/format.sh only: clang-format for C++, and ruff for Python from PyPI (pinned: its rules
# change between versions), which scripts/test.sh installs into build/venv too.
BONL_FORMAT_APT_PACKAGES=(clang-format-14)
BONL_RUFF=ruff==0.17.6

# The compiler cache: every CMake build the scripts make (build/ci, build/asan, build/fuzz,
# the Python extension's, examples/consumer's, ...) compiles through ccache when it is
# installed; CMake (3.17 and later) reads CMAKE_CXX_COMPILER_LAUNCHER from the environment when it
# first configures a build folder. Paths under the clone are hashed relative to the compiler's
# working folder and that folder itself is not hashed, so a fresh clone in another folder hits
# the objects an earlier clone compiled (the debug information of a hit then names that clone's
# build folder). The cache is in ccache's default folder (~/.cache/ccache, or CCACHE_DIR). An empty
# CMAKE_CXX_COMPILER_LAUNCHER turns the cache off. Set here where ccache is installed already, and
# again by bonl_ensure_deps once it has installed it (on a new machine the first build would
# otherwise compile without the cache and fill nothing).
bonl_use_ccache() {
  if command -v ccache >/dev/null 2>&1 && [[ -z ${CMAKE_CXX_COMPILER_LAUNCHER+set} ]]; then
    export CMAKE_CXX_COMPILER_LAUNCHER=ccache
  fi
}
bonl_use_ccache
CCACHE_BASEDIR=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
export CCACHE_BASEDIR
export CCACHE_NOHASHDIR=1
# The compiler is identified by its contents, not its modification time (which a copied or
# reinstalled toolchain changes without changing the compiler).
export CCACHE_COMPILERCHECK=${CCACHE_COMPILERCHECK:-content}

# Each step prints the wall time since the first script of the run started (the CI's log shows
# where its minutes go); BONL_STEP_T0 is exported so that scripts started by scripts share it.
export BONL_STEP_T0=${BONL_STEP_T0:-$(date +%s)}
step() {
  local elapsed=$(($(date +%s) - BONL_STEP_T0))
  printf '\n==> [%d:%02d] %s\n' $((elapsed / 60)) $((elapsed % 60)) "$*"
}

# apt-get update + install of every package (through sudo when not root).
bonl_apt_install() {
  local sudo=()
  [[ $(id -u) -eq 0 ]] || sudo=(sudo)
  step "apt-get update"
  "${sudo[@]}" apt-get update
  step "apt-get install ${BONL_APT_PACKAGES[*]}"
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive \
    apt-get install -y --no-install-recommends "${BONL_APT_PACKAGES[@]}"
}

# apt-get update + install of the given packages when dpkg says one of them is missing, else no apt
# at all: bonl_ensure_packages PACKAGE... (scripts/fuzz.sh: BONL_FUZZ_APT_PACKAGES, scripts/sanitize.sh:
# BONL_CLANG_APT_PACKAGES, scripts/format.sh: BONL_FORMAT_APT_PACKAGES).
bonl_ensure_packages() {
  local missing=() p sudo=()
  [[ $(id -u) -eq 0 ]] || sudo=(sudo)
  if ! command -v dpkg-query >/dev/null 2>&1; then
    step "no dpkg-query (not Debian?): assuming $* are installed"
    return
  fi
  for p in "$@"; do
    [[ $(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null) == installed ]] || missing+=("$p")
  done
  if ((${#missing[@]} > 0)); then
    step "apt-get install ${missing[*]}"
    "${sudo[@]}" apt-get update
    "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${missing[@]}"
  else
    step "apt packages already installed, skipping apt"
  fi
}

# The packages of BONL_APT_PACKAGES (scripts/test.sh, scripts/demo.sh, ...), as bonl_ensure_packages.
bonl_ensure_deps() {
  bonl_ensure_packages "${BONL_APT_PACKAGES[@]}"
  bonl_use_ccache
}

# build/venv with the given PyPI packages and this package installed from the working tree (pip
# install .), as scripts/test.sh, bench/run and scripts/api_reference.sh need it:
#   bonl_venv_install [--reuse BUILD] PACKAGE...
# The build requirements (pyproject.toml's [build-system] requires) are installed into the venv too
# and the package is built without pip's isolated build environment, whose folder changes at every
# build and so would keep the compiler cache from hitting on pybind11's headers. --reuse BUILD links
# the plant and experiment libraries of that built bonl build folder into the extension instead of
# compiling them again (BONL_REUSE_BUILD in CMakeLists.txt), with warnings as errors.
bonl_venv_install() {
  # Both given every time: the extension's build folder (build/python) keeps its CMake cache.
  local reuse="" werror=OFF
  if [[ ${1:-} == --reuse ]]; then
    reuse="$PWD/$2" werror=ON
    shift 2
  fi
  local config=(--config-settings=cmake.define.BONL_REUSE_BUILD="$reuse"
                --config-settings=cmake.define.BONL_WARNINGS_AS_ERRORS="$werror")
  [[ -x build/venv/bin/python ]] || python3 -m venv build/venv
  local build_requires
  mapfile -t build_requires < <(build/venv/bin/python -c \
    'import tomllib; print("\n".join(tomllib.load(open("pyproject.toml", "rb"))["build-system"]["requires"]))')
  build/venv/bin/python -m pip install -q --disable-pip-version-check "${build_requires[@]}" "$@"
  build/venv/bin/python -m pip install -q --disable-pip-version-check --no-build-isolation "${config[@]}" .
}

# Configures build/examples (Release, examples only) and builds one example target, for the scripts
# that run an example: bonl_build_example TARGET.
bonl_build_example() {
  step "configure (build/examples)"
  cmake -S . -B build/examples -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DBONL_BUILD_TESTS=OFF -DBONL_BUILD_BENCH=OFF -DBONL_BUILD_DEMO=OFF -DBONL_BUILD_EXAMPLES=ON
  step "build $1"
  cmake --build build/examples -j2 --target "$1"
}

# Runs a results script (examples/.../NAME.py --json --markdown) and splices its table into PAGE:
#   bonl_results_script NAME SCRIPT PAGE [--quick]
# writes docs/results/NAME.json and NAME_summary.md; with --quick (the CI's smoke run) into a temporary
# folder and a copy of PAGE, so that nothing committed is touched. Fails when the table did not land.
bonl_results_script() {
  local name=$1 script=$2 page=$3 results=docs/results quick=()
  case ${4:-} in
    --quick)
      quick=(--quick)
      local tmp
      tmp=$(mktemp -d)
      # shellcheck disable=SC2064 # the folder is known now
      trap "rm -rf '$tmp'" EXIT
      results=$tmp
      cp "$page" "$tmp/$(basename "$page")"
      page=$tmp/$(basename "$page") ;;
    "") ;;
    *) echo "usage: bash scripts/$name.sh [--quick]" >&2; return 2 ;;
  esac
  local python=${PYTHON:-build/venv/bin/python}
  step "$script ${quick[*]}"
  "$python" "$script" --json "$results/$name.json" --markdown "$results/${name}_summary.md" "${quick[@]}"
  bonl_splice_summary "${name}_summary" "$results/${name}_summary.md" "$page"
  "$python" -c 'import sys; sys.exit(open(sys.argv[1]).read() not in open(sys.argv[2]).read())' \
    "$results/${name}_summary.md" "$page" ||
    { echo "$name.sh: the table was not spliced into $page" >&2; return 1; }
  step "wrote $results/$name.json and ${name}_summary.md, updated $page"
}

# Replaces what stands between the NAME markers of PAGE (<!-- NAME: begin ... --> and
# <!-- NAME: end -->) with the contents of FILE: bonl_splice_summary NAME FILE PAGE...
# tests/python/test_published_figures.py checks that the copies match their results file.
bonl_splice_summary() {
  local name=$1 file=$2 page
  shift 2
  for page in "$@"; do
    awk -v summary="$file" -v name="$name" '
      index($0, "<!-- " name ": begin") { print; while ((getline line < summary) > 0) print line; close(summary); skip = 1; next }
      index($0, "<!-- " name ": end") { skip = 0 }
      !skip { print }' "$page" > "$page.tmp" && mv "$page.tmp" "$page"
  done
}
