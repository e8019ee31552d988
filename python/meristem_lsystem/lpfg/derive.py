"""lpfg's derivation of a read model: `Start:`, the axiom, per step `StartEach:`, one parallel
rewriting (forward or, after `Backward()`, from the right end, so `>>` sees the new string),
decomposition to its maximum depth, `EndEach:`; then `End:` and interpretation to its maximum
depth. A production whose body ends without `produce` does not apply, and the next one is
tried (the current group's first, then group 0's). Modules are tuples `(name, args)`.
"""

from .lexer import LpfgError
from .matching import Reversed, Skipper, match_left, match_right, match_right_end, match_strict
from .runtime import StopDerivation, _f32, _int, _val
from .environment import environment_of
from .turtle import answer_queries

# lpfg's own modules whose parameters are floats (SetColor's are ints: it is left as written).
PREDEFINED_FLOATS = {
    "F", "f", "Left", "Right", "Up", "Down", "RollL", "RollR", "SetWidth", "Sphere", "Circle",
    "MoveTo", "MoveRel", "Line", "LineTo", "LineRel", "Cylinder", "Rhombus",
    "Triangle", "SetHead", "Sphere0", "Circle0", "Elasticity", "SetElasticity", "TropismDirection",
    "CurveScale", "Orient", "E1", "E2",
}
# lpfg's own modules with integer parameters (a colour or surface index): C truncates.
PREDEFINED_TYPED = {
    "SetColor": [_int], "CurrentTexture": [_int], "Surface": [_int, float],
    "Surface3": [_int, float, float, float],
}
COERCE = {"int": _int, "float": float, "f32": _f32, "bool": lambda v: 1 if v else 0}


class Engine:
    def __init__(self, model, namespace, runtime, max_modules, environment=None):
        self.model = model
        self.ns = namespace
        self.rt = runtime
        self.max_modules = max_modules
        runtime.max_modules = max_modules
        self.skipper = Skipper(model.ignore, model.consider)
        self.forward_index = {}  # (group, first name) -> productions
        self.backward_index = {}  # (group, last name) -> productions
        self.rules = {"decomposition": {}, "interpretation": {}}
        for p in model.productions:
            p.call = namespace[p.func]
            if p.section == "production":
                self.forward_index.setdefault((p.group, p.pred[0][0]), []).append(p)
                self.backward_index.setdefault((p.group, p.pred[-1][0]), []).append(p)
            elif getattr(p, "view", None) in (None, 0):  # the first view is the one drawn
                self.rules[p.section].setdefault((p.group, p.pred[0][0]), []).append(p)
        self.coercers = {name: None for name in PREDEFINED_FLOATS}
        self.coercers.update(PREDEFINED_TYPED)
        for name, types in model.modules.items():
            self.coercers[name] = [COERCE.get(t, _val) for t in types]
        self.environment = environment
        for key, depth in list(model.max_depth.items()):
            if isinstance(depth, str):
                model.max_depth[key] = namespace[depth]()
        if "_ring" in namespace:
            model.ring = bool(namespace["_ring"]())
        self.current_line = 0
        self.where = None
        self.context_state = {}
        namespace["_in_context"] = self.in_context

    # --- one production ---------------------------------------------------------------------
    def fire(self, p, args, where=None):
        """The successor of `p` with `args`, or None when its body produced nothing. `where`
        is (string, start, new string so far, new string to the right reversed), for the
        body's `InRightContext` and kin."""
        self.rt.tick()
        self.where = where
        self.context_state = {}
        self.current_line = self.rt.line = p.line
        self.rt.buffer = []
        if p.call(*args) is not True:
            return None
        out = self.rt.buffer
        return self.coerce(out)

    def coerce(self, out):
        """Parameters as the module's declaration types them (lpfg's own modules take floats)."""
        coercers = self.coercers
        for k, m in enumerate(out):
            name = m[0]
            if name not in coercers:
                continue
            c = coercers[name]
            if c is None:
                out[k] = (name, tuple(float(a) if type(a) is int else a for a in m[1]))
            elif len(c) == len(m[1]):
                out[k] = (name, tuple(f(a) for f, a in zip(c, m[1])))
        return out

    def candidates(self, index, name):
        group = self.rt.group
        found = index.get((group, name), [])
        if group != 0:
            found = found + index.get((0, name), [])
        return found

    def in_context(self, side, new, key, pattern):
        """The parameters of `pattern` beside the predecessor being rewritten, or None."""
        if self.where is None:
            return None
        s, start, p, out, out_rev = self.where
        pattern = [tuple(x) for x in pattern]
        if side == "left":
            if new:
                return None if out is None else match_left(out, len(out), pattern, self.skipper)
            return match_left(s, start, pattern, self.skipper)
        if new:
            if out_rev is None:
                return None
            seq, j = Reversed(out_rev), 0
        else:
            seq, j = s, start + len(p.pred)
        j = self.context_state.get(key, j)
        found = match_right_end(seq, j, pattern, self.skipper)
        if found is None:
            return None
        if pattern[0][0] == "SB":  # called again, the next branch
            self.context_state[key] = found[1]
        return found[0]

    # --- a derivation step ------------------------------------------------------------------
    def step_gillespie(self, s):
        """A ggroup step (Gillespie's algorithm): every applicable production gives its
        propensity; one of them, drawn in proportion, rewrites its predecessor alone."""
        reactions = []
        for i in range(len(s)):
            for p in self.forward_index.get((self.rt.group, s[i][0]), ()):
                args = self.match(p, s, i, None, None)
                if args is None:
                    continue
                self.rt.propensity = 1.0
                result = self.fire(p, args, (s, i, p, None, None))
                if result is not None:
                    if self.rt.propensity > 0:
                        reactions.append((self.rt.propensity, i, len(p.pred), result))
                    break
        if not reactions:
            return s
        pick = self.rt.rng.random() * sum(r[0] for r in reactions)
        for rate, i, width, result in reactions:
            pick -= rate
            if pick < 0:
                break
        return s[:i] + result + s[i + width:]

    def step(self, s):
        if self.rt.group in self.model.gillespie:
            return self.step_gillespie(cut(s))
        if self.rt.direction == "backward":
            return self.step_backward(s)
        s = cut(s)  # lpfg's DeriveForward skips from a Cut to the end of its branch
        out = []
        i, n = 0, len(s)
        while i < n:
            width = 0
            for p in self.candidates(self.forward_index, s[i][0]):
                args = self.match(p, s, i, out, None)
                if args is None:
                    continue
                result = self.fire(p, args, (s, i, p, out, None))
                if result is not None:
                    out.extend(result)
                    width = len(p.pred)
                    if len(out) > self.max_modules:
                        raise LpfgError(f"the string grew beyond {self.max_modules} modules at step {self.rt.step + 1}")
                    break
            if width:
                i += width
            else:
                out.append(s[i])
                i += 1
        return out

    def step_backward(self, s):
        out_rev = []
        i = len(s) - 1
        while i >= 0:
            width = 0
            for p in self.candidates(self.backward_index, s[i][0]):
                args = self.match(p, s, i - len(p.pred) + 1, None, out_rev)
                if args is None:
                    continue
                result = self.fire(p, args, (s, i - len(p.pred) + 1, p, None, out_rev))
                if result is not None:
                    out_rev.extend(reversed(result))
                    width = len(p.pred)
                    if len(out_rev) > self.max_modules:
                        raise LpfgError(f"the string grew beyond {self.max_modules} modules at step {self.rt.step + 1}")
                    break
            if width:
                i -= width
            else:
                out_rev.append(s[i])
                i -= 1
        out_rev.reverse()
        return out_rev

    def match(self, p, s, start, out, out_rev):
        # lpfg (TryMatchForward/Backward) skips a production whose new context lies on the
        # side not yet derived: `>>` when deriving forward, `<<` when backward.
        if (out is not None and p.right_new) or (out_rev is not None and p.left_new):
            return None
        args = match_strict(s, start, p.pred)
        if args is None:
            return None
        if self.model.ring and (p.left or p.right):
            return self.match_ring(p, s, start, args)
        if p.left:
            if p.left_new and out is not None:
                left = match_left(out, len(out), p.left, self.skipper)
            else:
                left = match_left(s, start, p.left, self.skipper)
            if left is None:
                return None
            args = left + args
        if p.right:
            if p.right_new and out_rev is not None:
                right = match_right(Reversed(out_rev), 0, p.right, self.skipper)
            else:
                right = match_right(s, start + len(p.pred), p.right, self.skipper)
            if right is None:
                return None
            args = args + right
        return args

    def match_ring(self, p, s, start, args):
        """A ring L-system: the string's end touches its start (for contexts)."""
        n = len(s)
        twice = s + s
        if p.left:
            left = match_left(twice, start + n, p.left, self.skipper)
            if left is None:
                return None
            args = left + args
        if p.right:
            right = match_right(twice, start + len(p.pred), p.right, self.skipper)
            if right is None:
                return None
            args = args + right
        return args

    # --- decomposition and interpretation ---------------------------------------------------
    def rewrite(self, s, section):
        """Each module replaced by its rule's successor, again in that, down to the section's
        maximum depth (an explicit stack: depths of a thousand are common). Contexts are
        matched in the string the module is in."""
        rules = self.rules[section]
        if not rules:
            return s
        out = []
        stack = [[s, 0, self.model.max_depth[section]]]
        while stack:
            top = stack[-1]
            seq, i, depth = top
            if i >= len(seq):
                stack.pop()
                continue
            result, width = None, 1
            if depth > 0:
                for p in self.candidates(rules, seq[i][0]):
                    args = self.match(p, seq, i, None, None)
                    if args is not None:
                        result = self.fire(p, args)
                        if result is not None:
                            width = len(p.pred)
                            break
            top[1] = i + width
            if result is None:
                out.append(seq[i])
                if len(out) > self.max_modules:
                    raise LpfgError(f"the string grew beyond {self.max_modules} modules during {section}")
            else:
                stack.append([result, 0, depth - 1])
        return out

    # --- the whole run ----------------------------------------------------------------------
    def hook(self, name):
        if name in self.model.hooks:
            self.ns[name]()

    def run(self, steps):
        """(final string after interpretation, steps derived)."""
        self.hook("_start")
        if steps is None:
            steps = self.ns["_derivation_length"]() if self.model.has_length else 0
        self.rt.buffer = []
        if "_axiom" not in self.ns:
            raise LpfgError("the model has no Axiom:", self.model.last_line, 1)
        self.ns["_axiom"]()
        s = self.rewrite(self.fire_axiom(), "decomposition")
        done = 0
        try:
            while done < steps and not self.rt.stop:
                self.rt.step = done
                s = self.settle(s)
                self.hook("_start_each")
                s = self.rewrite(self.step(s), "decomposition")
                done += 1
                if len(s) > self.max_modules:
                    raise LpfgError(f"the string grew beyond {self.max_modules} modules at step {done}")
                self.hook("_end_each")
            self.hook("_end")
        except StopDerivation:
            pass
        return self.rewrite(s, "interpretation"), done

    def settle(self, s):
        """What lpfg does before each step (`InterpretForEnvironment`): the turtle answers
        `GetPos` and the other queries, the environment the `E1`/`E2` modules."""
        if not self.rt.environment_on:
            return s
        return answer_queries(self, s, self.environment)

    def fire_axiom(self):
        return list(self.coerce(self.rt.buffer))


def cut(s):
    """`s` without each `Cut()` and what follows it up to the end of its branch."""
    if not any(m[0] == "Cut" for m in s):
        return s
    out = []
    i, n = 0, len(s)
    while i < n:
        if s[i][0] != "Cut":
            out.append(s[i])
            i += 1
            continue
        depth = 0
        i += 1
        while i < n:
            name = s[i][0]
            if name == "SB":
                depth += 1
            elif name == "EB":
                if depth == 0:
                    break
                depth -= 1
            i += 1
    return out
