#!/usr/bin/env bash
# Regenerates the committed drawings under docs/view/ and docs/chart/ from the built-in forged sample: the sample
# door (`view --setup 0x020019FF`), the sample landblock with every model of every object (`view --landblock 0xA9B4`)
# and compiled by `scene` (`view --scene`), and the door's movement map and 0.45 m-offset walk per model
# (`chart --movement --walk`, docs/chart.md's door story). Idempotent: the
# output is byte-identical on every run and machine, so a rerun leaves no git diff; tests fail when they drift.
# Usage: scripts/regenerate-drawings.sh            (from anywhere; needs the .NET 10 SDK)
set -euo pipefail
source "$(dirname "$0")/release-cli.sh"

scene="$(mktemp -d "${TMPDIR:-/tmp}/acshadow-scene.XXXXXX")"
story="$(mktemp -d "${TMPDIR:-/tmp}/acshadow-story.XXXXXX")"
trap 'rm -rf "$scene" "$story"' EXIT
"${acshadow[@]}" view --setup 0x020019FF --out docs/view
"${acshadow[@]}" view --landblock 0xA9B4 --out docs/view
"${acshadow[@]}" scene --landblock 0xA9B4 --out "$scene" --quiet
"${acshadow[@]}" view --scene "$scene" --out docs/view
"${acshadow[@]}" chart --setup 0x020019FF --movement --walk closed/out-in/lat+0.450/hdg+00/walk --out "$story" --quiet > /dev/null
mkdir -p docs/chart
cp "$story/movement-map-0x020019FF.svg" docs/chart/
for model in fallback-cylinder spheres union part-boxes part-hulls retail; do
  cp "$story/movement-walk-0x020019FF-$model.svg" docs/chart/
done
