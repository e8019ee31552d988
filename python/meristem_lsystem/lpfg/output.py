"""The final string written in lpfg's own module syntax: `F(1.0)SB()Left(30)EB()`.

Numbers are written as Python writes them (`repr`); a `V3f`/`V2f` or any other struct is written
as its fields' numbers in order (`MoveTo3f(1.0,2.0,0.0)`), a string in double quotes with C
escapes (`Label("total florets")`), a list (array) as its items.
"""

import json
import math

from .runtime import _Struct


def _values(v, out):
    if isinstance(v, bool):
        out.append("1" if v else "0")
    elif isinstance(v, int):
        out.append(repr(v))
    elif isinstance(v, float):
        out.append(repr(v) if math.isfinite(v) else ("nan" if v != v else ("inf" if v > 0 else "-inf")))
    elif isinstance(v, str):
        out.append(json.dumps(v))
    elif isinstance(v, _Struct):
        for name in v._fields:
            _values(getattr(v, name), out)
    elif isinstance(v, (list, tuple)):
        for x in v:
            _values(x, out)
    elif v is None:
        out.append("0")
    else:
        out.append(json.dumps(str(v)))


def write_lstring(modules):
    parts = []
    for name, args in modules:
        values = []
        for a in args:
            _values(a, values)
        parts.append(f"{name}({','.join(values)})")
    return "".join(parts)
