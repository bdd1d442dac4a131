#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# no-network.sh CLI WORKDIR
#
# The application opens no network connection (issue 9, patient data):
#  1. `demo`, `info` and `render` work in a network namespace of their own
#     (`unshare -n`: only a loopback interface that is down);
#  2. under `strace -f -e trace=socket`, the same commands create no socket
#     of any family but AF_UNIX (the X display, name-service lookups):
#     in particular no AF_INET / AF_INET6 socket.
# Exits 77 (ctest: skipped) with a message when unshare / strace cannot run
# here; render needs an X display (scripts/test runs ctest under xvfb-run).
set -uo pipefail

if (($# < 2)); then
  echo "usage: no-network.sh CLI WORKDIR" >&2
  exit 2
fi
cli=$1
work=$2
rm -rf "$work"
mkdir -p "$work"
failures=0
ran=0

fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}

if [[ -z "${DISPLAY:-}" ]]; then
  echo "SKIP: no X display for render (run under xvfb-run -a)"
  exit 77
fi

commands=(
  "demo --generations 2 --voxel-size 1 --seed 5 -o $work/demo.vtp"
  "info $work/demo.vtp"
  "render $work/demo.vtp -o $work/demo.png --size 320x240"
)

# 1. In a network namespace without any usable interface.
if unshare -n true 2>/dev/null; then
  ran=$((ran + 1))
  for c in "${commands[@]}"; do
    # shellcheck disable=SC2086  # the command line is split on purpose
    if ! timeout 120 unshare -n "$cli" $c >"$work/out" 2>"$work/err"; then
      fail "unshare -n vesselview-cli $c: $(cat "$work/err")"
    fi
  done
  [[ -s "$work/demo.png" ]] || fail "render under unshare -n wrote no PNG"
  echo "unshare -n: demo, info and render work without a network"
else
  echo "note: unshare -n is not permitted here (needs root or user namespaces); part 1 skipped"
fi

# 2. No socket but AF_UNIX.
if command -v strace >/dev/null && strace -f -qq -e trace=socket -o /dev/null true 2>/dev/null; then
  ran=$((ran + 1))
  rm -f "$work/demo.png"
  for c in "${commands[@]}"; do
    log="$work/strace-${c%% *}.log"
    # LeakSanitizer cannot run under ptrace (sanitizer builds): leaks are checked elsewhere.
    # shellcheck disable=SC2086
    if ! ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" timeout 120 strace -f -qq -e trace=socket -o "$log" "$cli" $c >"$work/out" 2>"$work/err"; then
      fail "strace vesselview-cli $c: $(cat "$work/err")"
      continue
    fi
    families=$(grep -o 'socket(AF_[A-Z0-9]*' "$log" | sort | uniq -c | tr -s ' ' | paste -sd, -)
    echo "strace ${c%% *}: socket calls by family: ${families:-none}"
    if grep -E 'socket\(AF_INET6?,' "$log"; then
      fail "${c%% *} created an internet socket"
    fi
    if grep -v 'socket(AF_UNIX' "$log" | grep -E 'socket\(' ; then
      fail "${c%% *} created a socket that is not AF_UNIX"
    fi
  done
  [[ -s "$work/demo.png" ]] || fail "render under strace wrote no PNG"
else
  echo "note: strace is not installed or not permitted (ptrace); part 2 skipped"
fi

if ((ran == 0)); then
  echo "SKIP: neither unshare -n nor strace can run here"
  exit 77
fi
if ((failures > 0)); then
  echo "no-network: $failures failure(s)"
  exit 1
fi
echo "no-network: ok ($ran check(s))"
