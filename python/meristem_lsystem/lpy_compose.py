"""`Lsystem('other.lpy')` inside a model: another L-system of the same files, run on demand.

L-Py models compose L-systems this way (one grows a structure, another reads it). The other
file is taken from the run's `files`; it shares the run's limits and clock."""

from __future__ import annotations

from .lpy_errors import ModelError
from .lstring import Lstring, StringReader, to_modules


class SubLsystem:
    def __init__(self, parent, filename, parameters=None):
        from .lpy_runtime import LpyRuntime

        name = str(filename).replace("\\", "/").split("/")[-1]
        if name not in parent.files:
            raise ModelError(f"Lsystem('{filename}'): no file of that name came with the model")
        options = dict(parent.options, steps=None)
        options["time_limit"] = max(0.0, parent.deadline - __import__("time").monotonic())
        self._rt = LpyRuntime(parent.files, name, options, parameters)
        reader = StringReader.current
        try:
            self._rt.load()
        finally:
            StringReader.current = reader

    @property
    def axiom(self):
        return self._rt.axiom()

    @property
    def derivationLength(self):
        return self._rt.derivation_length

    def derive(self, lstring=None, start=0, nbsteps=None):
        from .lpy_derive import derive_from

        if isinstance(lstring, int) and nbsteps is None:
            lstring, nbsteps = None, lstring
        if nbsteps is None and start and lstring is not None:
            nbsteps, start = start, 0
        s = self._rt.axiom() if lstring is None else Lstring(to_modules(lstring))
        n = self._rt.derivation_length if nbsteps is None else int(nbsteps)
        return derive_from(self._rt, s, start, n)

    def iterate(self, *args):
        return self.derive(*args)

    def interpret(self, lstring):
        from .lpy_derive import interpret

        return interpret(self._rt, lstring)

    homomorphism = interpret

    def __getattr__(self, name):
        ns = object.__getattribute__(self, "_rt").namespace
        if name in ns:
            return ns[name]
        raise AttributeError(name)

    def __setattr__(self, name, value):
        if name == "_rt":
            object.__setattr__(self, name, value)
        else:
            self._rt.namespace[name] = value
