#!/usr/bin/env bash
# Builds every cargo-fuzz target of fuzz/ into $OUT, with a seed corpus per target.
#
# Inside ClusterFuzzLite / OSS-Fuzz the base image sets SRC, OUT, SANITIZER and a nightly
# toolchain. By hand on this machine it needs nothing: SRC defaults to the checkout, OUT to
# fuzz/out, and without nightly the targets build on stable with no sanitizer:
#
#     .clusterfuzzlite/build.sh && ls fuzz/out
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="${SRC:+$SRC/polytri}"
root="${root:-$(dirname "$here")}"
[ -d "$root/fuzz" ] || root="$(dirname "$here")"
out="${OUT:-$root/fuzz/out}"
mkdir -p "$out"

cd "$root/fuzz"
targets=$(cargo fuzz list)

if [ -n "${SANITIZER:-}" ]; then
    # OSS-Fuzz: its RUSTFLAGS already carry the sanitizer; cargo fuzz adds coverage.
    cargo fuzz build -O --debug-assertions
    dir="target/x86_64-unknown-linux-gnu/release"
else
    sanitizer=none
    toolchain=()
    if rustup toolchain list 2>/dev/null | grep -q '^nightly'; then
        toolchain=(+nightly)
        sanitizer=address
    fi
    cargo "${toolchain[@]}" fuzz build -O --debug-assertions --sanitizer "$sanitizer"
    dir="target/x86_64-unknown-linux-gnu/release"
fi

for t in $targets; do
    cp "$dir/$t" "$out/"
    if [ -d "corpus/$t" ] && [ -n "$(ls -A "corpus/$t")" ]; then
        (cd "corpus/$t" && zip -q -r "$out/${t}_seed_corpus.zip" . 2>/dev/null) ||
            echo "build.sh: zip not found, no seed corpus for $t" >&2
    fi
done
echo "build.sh: $(echo $targets | wc -w) targets in $out"
