#!/usr/bin/env bash
# Formats the tree, or checks it (--check: exits 1 and lists what differs, changes nothing):
#   C++    clang-format-14 with .clang-format, on the tracked *.hpp, *.cpp, *.h;
#   Python ruff (ruff.toml, build/venv's ruff): `ruff check --fix` applies its safe fixes, --check
#          runs `ruff check`. ruff's formatter is not used (ruff.toml says why).
#
#   bash scripts/format.sh [--check] [--cpp | --python]   (default: both)
#
# The CI (.ci/run) runs `--check`.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source scripts/deps.sh

check=false
languages=(cpp python)
while (($#)); do
  case "$1" in
    --check) check=true ;;
    --cpp) languages=(cpp) ;;
    --python) languages=(python) ;;
    -h | --help) sed -n '2,9p' "$0"; exit 0 ;;
    *) echo "format.sh: unknown argument $1 (see --help)" >&2; exit 2 ;;
  esac
  shift
done

status=0
for language in "${languages[@]}"; do
  if [[ $language == cpp ]]; then
    bonl_ensure_packages "${BONL_FORMAT_APT_PACKAGES[@]}"
    mapfile -t files < <(git ls-files '*.hpp' '*.cpp' '*.h')
    if $check; then
      step "clang-format-14 --dry-run -Werror (${#files[@]} files)"
      clang-format-14 --style=file --dry-run -Werror "${files[@]}" || status=1
    else
      step "clang-format-14 -i (${#files[@]} files)"
      clang-format-14 --style=file -i "${files[@]}"
    fi
  else
    if ! build/venv/bin/ruff --version >/dev/null 2>&1; then
      [[ -x build/venv/bin/python ]] || python3 -m venv build/venv
      build/venv/bin/python -m pip install -q --disable-pip-version-check "$BONL_RUFF"
    fi
    if $check; then
      step "ruff check"
      build/venv/bin/ruff check --no-cache . || status=1
    else
      step "ruff check --fix"
      build/venv/bin/ruff check --no-cache --fix . || status=1
    fi
  fi
done
exit "$status"
