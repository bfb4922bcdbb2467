#!/usr/bin/env bash
# scalcal sweep under mpirun: with 1, 2 and 3 ranks the output (JSON and CSV, --no-timing) equals the
# single process's byte for byte, also where one synthesis's starts are split among the ranks; a task that
# fails on a rank is named on stderr with exit 1.
# Usage: sweep_ranks.sh SCALCAL MPIEXEC
set -euo pipefail
scalcal="$1" mpiexec="$2"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Root in a container is normal here; Open MPI refuses it without these.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
args=(sweep --positions 9..13 --criteria D,A,S --starts 3 --seed 5 --no-timing --json)
"$scalcal" "${args[@]}" --out "$work/single.csv" >"$work/single.json"
for np in 1 2 3; do
  "$mpiexec" -np "$np" "$scalcal" "${args[@]}" --out "$work/mpi$np.csv" >"$work/mpi$np.json"
  cmp "$work/single.json" "$work/mpi$np.json" || { echo "JSON differs at -np $np" >&2; exit 1; }
  cmp "$work/single.csv" "$work/mpi$np.csv" || { echo "CSV differs at -np $np" >&2; exit 1; }
done
[ "$(grep -c '"criterion"' "$work/single.json")" = 15 ] || { echo "expected 15 rows" >&2; exit 1; }
# One synthesis's starts split among the ranks (commands/research/sweep_starts): 20 forced starts of each
# task run ahead in ranges of 8, 8 and 4 on whichever rank is free; the rows are the single process's.
split=(sweep --positions 9..10 --criteria E,S --starts 20 --seed 3 --no-timing --json)
"$scalcal" "${split[@]}" >"$work/split.json"
for np in 2 3; do
  "$mpiexec" -np "$np" "$scalcal" "${split[@]}" >"$work/split$np.json"
  cmp "$work/split.json" "$work/split$np.json" || { echo "split starts differ at -np $np" >&2; exit 1; }
done
# Task (A, 10) fails on whichever rank takes it (they take tasks as they free up). The other rows still
# come out; the failure is named with its rank.
status=0
SCALCAL_SWEEP_FAIL=A:10 "$mpiexec" -np 2 -x SCALCAL_SWEEP_FAIL "$scalcal" "${args[@]}" >"$work/fail.json" \
  2>"$work/fail.err" || status=$?
[ "$status" = 1 ] || { echo "a failed task must exit 1, got $status" >&2; exit 1; }
grep -Eq "rank [01] failed on A N = 10: failure injected" "$work/fail.err" || { cat "$work/fail.err" >&2; exit 1; }
[ "$(grep -c '"criterion"' "$work/fail.json")" = 14 ] || { echo "expected the 14 other rows" >&2; exit 1; }
echo "sweep under MPI: -np 1, 2, 3 identical to the single process, starts split or not; a failing rank is reported"
