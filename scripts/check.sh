#!/usr/bin/env bash
# What CI does: formatting, lints, docs and tests of the whole workspace.
set -euo pipefail
cd "$(dirname "$0")/.."

# A clean clone gains nothing from incremental compilation and its caches cost disk.
if [ -n "${CI:-}" ]; then
    export CARGO_INCREMENTAL=0
fi
df -h . | tail -n 1 | awk '{print "== disk: " $4 " free of " $2}'

echo "== cargo fmt --check"
cargo fmt --all -- --check
echo "== cargo clippy -D warnings"
cargo clippy --workspace --all-targets --locked -- -D warnings
echo "== cargo doc"
RUSTDOCFLAGS="-D warnings" cargo doc --workspace --no-deps --locked --quiet
echo "== cargo test"
cargo test --workspace --locked
# The executor's `profile` feature (and the inspector's per-node times built on it) is off
# in the builds above; lint and test it on its own (docs/performance.md). Benches are
# compiled (not run) by clippy --all-targets.
echo "== profile feature: clippy -D warnings, tests"
cargo clippy -p strider-vm -p strider -p strider-inspector --all-targets --no-deps --locked \
    --features strider-vm/profile,strider/profile,strider-inspector/profile -- -D warnings
cargo test -p strider-vm -p strider-inspector --locked \
    --features strider-vm/profile,strider-inspector/profile
# The root crate's profile tests need no inspector: leaving it out (no default features)
# saves rebuilding the window stack with another feature set.
cargo test -p strider --no-default-features --features profile --locked --test profile --test allocations
