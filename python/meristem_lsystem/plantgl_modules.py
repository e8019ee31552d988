"""Stand-ins for the modules L-Py models import (`openalea.plantgl.all`, `openalea.lpy`, …).

They are installed in `sys.modules` before a model runs, holding the PlantGL names models use
(plantgl_math, plantgl_geometry) and L-Py's Python names (`Lstring`, `ParameterSet`, …)."""

from __future__ import annotations

import sys
import types

from . import plantgl_geometry as geo
from . import plantgl_math as pmath
from . import plantgl_patch as patch
from . import plantgl_cspline, plantgl_profile
from .lstring import AxialTree, Lstring, Module


class ParameterSet:
    """L-Py's bag of named values: `ParameterSet(a=1)`, `p.a`, `p.set(b=2)`."""

    def __init__(self, **kw):
        self.__dict__.update(kw)

    def set(self, **kw):
        self.__dict__.update(kw)

    def setdefault(self, name, value=None, **kw):
        for k, v in ({name: value} if isinstance(name, str) else {}).items() | kw.items():
            self.__dict__.setdefault(k, v)
        return self.__dict__.get(name) if isinstance(name, str) else None

    def get(self, name, default=None):
        return self.__dict__.get(name, default)

    def hasattr(self, name):
        return name in self.__dict__

    def parameter_names(self):
        return list(self.__dict__)

    def copy(self, deep=True):
        import copy

        return copy.deepcopy(self) if deep else ParameterSet(**self.__dict__)

    def __contains__(self, name):
        return name in self.__dict__

    def __repr__(self):
        return "ParameterSet(" + ",".join(f"{k}={v!r}" for k, v in self.__dict__.items()) + ")"


def _math_names() -> dict:
    names = {n: getattr(pmath, n) for n in ("Vector2", "Vector3", "Vector4", "norm", "normalize",
                                             "cross", "dot", "angle", "direction", "Color3", "Color4")}
    names["Vec3"] = pmath.Vector3
    return names


def plantgl_names() -> dict:
    names = _math_names()
    for n in ("Point2Array", "Point3Array", "Point4Array", "Point4Matrix", "NurbsCurve2D",
              "NurbsCurve", "BezierCurve2D", "BezierCurve", "Polyline2D", "Polyline",
              "QuantisedFunction", "Material", "ImageTexture", "Texture2D", "Point3Grid", "pointset_mean_direction",
              "Discretizer"):
        names[n] = getattr(geo, n)
    names["NurbsPatch"], names["BezierPatch"] = patch.NurbsPatch, patch.BezierPatch
    names.update(geo.GEOMETRY)
    names["Color3Array"] = list
    names["Point3Matrix"] = geo.Point4Matrix
    names["Matrix3"] = pmath.Matrix3
    names["Matrix4"].IDENTITY = names["Matrix4"]()
    names["Color3"] = pmath.Color3
    names.update(eStatic=0, eAnimatedPrimitives=1, eAnimatedScene=2)
    return names


def lpy_names() -> dict:
    return {"Lstring": Lstring, "AxialTree": AxialTree, "Module": Module, "ParameterSet": ParameterSet,
            "ParamModule": Module}


def _module(name: str, values: dict, package: bool = False) -> types.ModuleType:
    mod = types.ModuleType(name)
    mod.__dict__.update(values)
    mod.__all__ = [k for k in values if not k.startswith("_")]
    if package:
        mod.__path__ = []
    return mod


def install(extra_lpy: dict) -> None:
    """Puts the stand-ins in `sys.modules` (replacing earlier ones: `extra_lpy` is per run)."""
    pgl = plantgl_names()
    lpy = {**lpy_names(), **extra_lpy}
    table = {
        "openalea": _module("openalea", {}, True),
        "openalea.plantgl": _module("openalea.plantgl", {}, True),
        "openalea.plantgl.all": _module("openalea.plantgl.all", pgl),
        "openalea.plantgl.math": _module("openalea.plantgl.math", _math_names()),
        "openalea.plantgl.scenegraph": _module("openalea.plantgl.scenegraph", pgl),
        "openalea.plantgl.scenegraph.interpolated_profile": _module(
            "openalea.plantgl.scenegraph.interpolated_profile", {**pgl, **plantgl_profile.NAMES}),
        "openalea.plantgl.scenegraph.cspline": _module(
            "openalea.plantgl.scenegraph.cspline",
            {"CSpline": plantgl_cspline.CSpline, "cspline": plantgl_cspline.cspline}),
        "openalea.lpy": _module("openalea.lpy", lpy, True),
        "openalea.lpy.parameterset": _module("openalea.lpy.parameterset", {"ParameterSet": ParameterSet}),
    }
    table["openalea"].plantgl = table["openalea.plantgl"]
    table["openalea"].lpy = table["openalea.lpy"]
    table["openalea.plantgl"].all = table["openalea.plantgl.all"]
    table["openalea.plantgl"].math = table["openalea.plantgl.math"]
    table["openalea.plantgl"].scenegraph = table["openalea.plantgl.scenegraph"]
    for sub in ("interpolated_profile", "cspline"):
        setattr(table["openalea.plantgl.scenegraph"], sub, table["openalea.plantgl.scenegraph." + sub])
    table["openalea.lpy"].parameterset = table["openalea.lpy.parameterset"]
    sys.modules.update(table)
