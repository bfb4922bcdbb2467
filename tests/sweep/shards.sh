#!/usr/bin/env bash
# scalcal sweep split into shards (--shard I/N --results FILE), one of them killed with SIGKILL half-way and
# resumed, joined by `scalcal merge`: the JSON, the table and the --out CSV (--no-timing) equal the single
# process's byte for byte. Also: a line a kill left half-written is cut off, a shard that fails keeps its
# finished tasks, and merge names a file of another sweep and the tasks no file holds.
# Usage: shards.sh SCALCAL
set -euo pipefail
scalcal="$1"
work=$(mktemp -d)
trap 'kill -9 $(jobs -p) 2>/dev/null || true; rm -rf "$work"' EXIT
fail() { echo "shards.sh: $*" >&2; exit 1; }
args=(sweep --positions 9..24 --criteria D,A,E,S --starts 4 --seed 3 --threads 1)
"$scalcal" "${args[@]}" --no-timing --json >"$work/single.json"
"$scalcal" "${args[@]}" --no-timing --out "$work/single.csv" >"$work/single.txt"
tasks=$(grep -c '"criterion"' "$work/single.json")
[ "$tasks" = 64 ] || fail "expected 64 rows, got $tasks"

mkdir "$work/parts"
# Shard 0 of 5, killed with SIGKILL once it has finished 4 of its 13 tasks.
"$scalcal" "${args[@]}" --shard 0/5 --results "$work/parts/0.jsonl" >/dev/null 2>&1 &
pid=$!
for _ in $(seq 1 600); do
  [ -f "$work/parts/0.jsonl" ] && [ "$(wc -l <"$work/parts/0.jsonl")" -ge 5 ] && break
  sleep 0.05
done
kill -9 "$pid" 2>/dev/null || true
wait "$pid" 2>/dev/null || true
done_before=$(($(wc -l <"$work/parts/0.jsonl") - 1))
[ "$done_before" -ge 4 ] || fail "the killed shard kept $done_before tasks"
[ "$done_before" -lt 13 ] || echo "shards.sh: the shard finished before the kill (a fast machine); resuming all the same"
# As if the kill had come mid-write: half a line at the end.
printf '{"task":40,"criterion":"E","positions":' >>"$work/parts/0.jsonl"
"$scalcal" "${args[@]}" --shard 0/5 --results "$work/parts/0.jsonl" --no-timing >"$work/resumed.txt"
[ "$(wc -l <"$work/parts/0.jsonl")" = 14 ] || fail "the resumed shard holds $(($(wc -l <"$work/parts/0.jsonl") - 1)) of its 13 tasks"
[ "$(tail -c 1 "$work/parts/0.jsonl" | od -An -c | tr -d ' ')" = '\n' ] || fail "the cut line survived"
# Shard 1 fails on one task (the fault injection of tests/mpi/sweep_ranks.sh) and keeps the others before it.
status=0
SCALCAL_SWEEP_FAIL=D:20 "$scalcal" "${args[@]}" --shard 1/5 --results "$work/parts/1.jsonl" >/dev/null \
  2>"$work/fail.err" || status=$?
[ "$status" = 1 ] || fail "a failed task must exit 1, got $status"
grep -q "D N = 20: failure injected by SCALCAL_SWEEP_FAIL (the results so far are in" "$work/fail.err" ||
  fail "$(cat "$work/fail.err")"
status=0
"$scalcal" merge --results "$work/parts" >/dev/null 2>"$work/missing.err" || status=$?
[ "$status" = 2 ] || fail "merge with tasks missing must exit 2, got $status"
grep -q "of the sweep's 64 tasks are in no result file: D N = 11 (task 2)" "$work/missing.err" ||
  fail "$(cat "$work/missing.err")"
for i in 1 2 3 4; do "$scalcal" "${args[@]}" --shard "$i/5" --results "$work/parts/$i.jsonl" >/dev/null; done
"$scalcal" merge --results "$work/parts" --no-timing --json >"$work/merged.json"
"$scalcal" merge --results "$work/parts/0.jsonl" --results "$work/parts/1.jsonl" --results "$work/parts/2.jsonl" \
  --results "$work/parts/3.jsonl" --results "$work/parts/4.jsonl" --no-timing --out "$work/merged.csv" >"$work/merged.txt"
cmp "$work/single.json" "$work/merged.json" || fail "the merged JSON differs from the single process's"
cmp "$work/single.csv" "$work/merged.csv" || fail "the merged CSV differs"
cmp "$work/single.txt" "$work/merged.txt" || fail "the merged table differs"
# A shard of another request is named with what differs.
"$scalcal" sweep --positions 9..24 --criteria D,A,E,S --starts 4 --seed 4 --shard 0/100 --results "$work/other.jsonl" >/dev/null
cp "$work/other.jsonl" "$work/parts/z.jsonl"
status=0
"$scalcal" merge --results "$work/parts" >/dev/null 2>"$work/other.err" || status=$?
[ "$status" = 2 ] && grep -q "z.jsonl:1: a result file of another sweep (--seed 3 against 4" "$work/other.err" ||
  fail "merge of another sweep's file: exit $status, $(cat "$work/other.err")"
echo "sweep in 5 shards, one killed after $done_before of its 13 tasks and resumed: merged JSON, table and CSV equal the single process's (64 tasks)"
