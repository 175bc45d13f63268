#!/usr/bin/env bash
# expect_run.sh EXIT REGEX [REJECT_REGEX] -- COMMAND...
# Runs COMMAND; passes when its exit status matches EXIT ("0", "nonzero" or a number) and its combined
# output matches REGEX (extended grep) and, if given, does not match REJECT_REGEX. Prints the output, and
# with EXPECT_RUN_LOG set also writes it there (for tests that check more words of the same run).
set -u
expect_exit=$1; regex=$2; shift 2
reject=""
if [ "$1" != "--" ]; then reject=$1; shift; fi
shift   # --
output=$("$@" 2>&1); status=$?
printf '%s\n' "$output"
if [ -n "${EXPECT_RUN_LOG:-}" ]; then printf '%s\n' "$output" > "$EXPECT_RUN_LOG"; fi
echo "expect_run: exit status $status (expected $expect_exit)"
case $expect_exit in
  nonzero) [ "$status" -ne 0 ] || { echo "expect_run: FAIL: expected a non-zero exit"; exit 1; } ;;
  *) [ "$status" -eq "$expect_exit" ] || { echo "expect_run: FAIL: wrong exit status"; exit 1; } ;;
esac
printf '%s\n' "$output" | grep -Eq -- "$regex" || { echo "expect_run: FAIL: output lacks /$regex/"; exit 1; }
if [ -n "$reject" ] && printf '%s\n' "$output" | grep -Eq -- "$reject"; then
  echo "expect_run: FAIL: output matches the rejected /$reject/"; exit 1
fi
echo "expect_run: PASS"
