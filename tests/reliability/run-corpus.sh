#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# run-corpus.sh CLI GENERATOR GROUP WORKDIR [TIMEOUT_S]
#
# Generates the corrupt-input corpus of GROUP (vv_corrupt_corpus) in WORKDIR
# and runs `CLI info CASE` and `CLI render CASE -o OUT.png --size 160x120` on
# every case. Each run must
#   - end by itself within TIMEOUT_S seconds (default 20; else: HANG), or
#     the case's own "[limit N s]" (regressions of slow paths),
#   - not die from a signal (CRASH),
#   - exit 0 or 3; with 3, stderr names the case's path; with 0, info prints
#     the path on stdout and render writes the PNG,
#   - leave the input byte-identical (sha256 before / after) and, when render
#     fails, leave no PNG and no temporary file in the output folder.
# Prints one line per run and a summary; exits 1 when any run broke a rule.
# Needs an X display for render (scripts/test runs ctest under xvfb-run).
set -uo pipefail

if (($# < 4)); then
  echo "usage: run-corpus.sh CLI GENERATOR GROUP WORKDIR [TIMEOUT_S]" >&2
  exit 2
fi
cli=$1
generator=$2
group=$3
work=$4
limit=${5:-20}

rm -rf "$work"
mkdir -p "$work/out"
corpus="$work/corpus"

demo_args=()
if [[ "$group" == vtp ]]; then
  # A small demo tree (binary, zlib-compressed, appended data) as a second seed.
  "$cli" demo --generations 1 --voxel-size 2 --seed 3 -o "$work/demo-seed.vtp" >/dev/null ||
    { echo "run-corpus: cannot write the demo seed" >&2; exit 1; }
  demo_args=(--demo "$work/demo-seed.vtp")
fi
"$generator" "$corpus" "$group" "${demo_args[@]}" || { echo "run-corpus: generator failed" >&2; exit 1; }

commands=(info render)
if [[ -z "${DISPLAY:-}" && -z "${WAYLAND_DISPLAY:-}" ]]; then
  echo "run-corpus: no display (DISPLAY unset): skipping the render runs; run under xvfb-run -a"
  commands=(info)
fi

# sha256 of a file, or of every file under a folder (names and contents).
fingerprint() {
  if [[ -d "$1" ]]; then
    (cd "$1" && find . -type f -print0 | LC_ALL=C sort -z | xargs -0 -r sha256sum | sha256sum)
  else
    sha256sum <"$1"
  fi
}

failures=0
slow=()
declare -A tally=()
start=$(date +%s)
while IFS=$'\t' read -r path what; do
  before=$(fingerprint "$path")
  for command in "${commands[@]}"; do
    png="$work/out/out.png"
    rm -f "$png"
    args=("$command" "$path")
    [[ "$command" == render ]] && args+=(-o "$png" --size 160x120)
    t0=$(date +%s%N)
    case_limit=$limit
    [[ "$what" =~ \[limit\ ([0-9]+)\ s\]$ ]] && case_limit=${BASH_REMATCH[1]}
    timeout -k 5 "$case_limit" "$cli" "${args[@]}" >"$work/stdout" 2>"$work/stderr"
    rc=$?
    t1=$(date +%s%N)
    ms=$(((t1 - t0) / 1000000))
    problem=""
    if ((rc == 124 || rc == 137)); then
      problem="HANG (killed after ${case_limit} s)"
    elif ((rc > 128)); then
      problem="CRASH (signal $((rc - 128)))"
    elif ((rc == 3)); then
      grep -qF -- "$path" "$work/stderr" || problem="exit 3 without a message naming the file"
      if [[ "$command" == render ]] && [[ -e "$png" ]]; then
        problem="exit 3 but the PNG was written"
      fi
    elif ((rc == 0)); then
      if [[ "$command" == info ]]; then
        grep -qF -- "$path" "$work/stdout" || problem="exit 0 without the file in the output"
      elif [[ ! -s "$png" ]]; then
        problem="exit 0 but no PNG"
      fi
    else
      problem="exit $rc (expected 0 or 3)"
    fi
    leftovers=$(find "$work/out" -name '.*tmp*' | head -3)
    [[ -n "$leftovers" ]] && problem+="${problem:+; }temporary file left: $leftovers"
    [[ "$(fingerprint "$path")" == "$before" ]] || problem+="${problem:+; }the input changed"
    ((ms > limit * 250)) && slow+=("$command $(basename "$path") ${ms}ms")
    tally[$command-$rc]=$((${tally[$command-$rc]:-0} + 1))
    message=$(head -c 160 "$work/stderr" | head -1)
    if [[ -n "$problem" ]]; then
      failures=$((failures + 1))
      echo "FAIL $command rc=$rc ${ms}ms $path ($what): $problem"
      echo "     stderr: $(head -c 400 "$work/stderr")"
    else
      echo "ok   $command rc=$rc ${ms}ms $(basename "$path") ($what)${message:+ | $message}"
    fi
  done
done <"$corpus/cases.txt"
end=$(date +%s)

cases=$(wc -l <"$corpus/cases.txt")
summary=""
for key in $(printf '%s\n' "${!tally[@]}" | sort); do
  summary+=" $key:${tally[$key]}"
done
((${#slow[@]} > 0)) && echo "slow runs (over a quarter of the time limit): ${slow[*]}"
echo "run-corpus $group: $cases cases, runs by command-exit:$summary; $failures failure(s); $((end - start)) s"
((failures == 0))
