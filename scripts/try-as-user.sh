#!/usr/bin/env bash
# Uses acshadow the way a collision project outside this repository would, and fails if any step does:
#   1. packs the AcShadow.Fixtures library and the acshadow .NET tool into a local folder (the "feed"), the tool
#      with scripts/pack-tool.sh: the RID-specific Native AOT package and the framework-dependent fallback;
#   2. installs the tool with the README's command (dotnet tool install --global --add-source FEED acshadow)
#      into a throwaway DOTNET_CLI_HOME, checks that what it put on the PATH is the native binary, and from
#      then on runs it from a fresh shell (env -i) by name; also installs the framework-dependent fallback (from a
#      feed whose acshadow package names only `any`, as a platform with no package of its own gets it) and runs it;
#   3. generates fixtures with the installed tool and verifies them;
#   4. creates a new xunit project in a temp folder OUTSIDE the repository, adds the AcShadow.Fixtures
#      package from the feed with `dotnet add package`, copies in the sample consumer test
#      (tests/AcShadow.Fixtures.Consumer/DoorCollisionTests.cs) and runs it.
# Usage: scripts/try-as-user.sh [--keep]     (--keep leaves the temp folder for inspection)
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
export DOTNET_CLI_TELEMETRY_OPTOUT=1 DOTNET_NOLOGO=1 DOTNET_SKIP_FIRST_TIME_EXPERIENCE=1
unset ACSHADOW_DAT

work="$(mktemp -d "${TMPDIR:-/tmp}/acshadow-user.XXXXXX")"
if [[ "${1:-}" == "--keep" ]]; then echo "keeping $work"; else trap 'rm -rf "$work"' EXIT; fi
case "$work" in "$repo"/*) echo "temp folder $work is inside the repository" >&2; exit 1;; esac
feed="$work/feed" home="$work/home" project="$work/door-collision" packages="$work/packages"
dotnet_root="$(dirname "$(readlink -f "$(command -v dotnet)")")"

step() { printf '\n== %s\n' "$*"; }
# A fresh shell: nothing from this one but HOME (NuGet's config) and the tool folder on PATH. Its own
# package cache, so a package packed here is never shadowed by an older one of the same version.
user() { printf '$ %s\n' "$*"; env -i HOME="$HOME" DOTNET_CLI_HOME="$home" DOTNET_ROOT="$dotnet_root" NUGET_PACKAGES="$packages" \
    DOTNET_CLI_TELEMETRY_OPTOUT=1 DOTNET_NOLOGO=1 PATH="$home/.dotnet/tools:$dotnet_root:/usr/bin:/bin" \
    bash -c "set -o pipefail; cd '$work' && $*"; }

step "pack the library and the tool into $feed"
dotnet pack "$repo/src/AcShadow.Fixtures" -c Release -o "$feed" --nologo -v quiet -clp:ErrorsOnly
"$repo/scripts/pack-tool.sh" "$feed"

step "install the tool as the README says"
user "dotnet tool install --global --add-source '$feed' acshadow"
user "acshadow --version"
# On the machine that packed it, the command on the PATH is the Native AOT binary itself: no runtime starts.
user "acshadow --version | grep -F '(Native AOT)' && file -L \$(command -v acshadow) | grep -F ELF"

step "the framework-dependent fallback, as a platform with no package of its own gets it"
# A feed whose acshadow package names only `any`: what a machine the packages were not built for installs.
mkdir -p "$work/feed-any" && cp "$feed"/acshadow.any.*.nupkg "$work/feed-any/"
dotnet pack "$repo/src/AcShadow.Cli" -c Release -o "$work/feed-any" -p:ToolPackageRuntimeIdentifiers=any --nologo -v quiet -clp:ErrorsOnly
user "dotnet tool install --tool-path '$work/fallback' --add-source '$work/feed-any' acshadow >/dev/null && '$work/fallback/acshadow' --version | grep -F 'runtime: .NET' | grep -vF 'Native AOT'"
user "'$work/fallback/acshadow' dump --setup 0x020019FF --out '$work/fallback-dump' 2>/dev/null; ls '$work/fallback-dump'"

step "generate fixtures with the installed tool (built-in sample: no dat needed)"
mkdir -p "$project"
user "acshadow batch --doors --all --landblock 0xA9B4 --format both --out '$project/fixtures' --quiet 2>/dev/null"
user "acshadow verify --fixtures '$project/fixtures' 2>/dev/null"
user "ls '$project/fixtures/gfxobjs' | grep 0x010044B"

step "tab completion from the installed tool"
user "source <(acshadow completions bash) && COMP_LINE='acshadow dump --se' COMP_POINT=18 COMP_WORDS=(acshadow dump --se) COMP_CWORD=2 && _acshadow_complete && echo \"completes: \${COMPREPLY[*]}\""

step "a new test project outside the repository, using the AcShadow.Fixtures package"
cat > "$project/nuget.config" <<XML
<?xml version="1.0" encoding="utf-8"?>
<configuration>
  <packageSources>
    <add key="acshadow-local" value="$feed" />
  </packageSources>
</configuration>
XML
mkdir -p "$project/DoorCollision.Tests"
cat > "$project/DoorCollision.Tests/DoorCollision.Tests.csproj" <<'XML'
<Project Sdk="Microsoft.NET.Sdk">
  <PropertyGroup>
    <TargetFramework>net10.0</TargetFramework>
    <Nullable>enable</Nullable>
    <ImplicitUsings>enable</ImplicitUsings>
    <IsTestProject>true</IsTestProject>
  </PropertyGroup>
  <ItemGroup>
    <PackageReference Include="Microsoft.NET.Test.Sdk" Version="18.0.1" />
    <PackageReference Include="xunit" Version="2.9.3" />
    <PackageReference Include="xunit.runner.visualstudio" Version="3.1.5" />
  </ItemGroup>
  <ItemGroup>
    <Using Include="Xunit" />
  </ItemGroup>
</Project>
XML
cp "$repo/tests/AcShadow.Fixtures.Consumer/DoorCollisionTests.cs" "$project/DoorCollision.Tests/"
user "cd '$project/DoorCollision.Tests' && dotnet add package AcShadow.Fixtures --version 0.2.0 | grep -E 'PackageReference|error' "
user "cd '$project/DoorCollision.Tests' && grep -n 'AcShadow' DoorCollision.Tests.csproj && grep -rl AcShadow.Fixtures obj/project.assets.json"

step "run the consumer test"
user "cd '$project/DoorCollision.Tests' && ACSHADOW_FIXTURES='$project/fixtures' dotnet test --nologo -v quiet 2>&1 | grep -E 'Passed!|Failed|error'"
