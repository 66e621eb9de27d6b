#!/usr/bin/env bash
# Sets up, builds and runs the whole test suite, twice: a Release build with gcc, then a clang
# build with AddressSanitizer + UndefinedBehaviorSanitizer that also runs a short smoke run of
# every libFuzzer target. Ends with ctest's summary.
#   scripts/test.sh             both passes (what CI runs)
#   scripts/test.sh --fast      the Release pass only
#   scripts/test.sh --sanitize  the sanitizer pass only
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
JOBS="$(nproc 2>/dev/null || echo 2)"
mode="${1:-all}"

release_pass() {
  "$ROOT/scripts/setup.sh"
  HLR_CORPUS_DIR="$ROOT/build/corpus" "$ROOT/scripts/extract_corpus.sh" >/dev/null
  (cd "$ROOT/build" && ctest --output-on-failure -j "$JOBS")
}

sanitize_pass() {
  CC=clang CXX=clang++ HLR_BUILD_DIR="$ROOT/build-asan" HLR_BUILD_TYPE=RelWithDebInfo \
    "$ROOT/scripts/setup.sh" -DHLR_SANITIZE=ON -DHLR_FUZZ=ON -DHLR_BUILD_BENCHMARKS=OFF
  HLR_CORPUS_DIR="$ROOT/build-asan/corpus" "$ROOT/scripts/extract_corpus.sh" >/dev/null
  (cd "$ROOT/build-asan" && ASAN_OPTIONS=detect_leaks=1 LSAN_OPTIONS="suppressions=$ROOT/tests/lsan.supp" \
    UBSAN_OPTIONS=print_stacktrace=1 ctest --output-on-failure -j "$JOBS")
}

case "$mode" in
  --fast) release_pass ;;
  --sanitize) sanitize_pass ;;
  all) release_pass; echo; echo "== sanitizer build (ASan + UBSan) and fuzz smoke runs =="; sanitize_pass ;;
  *) echo "usage: scripts/test.sh [--fast|--sanitize]" >&2; exit 2 ;;
esac
