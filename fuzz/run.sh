#!/usr/bin/env bash
# Run the libFuzzer target built by `make fuzz` for a bounded time.
#   fuzz/run.sh BUILD_DIR SECONDS
# The working corpus (BUILD_DIR/corpus) starts from fuzz/corpus and
# fuzz/regressions and grows across runs; new crash, leak, timeout or
# out-of-memory inputs land in BUILD_DIR/artifacts. Prints the figures and
# fails (exit 1) when the run left any artifact: copy it to fuzz/regressions/,
# fix the bug, and make check replays it from then on.
set -u
build=${1:-build-fuzz}
secs=${2:-60}
bin=$build/fuzz_deck
corpus=$build/corpus
art=$build/artifacts
log=$build/fuzz.log
mkdir -p "$corpus" "$art"
cp -n fuzz/corpus/* fuzz/regressions/* "$corpus"/ 2>/dev/null
before=$(ls "$art" | wc -l)
# one process; a hang is an input taking more than 10 s; 2 GB memory at most
"$bin" -max_total_time="$secs" -timeout=10 -rss_limit_mb=2048 -max_len=8192 \
    -dict=fuzz/deck.dict -artifact_prefix="$art/" -print_final_stats=1 \
    "$corpus" > "$log" 2>&1
status=$?
after=$(ls "$art" | wc -l)
stat() { sed -n "s/^stat::$1: *//p" "$log" | tail -n 1; }
echo "fuzz: ${secs} s, $(stat number_of_executed_units) executions, $(stat average_exec_per_sec) exec/s," \
     "corpus $(ls "$corpus" | wc -l) inputs, new artifacts $((after - before)), peak RSS $(stat peak_rss_mb) MB"
if [ "$status" -ne 0 ] || [ "$after" -gt "$before" ]; then
    echo "fuzz: FAILED (exit $status); the report:"
    grep -E "ERROR|SUMMARY|fuzz_deck:|Test unit written|timeout|leak" "$log" | head -n 40
    ls -l "$art"
    exit 1
fi
echo "fuzz: no crash, leak or hang"
