"""The final string written in lpfg's own module syntax: `F(1.0)SB()Left(30)EB()`.

Numbers are written as Python writes them (`repr`; an infinite or NaN float as 0, with a
note); a `V3f`/`V2f` or any other struct is written
as its fields' numbers in order (`MoveTo3f(1.0,2.0,0.0)`), a string in double quotes with C
escapes (`Label("total florets")`), a list (array) as its items.
"""

import json
import math

from .runtime import _Struct


def _values(v, out, non_finite):
    if isinstance(v, bool):
        out.append("1" if v else "0")
    elif isinstance(v, int):
        out.append(repr(v))
    elif isinstance(v, float):
        if math.isfinite(v):
            out.append(repr(v))
        else:
            out.append("0")
            non_finite[0] += 1
    elif isinstance(v, str):
        out.append(json.dumps(v))
    elif isinstance(v, _Struct):
        for name in v._fields:
            _values(getattr(v, name), out, non_finite)
    elif isinstance(v, (list, tuple)):
        for x in v:
            _values(x, out, non_finite)
    elif v is None:
        out.append("0")
    else:
        out.append(json.dumps(str(v)))


def write_lstring(modules, notes=None):
    """The string; a note when a parameter was infinite or NaN (written 0, as the L-Py side does)."""
    non_finite = [0]
    parts = []
    for name, args in modules:
        values = []
        for a in args:
            _values(a, values, non_finite)
        parts.append(f"{name}({','.join(values)})")
    if non_finite[0] and notes is not None:
        notes.append({"line": 0, "message": f"{non_finite[0]} parameters were infinite or NaN (a C division by zero?): written 0"})
    return "".join(parts)
