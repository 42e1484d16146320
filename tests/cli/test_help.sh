#!/usr/bin/env bash
# Every subcommand answers --help.
source "$(dirname "$0")/common.sh" "$@"
expect_exit 0 "symmesh --help" -- "$BIN" --help
for c in check graph lemmas bpp generate example cut solve render adapt; do
  expect_exit 0 "symmesh $c --help" -- "$BIN" "$c" --help
  grep -qi "usage" "$TMP/stdout" && pass "$c help has usage" || fail "$c help"
done
expect_exit 2 "no subcommand" -- "$BIN"
expect_exit 0 "--version" -- "$BIN" --version
finish
