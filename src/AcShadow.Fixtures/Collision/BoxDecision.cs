namespace AcShadow.Fixtures.Collision;

/// <summary>A test decided over a whole box of centres: false for every centre, true for every centre, or depending on the centre.</summary>
internal enum BoxDecision { False, True, Mixed }
