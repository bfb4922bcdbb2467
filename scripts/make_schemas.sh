#!/usr/bin/env bash
# Writes docs/schema/COMMAND.json, the JSON Schema of every command's request, from the built CLI
# (`scalcal schema COMMAND`); tests/schema/check_schemas.py fails when they differ.
# Usage: scripts/make_schemas.sh [SCALCAL] (default build/experiments/scalcal)
set -euo pipefail
cd "$(dirname "$0")/.."
scalcal="${1:-build/experiments/scalcal}"
rm -f docs/schema/*.json
for c in $("$scalcal" help | sed -n 's/^  \([a-z]*\) .*/\1/p; s/^  \([a-z]*\)$/\1/p'); do
  "$scalcal" schema "$c" --out "docs/schema/$c.json"
done
ls docs/schema | wc -l
