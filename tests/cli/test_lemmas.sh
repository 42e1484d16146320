#!/usr/bin/env bash
# symmesh lemmas as a user tool: passes on valid generators, catches dropped hypotheses and writes
# counterexamples that `symmesh check` itself classifies as non-conforming.
source "$(dirname "$0")/common.sh" "$@"

expect_exit 0 "lemmas --list" -- "$BIN" lemmas --list
n=$(wc -l < "$TMP/stdout")
[ "$n" -ge 20 ] && pass "$n properties listed" || fail "only $n properties listed"
expect_exit 0 "Lemma 4.2 passes (40 cases)" -- "$BIN" lemmas --cases 40 --only Lemma_4_2 --quiet --out "$TMP/ce"
grep -qE '^[0-9]+ passed, 0 failed$' "$TMP/stdout" && pass "closing line" || fail "closing line missing"
# The whole drop mode (every property with a dropped-hypothesis variant, few seeded cases): each
# check must fail on the inputs that violate its hypothesis (issue 20: not only Lemma 4.2).
expect_exit 0 "every dropped hypothesis is caught (all lemmas, 10 cases, seeded)" -- \
  "$BIN" lemmas --cases 10 --seed 20261125 --drop-hypothesis --quiet --out "$TMP/ce_all"
grep -qE "^[0-9]+ passed, 0 failed" "$TMP/stdout" && ! grep -q MISSED "$TMP/stdout" \
  && pass "no dropped hypothesis went unnoticed ($(grep -oE '^[0-9]+ passed' "$TMP/stdout"))" \
  || fail "a dropped hypothesis was missed: $(grep MISSED "$TMP/stdout" | head -3)"
# Every holds property without a dropped variant is listed, with its reason, in spec/lemmas.md
# (issue 20 item 4): the set run above and the listed set must cover all holds properties.
awk '{print $2}' "$TMP/stdout" | grep -E '_(2d|3d)$|^[a-z_0-9]+$' | sort -u > "$TMP/dropped"
"$BIN" lemmas --list | awk -F'\t' '$4 == "holds" {print $2}' | sort -u > "$TMP/holds"
table=$(sed -n '/^## holds-without-dropped-variant/,/^## /p' "$ROOT/spec/lemmas.md")
unlisted=""
for name in $(comm -23 "$TMP/holds" "$TMP/dropped"); do
  stem="${name%_2d}"; stem="${stem%_3d}"
  grep -qF "\`$stem\`" <<<"$table" || grep -qF "\`$name\`" <<<"$table" || unlisted="$unlisted $name"
done
[ -z "$unlisted" ] && pass "every holds property without a dropped variant is listed in spec/lemmas.md" \
  || fail "holds properties with neither a dropped variant nor a reason in spec/lemmas.md:$unlisted"
expect_exit 0 "dropped hypothesis of Lemma 4.2 is caught" -- "$BIN" lemmas --cases 40 --only Lemma_4_2 --drop-hypothesis --quiet --out "$TMP/ce"
grep -q caught "$TMP/stdout" && ! grep -q MISSED "$TMP/stdout" && pass "every check caught" || fail "a dropped hypothesis was missed"
ce=$(ls "$TMP"/ce/Lemma_4_2_sufficiency_2d_dropped.json 2>/dev/null | head -1)
br="$TMP/ce/Lemma_4_2_boundary_reduction_agrees_2d_dropped.json"
if [ -s "$br" ]; then
  expect_exit 2 "the boundary-reduction counterexample overlaps (Eq. 4.2 dropped): check rejects it" -- "$BIN" check "$br"
else
  fail "no boundary-reduction counterexample written"
fi
if [ -n "$ce" ]; then
  pass "counterexample written: $(basename "$ce")"
  expect_exit 1 "symmesh check classifies the shrunk counterexample as not a templated mesh" -- "$BIN" check "$ce"
  svg="${ce%.json}.svg"
  if [ -s "$svg" ] || grep -q '"dimension": 3' "$ce"; then pass "SVG for 2D counterexample"; else fail "no SVG next to $ce"; fi
else
  fail "no counterexample JSON written"
fi
expect_exit 2 "unknown lemma" -- "$BIN" lemmas --only Lemma_9_9
expect_exit 2 "bad --dim" -- "$BIN" lemmas --dim 4
finish
