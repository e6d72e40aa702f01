#!/usr/bin/env bash
# The malformed-deck catalogue (tests/malformed/README.md): `ricochet check`
# on each deck of tests/malformed/expect.tsv must exit with 2 and print a
# message naming the expected file:line (the line holding the faulty field),
# the card and the field (or the fault). One PASS/FAIL line per deck,
# counted by scripts/check.sh; the base deck itself must pass the check.
set -u
bin=$(realpath "${1:-build/ricochet}")
cd "$(dirname "$0")/malformed" || exit 1
tmp=$(mktemp)
trap 'rm -f "$tmp"' EXIT

"$bin" check base.rad > "$tmp" 2>&1; rc=$?
if [ "$rc" -eq 0 ]; then echo "PASS malformed.base: the base deck passes the check"
else echo "FAIL malformed.base: exit $rc: $(head -c 300 "$tmp")"; fi

while IFS=$'\t' read -r file place card field; do
    case "$file" in '#'*|'') continue ;; esac
    name=${file%.rad}
    "$bin" check "$file" > "$tmp" 2>&1; rc=$?
    msg=$(head -c 600 "$tmp")
    why=""
    [ "$rc" -eq 2 ] || why="exit $rc, expected 2"
    # the place starts the message (after "ricochet: input error: ")
    [ -n "$why" ] || grep -q "^ricochet: input error: $place: " "$tmp" || why="no place $place"
    if [ -z "$why" ] && [ "$card" != "-" ]; then
        grep -qF "card $card" "$tmp" || why="no card $card"
    fi
    [ -n "$why" ] || grep -qF -- "$field" "$tmp" || why="no \"$field\""
    if [ -z "$why" ]; then echo "PASS malformed.$name: $msg"
    else echo "FAIL malformed.$name: $why: $msg"; fi
done < expect.tsv
