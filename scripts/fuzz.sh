#!/usr/bin/env bash
# One fuzzing campaign (docs/testing.md):  scripts/fuzz.sh HARNESS [SECONDS]
#   HARNESS: scene (scene files, then `appell eval` in every scalar) or
#            expression (cone expressions, their derivatives and evaluation).
# Builds the library and the harness with Clang, libFuzzer, ASan and UBSan in
# ./build-fuzz, runs libFuzzer for SECONDS (default 3600, one process) on the
# committed corpus, then merges what reached new coverage into tests/fuzz/corpus/HARNESS
# (minimized).  Findings (crash-*, timeout-*, oom-*) go to build-fuzz/findings/HARNESS;
# the statistics to build-fuzz/HARNESS.log.  Limits per input: 10 s, 2 GiB.
set -euo pipefail
cd "$(dirname "$0")/.."
harness=${1:?usage: scripts/fuzz.sh scene|expression [SECONDS]}
seconds=${2:-3600}
case "$harness" in scene|expression) ;; *) echo "fuzz.sh: unknown harness '$harness'" >&2; exit 2;; esac
scripts/deps.sh
if ! command -v clang++ >/dev/null || ! ls /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a >/dev/null 2>&1; then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends clang libclang-rt-14-dev >/dev/null
fi
CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=Fuzz -DCMAKE_CXX_FLAGS_FUZZ="-O1 -g1" -DAPPELL_FUZZ=ON >/dev/null
cmake --build build-fuzz -j"$(nproc)" --target "fuzz_$harness"
work=build-fuzz/corpus/$harness findings=build-fuzz/findings/$harness
mkdir -p "$work" "$findings"
# -fork=1: the campaign goes on after a finding (each is saved, and counted in the log)
./build-fuzz/tests/fuzz/fuzz_"$harness" "$work" tests/fuzz/corpus/"$harness" \
  -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
  -dict=tests/fuzz/"$harness".dict -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
  -max_len=4096 -artifact_prefix="$findings"/ >build-fuzz/"$harness".log 2>&1 || true
grep -E '^#[0-9]+: cov' build-fuzz/"$harness".log | tail -1 | sed "s/^/fuzz.sh: $harness: last status: /"
# keep a minimal set that covers what the campaign reached
merged=build-fuzz/merged/$harness
rm -rf "$merged" && mkdir -p "$merged"
./build-fuzz/tests/fuzz/fuzz_"$harness" -merge=1 -timeout=10 -rss_limit_mb=2048 "$merged" tests/fuzz/corpus/"$harness" "$work" >/dev/null 2>&1
rm -f tests/fuzz/corpus/"$harness"/found-*   # the merged set covers them
seeds=$(sha1sum tests/fuzz/corpus/"$harness"/seed-* | cut -d' ' -f1)
for f in "$merged"/*; do
  b=$(basename "$f")   # libFuzzer names a merged input by its SHA-1
  grep -qx "$b" <<<"$seeds" || cp "$f" tests/fuzz/corpus/"$harness"/found-"$b"
done
echo "fuzz.sh: $harness: $(ls "$findings" | wc -l) findings; corpus now $(ls tests/fuzz/corpus/"$harness" | wc -l) files"
