# Sourced by scripts/test.sh, scripts/demo.sh and .ci/run: the Debian 12 packages bonl needs
# (doxygen for scripts/api_reference.sh's C++ reference).
BONL_APT_PACKAGES=(build-essential cmake ninja-build libeigen3-dev libsundials-dev catch2 libbenchmark-dev nlohmann-json3-dev python3 python3-pip python3-venv doxygen)
# scripts/fuzz.sh only: clang and its runtimes (libclang_rt.fuzzer, asan, ubsan).
BONL_FUZZ_APT_PACKAGES=(clang-14 libclang-rt-14-dev)

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

# Like bonl_apt_install, but skips apt when dpkg says every package is already installed.
bonl_ensure_deps() {
  local missing=() p
  if ! command -v dpkg-query >/dev/null 2>&1; then
    step "no dpkg-query (not Debian?): assuming the dependencies are installed"
    return
  fi
  for p in "${BONL_APT_PACKAGES[@]}"; do
    [[ $(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null) == installed ]] || missing+=("$p")
  done
  if ((${#missing[@]} == 0)); then
    step "apt packages already installed, skipping apt"
  else
    echo "missing packages: ${missing[*]}"
    bonl_apt_install
  fi
}

# scripts/fuzz.sh: apt-get update + install of BONL_FUZZ_APT_PACKAGES when dpkg says one is missing.
bonl_ensure_fuzz_deps() {
  local missing=() p sudo=()
  [[ $(id -u) -eq 0 ]] || sudo=(sudo)
  if ! command -v dpkg-query >/dev/null 2>&1; then
    step "no dpkg-query (not Debian?): assuming clang-14 and its runtimes are installed"
    return
  fi
  for p in "${BONL_FUZZ_APT_PACKAGES[@]}"; do
    [[ $(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null) == installed ]] || missing+=("$p")
  done
  if ((${#missing[@]} > 0)); then
    step "apt-get install ${missing[*]}"
    "${sudo[@]}" apt-get update
    "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${missing[@]}"
  fi
}

# build/venv with the given PyPI packages and this package installed from the working tree (pip
# install .), as scripts/test.sh, bench/run and scripts/api_reference.sh need it: bonl_venv_install PACKAGE...
bonl_venv_install() {
  [[ -x build/venv/bin/python ]] || python3 -m venv build/venv
  build/venv/bin/python -m pip install -q --disable-pip-version-check "$@"
  build/venv/bin/python -m pip install -q --disable-pip-version-check .
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
