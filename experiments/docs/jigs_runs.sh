#!/usr/bin/env bash
# Regenerates the tables of jigs.md: `scalcal jig NAME --criterion C --json` for every printable jig the
# catalogue lists (a new jig family file shows up here with no edit) and every criterion, then the tables.
# Usage: bash experiments/docs/jigs_runs.sh [path/to/scalcal] [scratch folder]
set -euo pipefail
cd "$(dirname "$0")/../.."
cli=${1:-build/experiments/scalcal}
out=${2:-$(mktemp -d)}
mkdir -p "$out"
"$cli" catalogue --json > "$out/catalogue.json"
jigs=$(python3 -c "import json,sys; print(' '.join(e['name'] for e in json.load(open(sys.argv[1])) if e['name'].startswith('jig:')))" "$out/catalogue.json")
for jig in $jigs; do
  for c in D A E S; do
    status=0
    "$cli" jig "$jig" --criterion "$c" --json > "$out/$jig-$c.json" 2> "$out/$jig-$c.err" || status=$?
    echo "$status" > "$out/$jig-$c.status"
  done
done
python3 experiments/docs/jigs_table.py "$out" $jigs
