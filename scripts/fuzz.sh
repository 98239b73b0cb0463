#!/usr/bin/env bash
# The libFuzzer targets (fuzz/, docs/lab/fuzzing.md): builds them with clang-14 into build/fuzz
# (ASan + UBSan, -fno-sanitize-recover=all, leak detection on) and runs each one.
#
#   bash scripts/fuzz.sh [--quick | --runs N | --seconds S] [target ...]
#
#   --quick      (the default; CI) 10 s per target, -seed=1, on a temporary corpus seeded from the
#                committed fuzz/corpus/<target>/ (which is only read).
#   --runs N     exactly N executions per target, -seed=1.
#   --seconds S  S seconds per target, -seed=1.
# The long modes keep what they find in build/fuzz/corpus/<target>/ (not committed) and start from
# it next time, together with the committed seeds. Targets: fuzz_model_json, fuzz_plant_parameters,
# fuzz_estimator_update, fuzz_inverse_model (default: all four). A crash, a sanitizer report, a leak, a timeout (10 s
# for one input) or a violated invariant is a finding: the input is saved under
# build/fuzz/findings/<target>/, the log under build/fuzz/logs/, and the script exits 1 after
# running the remaining targets.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source scripts/deps.sh

mode=quick
amount=10
targets=()
while (($#)); do
  case "$1" in
    --quick) mode=quick; amount=10 ;;
    --runs) mode=runs; amount="${2:?--runs needs a number}"; shift ;;
    --seconds) mode=seconds; amount="${2:?--seconds needs a number}"; shift ;;
    fuzz_model_json | fuzz_plant_parameters | fuzz_estimator_update | fuzz_inverse_model) targets+=("$1") ;;
    -h | --help) sed -n '2,18p' "$0"; exit 0 ;;
    *) echo "fuzz.sh: unknown argument $1 (see --help)" >&2; exit 2 ;;
  esac
  shift
done
[[ $amount =~ ^[0-9]+$ && $amount -gt 0 ]] || { echo "fuzz.sh: expected a positive integer, got $amount" >&2; exit 2; }
((${#targets[@]})) || targets=(fuzz_model_json fuzz_plant_parameters fuzz_estimator_update fuzz_inverse_model)

bonl_ensure_deps
bonl_ensure_packages "${BONL_FUZZ_APT_PACKAGES[@]}"

# Milliseconds since the epoch, and a duration in seconds with one decimal (no bc on a bare machine).
now_ms() { echo $(($(date +%s%N) / 1000000)); }
seconds_since() { local ms=$(($(now_ms) - $1)); printf '%d.%d' $((ms / 1000)) $((ms % 1000 / 100)); }

build=build/fuzz
start=$(now_ms)
step "configure + build ($build): clang-14, libFuzzer + ASan + UBSan"
if [[ ! -f $build/build.ninja ]]; then
  cmake -S fuzz -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++-14
fi
cmake --build "$build" -j2
build_seconds=$(seconds_since "$start")

# Largest input per target: JSON documents up to 4 KiB; the parameter and estimator inputs are
# decoded into a few dozen numbers, or a few hundred samples.
declare -A max_len=([fuzz_model_json]=4096 [fuzz_plant_parameters]=1024 [fuzz_estimator_update]=512 [fuzz_inverse_model]=512)
declare -A extra=([fuzz_model_json]="-dict=fuzz/model_json.dict")

export ASAN_OPTIONS="detect_leaks=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"
if command -v llvm-symbolizer-14 >/dev/null 2>&1; then export ASAN_SYMBOLIZER_PATH=${ASAN_SYMBOLIZER_PATH:-$(command -v llvm-symbolizer-14)}; fi

mkdir -p "$build/logs"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
status=0
summary=()
for target in "${targets[@]}"; do
  case "$mode" in
    quick) corpus="$tmp/$target"; limit=(-max_total_time="$amount") ;;
    seconds) corpus="$build/corpus/$target"; limit=(-max_total_time="$amount") ;;
    runs) corpus="$build/corpus/$target"; limit=(-runs="$amount") ;;
  esac
  findings="$build/findings/$target"
  log="$build/logs/$target.log"
  mkdir -p "$corpus" "$findings"
  step "$target: $mode $amount"
  t0=$(now_ms)
  # The first directory receives new inputs; the committed seeds are only read.
  # shellcheck disable=SC2086
  if "$build/$target" -seed=1 "${limit[@]}" -max_len="${max_len[$target]}" -timeout=10 -rss_limit_mb=2048 \
      -print_final_stats=1 -artifact_prefix="$findings/" ${extra[$target]:-} "$corpus" "fuzz/corpus/$target" \
      >"$log" 2>&1; then
    result=ok
  else
    result="FINDING (exit $?, see $log and $findings/)"
    status=1
    tail -n 60 "$log"
  fi
  wall=$(seconds_since "$t0")
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  rss=$(sed -n 's/^stat::peak_rss_mb: *//p' "$log" | tail -1)
  last=$(grep -E '^#[0-9]+' "$log" | tail -1 | grep -oE 'cov: [0-9]+ ft: [0-9]+ corp: [0-9]+/[0-9]+[a-zA-Z]*' || true)
  line=$(printf '%-22s %s: %s execs, %s exec/s, %s s, %s, peak rss %s MB' "$target" "$result" "${execs:-?}" \
    "${rate:-?}" "$wall" "${last:-no status line}" "${rss:-?}")
  echo "$line"
  summary+=("$line")
done

step "summary ($mode $amount per target; build $build_seconds s, total $(seconds_since "$start") s)"
printf '%s\n' "${summary[@]}"
exit "$status"
