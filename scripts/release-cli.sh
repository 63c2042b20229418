# Sourced by the regenerate-* scripts: builds the Release CLI from the repository root and defines
# `acshadow` (an array) to run it. Committed output comes from the built-in sample, never from a dat the
# caller happens to have configured, so ACSHADOW_DAT is unset.
cd "$(dirname "${BASH_SOURCE[0]}")/.."
export DOTNET_CLI_TELEMETRY_OPTOUT=1 DOTNET_NOLOGO=1
unset ACSHADOW_DAT
dotnet build src/AcShadow.Cli -c Release --nologo -v quiet -clp:ErrorsOnly
acshadow=(dotnet src/AcShadow.Cli/bin/Release/net10.0/acshadow.dll)
