#!/usr/bin/env bash
# docs/tutorial.md: every picture in docs/tutorial/ is what scripts/tutorial.sh writes (byte for
# byte; none is drawn or edited by hand), every picture the tutorial links exists, and the check
# output it quotes is the command's.
source "$(dirname "$0")/common.sh" "$@"

expect_exit 0 "scripts/tutorial.sh runs every command of the tutorial" -- \
  bash "$ROOT/scripts/tutorial.sh" "$BIN" "$TMP/tutorial" --pictures
for f in "$ROOT"/docs/tutorial/*; do
  name=$(basename "$f")
  cmp -s "$f" "$TMP/tutorial/$name" && pass "docs/tutorial/$name is reproduced byte for byte" \
    || fail "docs/tutorial/$name differs from what scripts/tutorial.sh writes"
done
for f in "$TMP"/tutorial/*; do
  [ -e "$ROOT/docs/tutorial/$(basename "$f")" ] || fail "scripts/tutorial.sh writes $(basename "$f"), which docs/tutorial/ lacks"
done
missing=""
for link in $(grep -oE '\(tutorial/[^)]+\)' "$ROOT/docs/tutorial.md" | tr -d '()'); do
  [ -e "$ROOT/docs/$link" ] || missing="$missing $link"
done
[ -z "$missing" ] && pass "every picture the tutorial links exists" || fail "missing pictures:$missing"
grep -qF "$(sed -n 2p "$ROOT/docs/tutorial/plate.check.txt")" "$ROOT/docs/tutorial.md" \
  && pass "the tutorial quotes the check output" || fail "the tutorial's check output is stale"
finish
