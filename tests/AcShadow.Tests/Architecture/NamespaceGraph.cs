using Mono.Cecil;
using Mono.Cecil.Cil;

namespace AcShadow.Tests.Architecture;

/// <summary>
/// Which of an assembly's namespaces use which, read from the compiled assembly (not the source's
/// <c>using</c> lines, which miss a child namespace's implicit view of its parent and name unused imports):
/// every type's base type, interfaces, attributes, fields, properties, events, method signatures, locals,
/// caught exceptions and the types, methods and fields its IL instructions name. A nested or compiler-made
/// type (a lambda's closure, an iterator) counts as its outermost declaring type's namespace.
/// </summary>
internal sealed class NamespaceGraph
{
    private readonly SortedDictionary<string, SortedDictionary<string, SortedSet<string>>> _uses = new(StringComparer.Ordinal);

    private NamespaceGraph(string assemblyName, IReadOnlyList<string> assemblyReferences)
    {
        AssemblyName = assemblyName;
        AssemblyReferences = assemblyReferences;
    }

    public string AssemblyName { get; }

    /// <summary>The names of the assemblies this one references.</summary>
    public IReadOnlyList<string> AssemblyReferences { get; }

    /// <summary>Every namespace of the assembly that declares a type (under its root namespace).</summary>
    public IReadOnlyCollection<string> Namespaces => _uses.Keys;

    /// <summary>The namespaces <paramref name="from"/> uses (itself excluded), each with the uses that make it one.</summary>
    public IReadOnlyDictionary<string, SortedSet<string>> Uses(string from) => _uses[from];

    /// <summary>Reads the assembly at <paramref name="path"/>, keeping the namespaces under <paramref name="root"/>.</summary>
    public static NamespaceGraph Read(string path, string root)
    {
        using var assembly = AssemblyDefinition.ReadAssembly(path);
        var module = assembly.MainModule;
        var graph = new NamespaceGraph(assembly.Name.Name, [.. module.AssemblyReferences.Select(r => r.Name)]);
        bool Ours(string ns) => ns == root || ns.StartsWith(root + ".", StringComparison.Ordinal);
        foreach (var type in module.GetTypes())
        {
            var from = NamespaceOf(type);
            if (Ours(from)) graph._uses.TryAdd(from, new(StringComparer.Ordinal));
        }

        foreach (var type in module.GetTypes())
        {
            var from = NamespaceOf(type);
            if (!Ours(from)) continue;
            var uses = graph._uses[from];
            new Walker(module, (to, use) =>
            {
                if (to == from || !Ours(to)) return;
                if (!uses.TryGetValue(to, out var why)) uses.Add(to, why = new(StringComparer.Ordinal));
                why.Add(use);
            }).Type(type);
        }

        return graph;
    }

    /// <summary>The namespace a type reference of this module belongs to: its outermost declaring type's.</summary>
    internal static string NamespaceOf(TypeReference type)
    {
        while (type.DeclaringType is { } outer) type = outer;
        return type.Namespace;
    }

    /// <summary>Walks one type's members, recording each namespace of the module it names.</summary>
    private sealed class Walker(ModuleDefinition module, Action<string, string> uses)
    {
        private string _where = "";

        public void Type(TypeDefinition type)
        {
            _where = type.FullName;
            Use(type.BaseType);
            foreach (var i in type.Interfaces) Use(i.InterfaceType);
            Generics(type.GenericParameters);
            Attributes(type.CustomAttributes);
            foreach (var f in type.Fields)
            {
                _where = $"{type.FullName}.{f.Name}";
                Use(f.FieldType);
                Attributes(f.CustomAttributes);
            }

            foreach (var p in type.Properties)
            {
                _where = $"{type.FullName}.{p.Name}";
                Use(p.PropertyType);
                Attributes(p.CustomAttributes);
            }

            foreach (var e in type.Events)
            {
                _where = $"{type.FullName}.{e.Name}";
                Use(e.EventType);
                Attributes(e.CustomAttributes);
            }

            foreach (var m in type.Methods) Method(type, m);
        }

        private void Method(TypeDefinition type, MethodDefinition method)
        {
            _where = $"{type.FullName}.{method.Name}";
            Use(method.ReturnType);
            Attributes(method.CustomAttributes);
            Attributes(method.MethodReturnType.CustomAttributes);
            Generics(method.GenericParameters);
            foreach (var p in method.Parameters)
            {
                Use(p.ParameterType);
                Attributes(p.CustomAttributes);
            }

            if (!method.HasBody) return;
            foreach (var v in method.Body.Variables) Use(v.VariableType);
            foreach (var h in method.Body.ExceptionHandlers) Use(h.CatchType);
            foreach (var instruction in method.Body.Instructions)
            {
                switch (instruction.Operand)
                {
                    case TypeReference t:
                        Use(t);
                        break;
                    case MethodReference m:
                        Member(m);
                        break;
                    case FieldReference f:
                        Use(f.DeclaringType);
                        Use(f.FieldType);
                        break;
                    case CallSite site:
                        Use(site.ReturnType);
                        foreach (var p in site.Parameters) Use(p.ParameterType);
                        break;
                }
            }
        }

        private void Member(MethodReference method)
        {
            Use(method.DeclaringType);
            Use(method.ReturnType);
            foreach (var p in method.Parameters) Use(p.ParameterType);
            if (method is GenericInstanceMethod generic)
                foreach (var a in generic.GenericArguments) Use(a);
        }

        private void Generics(IEnumerable<GenericParameter> parameters)
        {
            foreach (var g in parameters)
                foreach (var c in g.Constraints) Use(c.ConstraintType);
        }

        private void Attributes(IEnumerable<CustomAttribute> attributes)
        {
            foreach (var a in attributes)
            {
                Use(a.AttributeType);
                foreach (var argument in a.ConstructorArguments.Concat(a.Properties.Select(p => p.Argument)).Concat(a.Fields.Select(f => f.Argument)))
                {
                    Use(argument.Type);
                    if (argument.Value is TypeReference t) Use(t);
                }
            }
        }

        private void Use(TypeReference? type)
        {
            switch (type)
            {
                case null or GenericParameter:
                    return;
                case GenericInstanceType generic:
                    Use(generic.ElementType);
                    foreach (var a in generic.GenericArguments) Use(a);
                    return;
                case IModifierType modified:
                    Use(modified.ModifierType);
                    Use(modified.ElementType);
                    return;
                case FunctionPointerType pointer:
                    Use(pointer.ReturnType);
                    foreach (var p in pointer.Parameters) Use(p.ParameterType);
                    return;
                case TypeSpecification specification:
                    Use(specification.ElementType);
                    return;
            }

            if (type.Scope != module) return;
            uses(NamespaceOf(type), $"{_where} uses {type.FullName}");
        }
    }
}
