using System.Numerics;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Analysis.Chart.Models;

/// <summary>
/// Each retail BSP part's bounding sphere only (the root sphere, posed and scaled as retail poses the
/// part): the broad phase taken for the answer. Objects without BSP parts get nothing.
/// </summary>
internal sealed class PartSpheresModel : IShapeModel
{
    public string Name => "part-spheres";
    public string Description => "each retail BSP part's bounding sphere, nothing else";

    public PreparedModel Prepare(ChartSubject subject)
    {
        var set = subject.Build(subject.Options(ShapePolicy.Retail));
        var shapes = set.Shapes
            .Where(s => s.CollisionType == CollisionType.Bsp && s.LocalSphere is not null)
            .Select(s => new ShadowShape(ShapeSource.Part, s.SourceIndex, s.GfxObjId, CollisionType.Sphere, s.LocalSphere!.Value.Center, Quaternion.Identity, s.Scale, s.LocalSphere.Value.Radius, 0f, null));
        return PreparedModel.Of(shapes, subject);
    }
}
