#!/usr/bin/env bash
# scripts/animate.py: animations of short runs (a sphere, boxes), their
# frame counts read back from the GIF, the exit codes of wrong input.
# Prints PASS/FAIL lines (counted by scripts/check.sh).
set -u
bin=${1:-build/ricochet}
py=/usr/bin/python3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

check() { # name, condition (0 true), detail
    if [ "$2" -eq 0 ]; then echo "PASS animate.$1: $3"; else echo "FAIL animate.$1: $3"; fi
}
# frames of a GIF read back with Pillow ("" without Pillow)
gif_frames() {
    $py -c 'import sys
try:
    from PIL import Image
except ImportError:
    sys.exit(0)
print(Image.open(sys.argv[1]).n_frames)' "$1" 2>/dev/null
}
if ! $py -c 'import PIL' 2>/dev/null; then
    echo "SKIP animate: no Pillow (python3-pil) for $py: GIFs cannot be written"
    exit 0
fi

# sphere drop: 0.2 s at Dt_out 10 ms = 21 output times = 21 frames by default
"$bin" run cases/t6_hysteresis_drop.rad -o "$tmp/drop.nc" --t-end 0.2 --dt-out 0.01 -q > "$tmp/r" 2>&1
$py scripts/animate.py "$tmp/drop.nc" -o "$tmp/drop.gif" > "$tmp/o" 2>&1; rc=$?
n=$(gif_frames "$tmp/drop.gif")
[ $rc -eq 0 ] && [ -s "$tmp/drop.gif" ] && [ "$n" = 21 ] && grep -q "drop.gif: 21 frames (every output time" "$tmp/o"
check sphere_default $? "exit $rc, $n frames read back (21 expected): $(head -c 200 "$tmp/o")"

# the boxes: 0.1 s at 5 ms, three views, --every and --dt
"$bin" run cases/box_stack.rad -o "$tmp/boxes.nc" --t-end 0.1 --dt-out 0.005 -q > "$tmp/r" 2>&1
nrec=$($py -c 'import netCDF4, sys; print(len(netCDF4.Dataset(sys.argv[1]).dimensions["time"]))' "$tmp/boxes.nc")
want=$(( (nrec + 2) / 3 ))
$py scripts/animate.py "$tmp/boxes.nc" -o "$tmp/every.gif" --every 3 --width 320 > "$tmp/o" 2>&1; rc=$?
n=$(gif_frames "$tmp/every.gif")
[ $rc -eq 0 ] && [ "$n" = "$want" ]
check boxes_every $? "exit $rc, --every 3 of $nrec records: $n frames ($want expected)"
$py scripts/animate.py "$tmp/boxes.nc" -o "$tmp/dt.gif" --dt 0.02 --view yz --fps 10 > "$tmp/o" 2>&1; rc=$?
n=$(gif_frames "$tmp/dt.gif")
[ $rc -eq 0 ] && [ "$n" = 6 ]
check boxes_dt $? "exit $rc, --dt 0.02 over 0.1 s: $n frames (6 expected)"
$py scripts/animate.py "$tmp/boxes.nc" -o "$tmp/xy.gif" --view xy --max-frames 10 > "$tmp/o" 2>&1; rc=$?
n=$(gif_frames "$tmp/xy.gif")
# 21 output times, at most 10 frames: one per 20 ms (6 frames)
[ $rc -eq 0 ] && [ "$n" = 6 ] && grep -q "one per 0.02 s" "$tmp/o"
check boxes_capped $? "exit $rc, --max-frames 10 of 21 output times: $n frames (6 expected): $(tail -c 200 "$tmp/o")"

# wrong input: exit 2 and a message naming the file
$py scripts/animate.py "$tmp/missing.nc" -o "$tmp/m.gif" > "$tmp/o" 2>&1; rc=$?
[ $rc -eq 2 ] && grep -q "missing.nc: no such file" "$tmp/o" && [ ! -e "$tmp/m.gif" ]
check missing_file $? "exit $rc: $(head -c 160 "$tmp/o")"
$py scripts/animate.py cases/box_stack.rad -o "$tmp/m.gif" > "$tmp/o" 2>&1; rc=$?
[ $rc -eq 2 ] && grep -q "box_stack.rad: not a" "$tmp/o"
check not_results $? "exit $rc: $(head -c 160 "$tmp/o")"
$py scripts/animate.py "$tmp/drop.nc" -o "$tmp/m.avi" > "$tmp/o" 2>&1; rc=$?
[ $rc -eq 2 ] && grep -q "expected a .gif or .mp4" "$tmp/o"
check bad_suffix $? "exit $rc: $(head -c 160 "$tmp/o")"
$py scripts/animate.py "$tmp/drop.nc" --every 2 --dt 0.1 > "$tmp/o" 2>&1; rc=$?
[ $rc -eq 2 ]
check every_and_dt $? "exit $rc (--every with --dt refused)"
$py scripts/animate.py --help > "$tmp/o" 2>&1; rc=$?
[ $rc -eq 0 ] && grep -q -- "--view" "$tmp/o" && grep -q -- "--every N" "$tmp/o" && grep -q -- "--dt T" "$tmp/o" &&
    grep -q -- "--fps" "$tmp/o" && grep -q -- "--width PX" "$tmp/o"
check help $? "exit $rc, options listed"
