namespace AcShadow.Core.Poses;

/// <summary>Which frame the parts are posed by (`--pose`).</summary>
public enum PosePolicy
{
    /// <summary>
    /// As a live object stands right after retail creates it: the current frame of its motion table's
    /// default state or of its DefaultAnimation; the placement frame only when it has neither.
    /// </summary>
    Retail,

    /// <summary>The Setup's placement frame (Resting, else Default), as the part array starts.</summary>
    Placement,
}

/// <summary>A door's motion (`--state`): closed = the Off substate, open = On.</summary>
public enum DoorState
{
    Closed,
    Open,
}

public static class PoseNames
{
    public static string Name(this PosePolicy pose) => pose == PosePolicy.Retail ? "retail" : "placement";

    public static string Name(this DoorState state) => state == DoorState.Closed ? "closed" : "open";

    public static bool TryParse(string text, out PosePolicy pose)
    {
        switch (text.ToLowerInvariant())
        {
            case "retail": pose = PosePolicy.Retail; return true;
            case "placement": pose = PosePolicy.Placement; return true;
            default: pose = default; return false;
        }
    }

    public static bool TryParse(string text, out DoorState state)
    {
        switch (text.ToLowerInvariant())
        {
            case "closed": state = DoorState.Closed; return true;
            case "open": state = DoorState.Open; return true;
            default: state = default; return false;
        }
    }
}
