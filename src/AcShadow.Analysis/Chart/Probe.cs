using System.Numerics;

namespace AcShadow.Analysis.Chart;

/// <summary>
/// One query sphere in entity space. Doorway probes carry their line (0 = most negative offset) and the
/// line's lateral offset from the opening's centre in metres; grid probes have Line −1.
/// </summary>
public readonly record struct Probe(Vector3 Center, float Radius, ProbeKind Kind, int Line = -1, float Offset = 0f);
