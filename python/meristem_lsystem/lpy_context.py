"""What an L-Py model sees of its L-system: `context()`, the turtle's set-up, the functions
`getIterationNb`, `useGroup`, `Stop`, `forward`/`backward`, `extern` … bound to one run."""

from __future__ import annotations

from .plantgl_geometry import Material


class Turtle:
    """The turtle's set-up a model makes in `__initialiseContext__` or its code."""

    def __init__(self):
        self.materials: dict[int, Material] = {}
        self.settings: dict[str, float] = {}

    def setMaterial(self, index, material):
        if isinstance(material, Material):
            self.materials[int(index)] = material

    def getMaterial(self, index):
        return self.materials.get(int(index), Material())

    def setColorList(self, materials):
        for i, m in enumerate(materials):
            self.setMaterial(i, m)

    def setAngleIncrement(self, angle):
        self.settings["angle_increment"] = float(angle)

    def setWidthIncrement(self, width):
        self.settings["width_increment"] = float(width)

    def setColorIncrement(self, inc):
        self.settings["color_increment"] = float(inc)

    def setScaleMultiplier(self, k):
        self.settings["scale_multiplier"] = float(k)

    def setDefaultStep(self, step):
        self.settings["default_step"] = float(step)

    def setWidth(self, width):
        self.settings["width"] = float(width)

    def __getattr__(self, name):
        # The viewer's settings (camera, selection, warnings) do not change the plant.
        if name.startswith("set") or name.startswith("enable") or name.startswith("disable"):
            return lambda *a, **k: None
        raise AttributeError(name)


class Options:
    """L-Py's option panel (`context.options.setSelection(...)`): editor settings only."""

    def setSelection(self, *args):
        pass

    def __getattr__(self, name):
        if name.startswith("set"):
            return lambda *a, **k: None
        raise AttributeError(name)


class Context:
    """`context` of `__initialiseContext__` and `context()`: the model's namespace and turtle."""

    def __init__(self, runtime):
        self._runtime = runtime
        self.turtle = Turtle()
        self.options = Options()
        self.animation_timestep = 0.0

    def __setitem__(self, name, value):
        ns = self._runtime.namespace
        if name == "__scalars__":
            for item in value:
                ns[item[0]] = scalar_value(item)
        elif name in ("__functions__", "__curves__"):
            for item in value:
                ns[item[0]] = item[1]
        ns[name] = value

    def __getitem__(self, name):
        return self._runtime.namespace[name]

    def __contains__(self, name):
        return name in self._runtime.namespace

    def __getattr__(self, name):
        api = self._runtime.api()
        if name in api:
            return api[name]
        if name.startswith("set") or name.startswith("enable"):
            return lambda *a, **k: None
        raise AttributeError(name)


def scalar_value(item):
    """A panel scalar: `(name, value, min, max)` or `(name, 'Integer'|'Float'|'Bool', value, …)`."""
    if len(item) > 2 and isinstance(item[1], str):
        value = item[2]
        return bool(value) if item[1] == "Bool" else value
    return item[1]
