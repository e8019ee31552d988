"""PlantGL's interpolated profiles: cross sections given at parameters, blended between them.

Ported from PlantGL, `src/openalea/plantgl/scenegraph/interpolated_profile.py` (`CrossSection`,
`InterpolatedProfile` alias `TemporalCurve`, `CSplineMethod`, `NurbsMethod`), openalea/plantgl at
commit 6e01c6db79ed1c61d81f71486a0a167105b8c0c4, licence CeCILL-C (author D. Barbeau et al.,
copyright INRIA - CIRAD - INRA). As in PlantGL:

- a `CrossSection((x, y), ...)` is a list of `Vector4(x, y, -1, 1)`; adding it at parameter t
  sets each point's third coordinate to t (normalised by `set_param_range`);
- with `CSplineMethod`, the j-th points of the sections (x, y, t), in the order of t, are joined
  by a cardinal spline (`plantgl_cspline`) whose knots are the differences of the t's, so
  `get_interpolated_section(t, False)` is the list of those splines' points at t (`Vector3(x, y,
  t)`), and at a section's own t it is that section; with `curve=True` it is the cardinal spline
  through those points;
- sections are cached per parameter until the next `update_interpolation`.

`NurbsMethod` (the default interpolator) builds PlantGL's C++ `NurbsPatch` and reads its
`getVSection`, which this package does not have: building a profile with it raises an error
that says so. `slice_patch` and the module's demonstration (Qt viewer) are not ported."""

from __future__ import annotations

import copy
import math

from .plantgl_cspline import cspline
from .plantgl_geometry import NurbsCurve, Point3Array, Point4Array
from .plantgl_math import Vector3, Vector4

NurbsCurve.CSpline = staticmethod(cspline)  # as PlantGL's scenegraph/__init__.py


class NurbsMethod:
    """PlantGL's NURBS-patch interpolator; not reproduced here (see the module's doc)."""

    @staticmethod
    def make_interpolation(curves, *args, **kargs):
        raise NotImplementedError(
            "InterpolatedProfile with NurbsMethod (PlantGL's NurbsPatch.getVSection) is not "
            "reproduced by Meristem; InterpolatedProfile(CSplineMethod) is")

    @staticmethod
    def make_section(pts, **kargs):
        return NurbsCurve(list(pts), degree=len(pts) - 1)


class CSplineMethod:
    class Patch:
        def __init__(self, curves, normalisedVDistances=None, normalisedUDistances=None, **kwargs):
            self._vs = [NurbsCurve.CSpline(pts, is_linear=False, distances=normalisedVDistances)
                        for pts in curves]
            us = list(zip(*curves))
            self._us = [NurbsCurve.CSpline(pts, is_linear=False, distances=normalisedUDistances[i])
                        for i, pts in enumerate(us)]

        def getVSection(self, v):
            return [x.getPointAt(v) for x in self._vs]

        def getUSection(self, u):
            return [x.getPointAt(u) for x in self._us]

        def real(self):
            return self

    @staticmethod
    def make_interpolation(curves, *args, **kargs):
        curves = [Point3Array(Vector3(p[0], p[1], p[2]) for p in c) for c in curves]
        return CSplineMethod.Patch(curves, *args, **kargs)

    @staticmethod
    def make_section(pts, distances=None, **kargs):
        pts = [Vector3(p[0], p[1], p[2]) for p in pts]
        return NurbsCurve.CSpline(pts, is_linear=False, distances=None)


class CrossSection(list):
    def __init__(self, *pointTuples):
        list.__init__(self, (Vector4(x[0], x[1], -1.0, 1) for x in pointTuples))


def normalise(p, lo, hi, is_distance=False):
    return p / float(hi - lo) if is_distance else (p - lo) / float(hi - lo)


def unnormalise(pn, lo, hi, is_distance=False):
    return pn * hi - lo * pn if is_distance else pn * hi - lo * (pn - 1)


def _line_length(line, xid=0, yid=1):
    """The length of the control points read as a polyline in (xid, yid)."""
    return sum(math.sqrt((b[xid] - a[xid]) ** 2 + (b[yid] - a[yid]) ** 2)
               for a, b in zip(line[:-1], line[1:])) if len(line) > 0 else 0.0


def _find_index_in_polyline(value, line, is_abscissa=True):
    """The index of the control point before which `value` falls, by relative polyline length."""
    xid, yid = (0, 1) if is_abscissa else (2, 1)
    total = _line_length(line, xid=xid, yid=yid)
    if total == 0.0:
        raise Exception("I'm too tired to know what I should do here")
    for i in range(1, len(line)):
        if _line_length(line[:i + 1], xid, yid) / total > value:
            return i
    return len(line)


def _lin_interpolation(norm_abs, p1, p2, xid=0, yid=1):
    xb, yb = p2[xid], p2[yid]
    xa, ya = p1[xid], p1[yid]
    assert xb != xa
    return ((yb - ya) / (xb - xa)) * (norm_abs - xb) + yb


class InterpolatedProfile(dict):
    """Cross sections by parameter (a dict t → CrossSection), blended by `Method`.

    `add_cross_section(s)` rebuilds the interpolation; moving a section's points does not
    (call `update_interpolation`). `tc(t)` is `get_interpolated_section(t)`."""

    _param_idx = 2  # the parameter (time, …) is the Vector4's z

    def __init__(self, interpolator=NurbsMethod):
        dict.__init__(self)
        self.Method = interpolator
        self._updt_cbk = []
        self._patch = None
        self._param_range = [0.0, 1.0]
        self._abscissa_range = [0.0, 1.0]
        self._epsilon = None  # when set, parameters closer than it are equal
        self._cached_sections = {}
        self._norm_to_real = {}
        self._sorted_tuples = []
        self.update_interpolation()

    @staticmethod
    def make_default():
        interpolator = InterpolatedProfile()
        interpolator.add_cross_sections(0.0, CrossSection((0.0, 0.0), (1.0, 0.0)),
                                        1.0, CrossSection((0.0, 0.0), (1.0, 0.0)))
        return interpolator

    def real(self):
        return dict((self._norm_to_real[k], v) for k, v in self.items())

    def as_sorted_tuples(self):
        return self._sorted_tuples

    # -- dict API --
    def __setitem__(self, parameter, value):
        if isinstance(value, (int, float)):  # move the curve at `parameter` to `value`
            if parameter not in self:
                return
            crv = self[parameter]
            dict.__delitem__(self, self.normalised_parameter(parameter))
            self[value] = crv
        else:
            self.add_cross_section(parameter, value)

    def __getitem__(self, parameter):
        parameter = self.normalised_parameter(parameter)
        pts = dict.get(self, self._epsilonised_parameter(self, parameter))
        if pts is not None:
            return pts
        raise Exception("No user-defined cross section at %s." % (str(parameter),)
                        + "Use the call operator.")

    def __delitem__(self, parameter):
        if parameter in self._param_range:
            return
        parameter = self.normalised_parameter(parameter)
        dict.__delitem__(self, self._epsilonised_parameter(self, parameter))
        self.update_interpolation()
        self._notify()

    def __contains__(self, parameter):
        if parameter is None:
            return False
        parameter = self.normalised_parameter(parameter)
        return self._epsilonised_parameter(self, parameter) is not None

    # -- queries --
    def check_control_point_count(self, section):
        """How many control points `section` has more than this profile's sections."""
        if len(self) > 0:
            return len(section) - len(next(iter(self.values())))
        return 0

    def update_interpolation(self):
        """Rebuilds the interpolation from the cross sections (at least two)."""
        num_sections = len(self)
        if num_sections < 2:
            return
        self._cached_sections.clear()
        self._norm_to_real = dict((k, self.unnormalised_parameter(k)) for k in self.keys())
        self._sorted_tuples = sorted(map(tuple, self.items()), key=lambda kv: kv[0])
        curves = [x[1] for x in self._sorted_tuples]
        normalised_u = [self._get_u_distances(c) for c in curves]
        curve_len = len(curves[0])
        columns = [Point4Array(c) for c in zip(*curves)]  # rows given, columns wanted
        self._patch = self.Method.make_interpolation(columns, udegree=curve_len - 1,
                                                     vdegree=num_sections - 1,
                                                     normalisedUDistances=normalised_u,
                                                     normalisedVDistances=self._get_v_distances())
        self._notify()

    @property
    def interpolating_surface(self):
        return self._patch.real()

    def get_interpolated_section(self, parameter, curve=True):
        """The section at `parameter`: a curve, or its control points when curve=False."""
        if not self._patch:
            return None
        parameter = self.normalised_parameter(parameter)
        eps_param = self._epsilonised_parameter(self._cached_sections, parameter)
        if eps_param is not None:
            pt_list = self._cached_sections[eps_param]
        else:
            pt_list = self._patch.getVSection(parameter)
            self._cached_sections[parameter] = pt_list
        return self.Method.make_section(pt_list) if curve else pt_list

    __call__ = get_interpolated_section

    def get_param_range(self):
        return self._param_range

    def get_abscissa_range(self):
        return self._abscissa_range

    def _get_u_distances(self, crv):
        if len(crv) < 2:
            return []
        return [self.normalised_abscissa(x[0] - y[0]) for x, y in zip(crv[1:], crv[:-1])]

    def _get_v_distances(self):
        steps = self.as_sorted_tuples()
        return [x[0] - y[0] for x, y in zip(steps[1:], steps[:-1])]

    # -- setters --
    def add_cross_section(self, parameter, section, autoUpdate=True, normalised=False):
        assert self._param_range[0] <= parameter <= self._param_range[1]
        section = copy.deepcopy(section)
        if self.check_control_point_count(section) != 0:
            raise Exception("Wrong control point count")
        nparameter = parameter if normalised else self.normalised_parameter(parameter)
        eps_param = self._epsilonised_parameter(self, nparameter)
        if eps_param is not None:  # a section there already: replace it
            nparameter = eps_param
        dict.__setitem__(self, nparameter, section)
        for point in section:
            point[InterpolatedProfile._param_idx] = nparameter
        if autoUpdate:
            self.update_interpolation()

    def add_cross_sections(self, *parameters_and_sections, **kargs):
        for i in range(0, len(parameters_and_sections), 2):
            t, s = parameters_and_sections[i], parameters_and_sections[i + 1]
            self.add_cross_section(t, s, autoUpdate=False, normalised=kargs.get("normalised"))
        self.update_interpolation()

    def set_param_range(self, min, max):
        self._param_range = [min, max]

    def set_abscissa_range(self, min, max):
        self._abscissa_range = [min, max]

    def add_update_callback(self, callback):
        self._updt_cbk.append(callback)

    # -- modifiers --
    def create_control_point(self, abscissa):
        """Inserts an interpolated control point in every section at `abscissa`."""
        abscissa = self.normalised_abscissa(abscissa)
        if abscissa == 1.0 or abscissa == 0.0 or not self._patch:
            return
        after_id = _find_index_in_polyline(abscissa, next(iter(self.values())), is_abscissa=True)
        pairs = [(c[after_id], c[after_id - 1]) for c in self.values()]
        pts = [Vector4(abscissa, _lin_interpolation(abscissa, before, after), after[2], 1)
               for after, before in pairs]
        self.insert_column_before(after_id, pts)

    def insert_column_before(self, index, controlPoints):
        """Inserts controlPoints[k] in the k-th section before column `index`."""
        assert len(controlPoints) == len(self)
        if self._patch:
            new_sections = []
            for line, (t, xsection) in enumerate(self.items()):
                xsection.insert(index, controlPoints[line])
                new_sections += [t, xsection]
            self.add_cross_sections(*new_sections, normalised=True)

    def create_cross_section(self, parameter):
        """Adds the section interpolated linearly at `parameter` to the defining sections."""
        if not self._patch:
            return
        nparameter = self.normalised_parameter(parameter)
        if dict.__contains__(self, nparameter):
            return
        columns = list(zip(*list(zip(*self.as_sorted_tuples()))[1]))
        after_id = _find_index_in_polyline(nparameter, next(iter(columns)), is_abscissa=False)
        pairs = [(c[after_id], c[after_id - 1]) for c in columns]
        section = CrossSection(*[(after[0], _lin_interpolation(nparameter, before, after, xid=2))
                                 for after, before in pairs])
        self.add_cross_section(parameter, section)

    def normalised_parameter(self, parameter, is_distance=False):
        return normalise(parameter, *self._param_range, is_distance)

    def normalised_abscissa(self, abscissa, is_distance=False):
        return normalise(abscissa, *self._abscissa_range, is_distance)

    def unnormalised_parameter(self, parameter, is_distance=False):
        return unnormalise(parameter, *self._param_range, is_distance)

    def unnormalised_abscissa(self, abscissa, is_distance=False):
        return unnormalise(abscissa, *self._abscissa_range, is_distance)

    normalise = staticmethod(normalise)
    unnormalise = staticmethod(unnormalise)

    def _epsilonised_parameter(self, mapping, key):
        """`key`, or the first key of `mapping` within epsilon of it; None when absent."""
        if self._epsilon:
            for k in mapping.keys():
                if abs(key - k) <= self._epsilon:
                    return k
            return None
        return key if key in mapping.keys() else None

    def _notify(self):
        for c in self._updt_cbk:
            c()


TemporalCurve = InterpolatedProfile  # PlantGL's alias

NAMES = {"CrossSection": CrossSection, "InterpolatedProfile": InterpolatedProfile,
         "TemporalCurve": TemporalCurve, "CSplineMethod": CSplineMethod, "NurbsMethod": NurbsMethod}
