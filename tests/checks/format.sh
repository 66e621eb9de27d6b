#!/usr/bin/env bash
# The house style on changed lines: every line of C++ changed since .clang-format was added
# (committed or not) must be as clang-format writes it. Lines nobody touched keep their
# layout, so the history is not rewritten for the formatter.
#   format.sh ROOT [--self-test]
set -euo pipefail
ROOT="${1:-$(dirname "$0")/../..}"
cd "$ROOT"
DIFF_TOOL="$(command -v clang-format-diff || command -v clang-format-diff-14 || true)"
if [ -z "$DIFF_TOOL" ]; then echo "format: clang-format-diff not found (apt install clang-format)"; exit 1; fi
if [ -z "$(command -v clang-format || true)" ]; then echo "format: clang-format not found"; exit 1; fi
base="$(git log --diff-filter=A --format=%H -- .clang-format | tail -1)"
if [ -z "$base" ]; then base=HEAD; fi
check() {  # the diff of changed lines against the style, from a unified diff on stdin
  python3 "$DIFF_TOOL" -p1 -style=file -binary "$(command -v clang-format)"
}
if [ "${2:-}" = "--self-test" ]; then
  # A changed line in the wrong style must be reported.
  bad=$(printf '%s\n' 'diff --git a/x.cpp b/x.cpp' '--- a/x.cpp' '+++ b/x.cpp' '@@ -0,0 +1 @@' '+int  f( ){return 1;}' )
  tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
  printf 'int  f( ){return 1;}\n' > "$tmp/x.cpp"; cp .clang-format "$tmp/"
  out=$(cd "$tmp" && printf '%s\n' "$bad" | python3 "$DIFF_TOOL" -p1 -style=file -binary "$(command -v clang-format)" || true)
  if [ -n "$out" ]; then echo "format --self-test: a badly formatted changed line is caught"; exit 0; fi
  echo "format --self-test: the check let a badly formatted line through"; exit 1
fi
out=$(git diff -U0 --no-color "$base" -- '*.cpp' '*.hpp' | check || true)
if [ -n "$out" ]; then
  echo "$out" | head -80
  echo "format: changed lines not in the house style (run: git diff -U0 $base | clang-format-diff -p1 -i)"
  exit 1
fi
echo "format: every changed line is in the house style"
