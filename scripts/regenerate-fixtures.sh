#!/usr/bin/env bash
# Regenerates fixtures/ — the golden output of `acshadow batch --doors --all` plus the sample landblock's
# scene and the sample door's movement cases (walked by the sample's mover) — from the built-in forged
# sample, in one run (one index.json that `acshadow verify` checks).
# Idempotent: the output is byte-identical on every run and machine, so a rerun leaves no git diff.
# Usage: scripts/regenerate-fixtures.sh            (from anywhere; needs the .NET 10 SDK)
set -euo pipefail
source "$(dirname "$0")/release-cli.sh"

# Write into a fresh folder first, so a failed run leaves the committed fixtures untouched.
staging="$(mktemp -d "${TMPDIR:-/tmp}/acshadow-fixtures.XXXXXX")"
trap 'rm -rf "$staging"' EXIT
"${acshadow[@]}" batch --doors --all --landblock 0xA9B4 --movement 0x020019FF --out "$staging" --quiet

# Replace only what batch writes (fixtures/README.md stays).
rm -rf fixtures/index.json fixtures/scene.json fixtures/setups fixtures/gfxobjs fixtures/cells fixtures/scenes fixtures/movement
mkdir -p fixtures
cp -R "$staging"/. fixtures/
"${acshadow[@]}" verify --fixtures fixtures
