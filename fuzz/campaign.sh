#!/usr/bin/env bash
# A long fuzz campaign on this machine:
#   1. every target at once, each with libFuzzer's -fork over its share of the cores;
#   2. the corpus merged and minimised (cargo fuzz cmin);
#   3. every crash minimised (cargo fuzz tmin), kept as a regression input under
#      fuzz/regressions/TARGET/ (replayed by stable `cargo test`), and turned into a named
#      corpus case under corpus/cases/ by `polytri promote`.
#
#     fuzz/campaign.sh [--minutes M] [--jobs N] [TARGET ...]
#
# Uses nightly with AddressSanitizer when nightly is installed, else stable without a
# sanitizer (polytri has no unsafe code; the sanitizer guards its dependencies).
set -euo pipefail
cd "$(dirname "$0")"

minutes=60
jobs=$(nproc)
targets=()
while [ $# -gt 0 ]; do
    case "$1" in
        --minutes) minutes="$2"; shift 2 ;;
        --jobs) jobs="$2"; shift 2 ;;
        -h|--help) sed -n '2,13p' "$0"; exit 0 ;;
        *) targets+=("$1"); shift ;;
    esac
done
[ ${#targets[@]} -gt 0 ] || mapfile -t targets < <(cargo fuzz list)

toolchain=()
sanitizer=none
if rustup toolchain list 2>/dev/null | grep -q '^nightly'; then
    toolchain=(+nightly)
    sanitizer=address
fi
fuzz() { cargo "${toolchain[@]}" fuzz "$@"; }

per_target=$(( jobs / ${#targets[@]} ))
[ "$per_target" -ge 1 ] || per_target=1
seconds=$(( minutes * 60 ))
echo "campaign: ${#targets[@]} targets x ${per_target} workers for ${minutes} min, sanitizer ${sanitizer}"

fuzz build -O --debug-assertions --sanitizer "$sanitizer"
mkdir -p logs
for t in "${targets[@]}"; do
    mkdir -p "corpus/$t" "artifacts/$t"
    fuzz run "$t" -O --debug-assertions --sanitizer "$sanitizer" "corpus/$t" -- \
        -fork="$per_target" -ignore_crashes=1 -max_total_time="$seconds" \
        -artifact_prefix="artifacts/$t/" >"logs/$t.log" 2>&1 &
done
wait || true

for t in "${targets[@]}"; do
    echo "campaign: minimising the corpus of $t"
    fuzz cmin "$t" -O --sanitizer "$sanitizer" "corpus/$t" >>"logs/$t.log" 2>&1 || true
    mkdir -p "regressions/$t"
    for crash in artifacts/"$t"/crash-* artifacts/"$t"/timeout-* artifacts/"$t"/oom-*; do
        [ -e "$crash" ] || continue
        name=$(basename "$crash")
        echo "campaign: minimising $crash"
        fuzz tmin "$t" -O --sanitizer "$sanitizer" "$crash" -- -runs=10000 >>"logs/$t.log" 2>&1 || true
        small=$(ls -t artifacts/"$t"/minimized-from-* 2>/dev/null | head -n1 || true)
        keep="regressions/$t/$name"
        cp "${small:-$crash}" "$keep"
        (cd .. && cargo run --release -q -- promote --fuzz-target "$t" "fuzz/$keep") ||
            echo "campaign: could not promote $keep; it is still replayed from fuzz/regressions" >&2
    done
done
echo "campaign: done; logs in fuzz/logs, new regressions in fuzz/regressions, cases in corpus/cases"
