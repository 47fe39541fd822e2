#!/usr/bin/env python3
"""Reads a USD stage with Pixar's own library (usd-core) and prints, as JSON, what a test needs to hold
a recording to the simulation: the stage's metadata, every prim with its type, the cloth's counts,
topology check and points at the asked time codes, and each collider's attributes and local-to-world
transform at those codes. Errors the library raises are reported, not hidden: {"error": "..."}.

Usage: usd_read.py FILE.usda [TIMECODE ...]
(run by the tests with the project's virtual environment, .venv/bin/python, which scripts/deps --headless makes)
"""
import json
import sys

from pxr import Usd, UsdGeom, UsdValidation, Tf


def main(path, codes):
    try:
        stage = Usd.Stage.Open(path)
    except Tf.ErrorException as e:
        return {"error": str(e)}
    if stage is None:
        return {"error": "Usd.Stage.Open returned nothing"}
    validators = UsdValidation.ValidationRegistry().GetOrLoadAllValidators()
    problems = [e.GetMessage() for e in UsdValidation.ValidationContext(validators).Validate(stage)]
    out = {
        "validators": len(validators),
        "validationErrors": problems,
        "upAxis": UsdGeom.GetStageUpAxis(stage),
        "metersPerUnit": UsdGeom.GetStageMetersPerUnit(stage),
        "timeCodesPerSecond": stage.GetTimeCodesPerSecond(),
        "framesPerSecond": stage.GetFramesPerSecond(),
        "startTimeCode": stage.GetStartTimeCode(),
        "endTimeCode": stage.GetEndTimeCode(),
        "defaultPrim": str(stage.GetDefaultPrim().GetPath()),
        "prims": {},
    }
    for prim in stage.Traverse():
        p = {"type": prim.GetTypeName()}
        custom = {a.GetName(): a.Get() for a in prim.GetAttributes() if a.IsCustom()}
        p["custom"] = {k: v for k, v in custom.items() if isinstance(v, (str, float, int))}
        if prim.IsA(UsdGeom.Mesh):
            mesh = UsdGeom.Mesh(prim)
            counts = mesh.GetFaceVertexCountsAttr().Get()
            indices = mesh.GetFaceVertexIndicesAttr().Get()
            points = mesh.GetPointsAttr()
            n = len(points.Get(codes[0] if codes else Usd.TimeCode.Default()))
            ok, why = UsdGeom.Mesh.ValidateTopology(indices, counts, n)
            p.update(faces=len(counts), corners=len(indices), points=n, topologyValid=bool(ok), topologyProblem=why,
                     pointSampleCount=points.GetNumTimeSamples())
            st = UsdGeom.PrimvarsAPI(prim).GetPrimvar("st")
            if st:
                p["st"] = {"count": len(st.Get()), "interpolation": st.GetInterpolation(), "type": str(st.GetTypeName())}
            normals = mesh.GetNormalsAttr()
            if normals.HasAuthoredValue():
                p["normals"] = {"interpolation": mesh.GetNormalsInterpolation(), "count": len(normals.Get(codes[0] if codes else 0))}
        if prim.IsA(UsdGeom.PointBased):
            attr = UsdGeom.PointBased(prim).GetPointsAttr()
            p["pointsAt"] = {str(c): [list(v) for v in attr.Get(c)] for c in codes}
        if prim.IsA(UsdGeom.Xformable):
            xf = UsdGeom.Xformable(prim)
            p["transformAt"] = {str(c): [list(row) for row in xf.ComputeLocalToWorldTransform(c)] for c in codes}
        for name in ("radius", "height", "size", "axis"):
            a = prim.GetAttribute(name)
            if a and a.HasAuthoredValue():
                p[name] = a.Get()
        out["prims"][str(prim.GetPath())] = p
    return out


if __name__ == "__main__":
    result = main(sys.argv[1], [float(c) for c in sys.argv[2:]])
    json.dump(result, sys.stdout)
    sys.stdout.write("\n")
