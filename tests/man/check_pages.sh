#!/usr/bin/env bash
# The man pages the build wrote (<build>/share/man/man1, installed by `cmake --install`): one for each
# command `scalcal help` lists plus scalcal.1, each valid roff (groff -ww warns of nothing) and giving,
# as rendered, an entry for every option that `scalcal SUB --help` (CLI11's rendering) lists. Then the
# check is checked: the optimize page with its --seed entry cut out must fail it, naming --seed.
# Usage: check_pages.sh SCALCAL MAN_DIR
set -euo pipefail
scalcal="$1"
dir="$2"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export LC_ALL=C

# Rendered as plain text, one line per entry (wide lines, no hyphenation): an option's entry is a line
# of its own, indented 7 columns, that starts with its name ("       --positions N").
render() { groff -man -Tascii -P-cbou -rLL=400n -rHY=0 "$1"; }

# check_page PAGE SUB: "" when the page is valid and names every option of SUB's --help, else why not.
check_page() {
  local page="$1" sub="$2" option
  groff -man -Tascii -ww -z "$page" 2>"$work/warnings" || true
  if [ -s "$work/warnings" ]; then
    echo "$page: groff warns: $(head -n 1 "$work/warnings")"
    return
  fi
  render "$page" >"$work/text"
  "$scalcal" "$sub" --help >"$work/help"
  # --help's entries: "  --positions N   ...", "  -h,--help ...", positionals "  PROGRAM TEXT REQUIRED ...".
  for option in $(sed -n 's/^  \([-A-Za-z][-A-Za-z0-9_,]*\).*/\1/p' "$work/help" | tr ',' ' '); do
    [ "$option" = "-h" ] && continue  # shown as "-h, --help"
    grep -Eq -- "^ {7}(-h, )?$option( |\$)" "$work/text" || { echo "$page: no entry for $option"; return; }
  done
}

commands=$("$scalcal" help | awk '/^  [a-z]/ { print $1 }')
[ -n "$commands" ] || { echo "no commands in 'scalcal help'"; exit 1; }
failed=0
for sub in $commands; do
  page="$dir/scalcal-$sub.1"
  [ -f "$page" ] || { echo "no page $page"; failed=1; continue; }
  why=$(check_page "$page" "$sub")
  [ -z "$why" ] || { echo "$why"; failed=1; }
done
# No page for a command that is not there, and the overview lists every command.
for page in "$dir"/scalcal-*.1; do
  sub=$(basename "$page" .1)
  sub=${sub#scalcal-}
  grep -qx "$sub" <<<"$commands" || { echo "$page: no command $sub"; failed=1; }
done
groff -man -Tascii -ww -z "$dir/scalcal.1" 2>"$work/warnings" || true
[ ! -s "$work/warnings" ] || { echo "scalcal.1: groff warns: $(head -n 1 "$work/warnings")"; failed=1; }
render "$dir/scalcal.1" >"$work/overview"
for sub in $commands; do
  grep -Eq "^ {7}$sub( |\$)" "$work/overview" || { echo "scalcal.1: no entry for $sub"; failed=1; }
done

# The check must fail for a page without an option: cut the --seed entry (its .TP and what follows up
# to the next .TP) out of the optimize page.
awk '/^\.TP$/ { held = $0; next }
     held != "" { skip = ($0 ~ /^\.BI "\\-\\-seed /); if (!skip) print held; held = "" }
     /^\.(TP|SH)/ { skip = 0 }
     !skip { print }' "$dir/scalcal-optimize.1" >"$work/scalcal-optimize.1"
why=$(check_page "$work/scalcal-optimize.1" optimize)
case "$why" in
  *"no entry for --seed") ;;
  *) echo "the check passed a page without --seed (it said: '$why')"; failed=1 ;;
esac
[ "$failed" -eq 0 ] && echo "man pages: $(echo "$commands" | wc -w) commands, every option named, groff -ww clean"
exit "$failed"
