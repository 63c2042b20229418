namespace AcShadow.Forge;

public static class Program
{
    public static int Main(string[] args) => ForgeApp.Run(args, Console.Out, Console.Error);
}
