#!/usr/bin/env bash
# Regenerates the committed drawings under docs/view/ from the built-in forged sample: the sample door
# (`view --setup 0x020019FF`), the sample landblock with every model of every object (`view --landblock 0xA9B4`)
# and compiled by `scene` (`view --scene`). Idempotent: the
# output is byte-identical on every run and machine, so a rerun leaves no git diff; tests fail when they drift.
# Usage: scripts/regenerate-drawings.sh            (from anywhere; needs the .NET 10 SDK)
set -euo pipefail
source "$(dirname "$0")/release-cli.sh"

scene="$(mktemp -d "${TMPDIR:-/tmp}/acshadow-scene.XXXXXX")"
trap 'rm -rf "$scene"' EXIT
"${acshadow[@]}" view --setup 0x020019FF --out docs/view
"${acshadow[@]}" view --landblock 0xA9B4 --out docs/view
"${acshadow[@]}" scene --landblock 0xA9B4 --out "$scene" --quiet
"${acshadow[@]}" view --scene "$scene" --out docs/view
