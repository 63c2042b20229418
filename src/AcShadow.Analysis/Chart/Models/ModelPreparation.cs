using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Analysis.Chart.Models;

/// <summary>Prepares a model for an object so that a model that cannot prepare blocks nothing: the chart goes on and says why.</summary>
internal static class ModelPreparation
{
    public static PreparedModel Prepare(IShapeModel model, ChartSubject subject)
    {
        try
        {
            return model.Prepare(subject);
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            return new PreparedModel(new NothingCollides(), [], [new Diagnostic(ModelDiagnosticCodes.ModelFailed, $"{model.Name} could not prepare Setup 0x{subject.Setup.Id:X8}: {e.Message}")]);
        }
    }

    private sealed class NothingCollides : ISphereOverlap
    {
        public bool Overlaps(System.Numerics.Vector3 center, float radius) => false;
    }
}
