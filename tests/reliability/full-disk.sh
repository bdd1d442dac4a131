#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# full-disk.sh CLI WORKDIR
#
# Outputs on a full disk (issue 9): in a private mount namespace, a 64 KiB
# tmpfs is mounted on WORKDIR/tiny and nearly filled; then
#   render DEMO -o tiny/out.png   (out.png exists: must stay byte-identical)
#   render DEMO -o tiny/new.png   (must not appear)
#   demo -o tiny/x.vtp            (x.vtp exists: must stay byte-identical)
#   demo -o tiny/y.vtp            (must not appear)
# must each exit 4 with a message that names the file and the problem (no
# space / disk full), and leave no partial or temporary file in the folder.
# Exits 77 (ctest: skipped) with a message when a tmpfs cannot be mounted
# (not root, no CAP_SYS_ADMIN, no unshare). render needs an X display.
set -uo pipefail

if (($# < 2)); then
  echo "usage: full-disk.sh CLI WORKDIR" >&2
  exit 2
fi
cli=$1
work=$2

if [[ -z "${VV_FULL_DISK_NS:-}" ]]; then
  if [[ -z "${DISPLAY:-}" ]]; then
    echo "SKIP: no X display for render (run under xvfb-run -a)"
    exit 77
  fi
  if ! unshare -m --propagation private true 2>/dev/null; then
    echo "SKIP: cannot make a mount namespace here (unshare -m needs root / CAP_SYS_ADMIN)"
    exit 77
  fi
  rm -rf "$work"
  mkdir -p "$work/tiny"
  # The mount disappears with the namespace, also when the test is killed.
  exec unshare -m --propagation private env VV_FULL_DISK_NS=1 bash "$0" "$@"
fi

tiny="$work/tiny"
if ! mount -t tmpfs -o size=64k,mode=0755 vv-full-disk "$tiny" 2>"$work/mount.err"; then
  echo "SKIP: cannot mount a tmpfs: $(cat "$work/mount.err")"
  exit 77
fi

failures=0
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}

# A small demo tree outside the tmpfs, as the render input.
"$cli" demo --generations 2 --voxel-size 1 --seed 5 -o "$work/demo.vtp" >/dev/null ||
  { echo "FAIL: cannot write the demo input"; exit 1; }

# Existing outputs, then fill the disk up to a few KiB.
head -c 3000 /dev/urandom >"$tiny/out.png"
head -c 5000 /dev/urandom >"$tiny/x.vtp"
before_png=$(sha256sum <"$tiny/out.png")
before_vtp=$(sha256sum <"$tiny/x.vtp")
head -c 100000 /dev/zero >"$tiny/filler" 2>/dev/null  # fails when full: that is the point
df -k "$tiny" | tail -1 | awk '{print "tmpfs: " $2 " KiB, " $4 " KiB free after filling"}'
listing_before=$(find "$tiny" -mindepth 1 -printf "%f\n" | LC_ALL=C sort)

check() {  # check NAME TARGET COMMAND...
  local name=$1 target=$2
  shift 2
  timeout 120 "$cli" "$@" >"$work/out" 2>"$work/err"
  local rc=$?
  local message
  message=$(cat "$work/err")
  echo "$name: exit $rc: $message"
  ((rc == 4)) || fail "$name: exit $rc, expected 4"
  grep -qF -- "$target" "$work/err" || fail "$name: the message does not name $target"
  grep -qiE 'no space|disk full|space left' "$work/err" ||
    fail "$name: the message does not say that the disk is full"
}

check "render over an existing PNG" "$tiny/out.png" \
  render "$work/demo.vtp" -o "$tiny/out.png" --size 1024x768
check "render to a new PNG" "$tiny/new.png" \
  render "$work/demo.vtp" -o "$tiny/new.png" --size 1024x768
check "demo over an existing VTP" "$tiny/x.vtp" demo -o "$tiny/x.vtp" --generations 3
check "demo to a new VTP" "$tiny/y.vtp" demo -o "$tiny/y.vtp" --generations 3

[[ "$(sha256sum <"$tiny/out.png")" == "$before_png" ]] || fail "out.png changed"
[[ "$(sha256sum <"$tiny/x.vtp")" == "$before_vtp" ]] || fail "x.vtp changed"
listing_after=$(find "$tiny" -mindepth 1 -printf "%f\n" | LC_ALL=C sort)
if [[ "$listing_after" != "$listing_before" ]]; then
  fail "files left in the folder: $(comm -13 <(echo "$listing_before") <(echo "$listing_after") | tr '\n' ' ')"
fi

umount "$tiny" 2>/dev/null
if ((failures > 0)); then
  echo "full-disk: $failures failure(s)"
  exit 1
fi
echo "full-disk: ok (exit 4, file and problem named, old outputs intact, nothing left behind)"
