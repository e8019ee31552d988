"""The derivation loop: parallel rewriting of a string by one kind of rule, and the steps.

A step walks the string once (forwards, or backwards after `backward()`), and at each module
tries the rules whose predecessor starts with its name (and the `*` rules), in the order of the
file; the first that matches and does not return None rewrites. The clock is read at every rule
application and the string's size after every step."""

from __future__ import annotations

import inspect
import time

_now = time.monotonic

from .lpy_errors import LimitReached
from .lpy_match import Reversed, end_of_branch, match_left, match_pred, match_right
from .lstring import Lstring, to_modules
from .lpy_turtle import fill_queries, has_query


def rule_table(rt, kind: str) -> dict:
    """Name → rules of `kind` active in the current group (declaration order), '*' → star rules."""
    key = (kind, rt.group)
    table = rt._tables.get(key)
    if table is None:
        table = {}
        # L-Py's __getRules: the group's rules, then group 0's, each in the file's order
        order = lambda r: (r.group != rt.group, r.order)
        chosen = sorted((r for r in rt.all_rules if r.spec.kind == kind and r.group in (0, rt.group)), key=order)
        for rule in chosen:
            table.setdefault(rule.first, []).append(rule)
        stars = table.pop("*", [])
        if stars:
            for name, rules in table.items():
                table[name] = sorted(rules + stars, key=order)
        table["*"] = stars
        rt._tables[key] = table
    return table


def try_rule(rt, rule, s, i, new, forward: bool):
    """(modules, length) when `rule` rewrites at `i` (forwards: starts there; backwards: ends)."""
    if rule.simple:
        args = s[i].args
        if len(args) != rule.nargs:
            return None
        length = 1
    else:
        got = match_rule(rt, rule, s, i, new, forward)
        if got is None:
            return None
        args, length = got
    if _now() > rt.deadline:
        raise LimitReached(f"the derivation passed the time limit ({rt.options.get('time_limit', 50)} s)")
    buffered = rt.nbuf
    buffered.clear()
    result = rule.func(*args)
    if result is None:
        if not buffered:
            return None
        return buffered[:], length
    if type(result) is not list:
        result = to_modules(result)
    return (buffered + result if buffered else result), length


def match_rule(rt, rule, s, i, new, forward: bool):
    """(bound parameters, predecessor length) when the rule's patterns match at `i`."""
    args: list = []
    start = i if forward else i - len(rule.pred) + 1
    if start < 0:
        return None
    filt = rt.filt
    if rule.left and not match_left(rule.left, s, start, args, filt):
        return None
    if rule.new_left and not match_left(rule.new_left, new if forward else s, len(new) if forward else start, args, filt):
        return None
    length = match_pred(rule.pred, s, start, args)
    if not length:
        return None
    end = start + length
    if rule.new_right:
        # `>>`: deriving backwards, the new string to the right is already built
        target, at = (s, end) if forward else (Reversed(new), 0)
        if not match_right(rule.new_right, 0, target, at, args, filt):
            return None
    if rule.right and not match_right(rule.right, 0, s, end, args, filt):
        return None
    return args, length


def rewrite(rt, s: list, kind: str, depth: int = 1) -> tuple[list, bool]:
    """One parallel rewriting of `s` by the rules of `kind`; (new string, whether any applied).

    With `depth` > 1 what a rule produced is rewritten again, alone, up to `depth` times
    (L-Py's `maximum depth` of decomposition and interpretation). `%` cuts its branch."""
    table = rule_table(rt, kind)
    stars = table["*"]
    if type(s) is not list:
        s = list(s)
    if len(table) == 1 and not stars and "%" not in table:
        return s, False
    if not rt.forward_dir:
        return rewrite_backward(rt, s, table)
    applied = False
    n = len(s)
    out: list = []
    i = 0
    buffered = rt.nbuf
    while i < n:
        m = s[i]
        if m.name == "%":
            i = end_of_branch(s, i + 1)
            continue
        for rule in table.get(m.name, stars):
            if rule.simple:
                # the common case inlined (one module, plain parameters, no context)
                args = m.args
                if len(args) != rule.nargs:
                    continue
                if _now() > rt.deadline:
                    raise LimitReached(f"the derivation passed the time limit ({rt.options.get('time_limit', 50)} s)")
                buffered.clear()
                result = rule.func(*args)
                if result is None:
                    if not buffered:
                        continue
                    produced = buffered[:]
                else:
                    if type(result) is not list:
                        result = to_modules(result)
                    produced = buffered + result if buffered else result
                length = 1
            else:
                got = try_rule(rt, rule, s, i, out, True)
                if got is None:
                    continue
                produced, length = got
            if depth > 1 and produced:
                produced, _ = rewrite(rt, produced, kind, depth - 1)
            out.extend(produced)
            i += length
            applied = True
            break
        else:
            out.append(m)
            i += 1
    return out, applied


def rewrite_backward(rt, s: list, table) -> tuple[list, bool]:
    """The same from the string's end (after `backward()`): predecessors end at the module."""
    applied = False
    chunks: list = []
    built = []  # what is built so far, last module first (read by `>>` through Reversed)
    i = len(s) - 1
    while i >= 0:
        m = s[i]
        for rule in candidates(rt, table, m.name):
            got = try_rule(rt, rule, s, i, built, False)
            if got is not None:
                chunks.append(got[0])
                built.extend(reversed(got[0]))
                i -= got[1]
                applied = True
                break
        else:
            chunks.append([m])
            built.append(m)
            i -= 1
    out = []
    for chunk in reversed(chunks):
        out.extend(chunk)
    return out, applied


def candidates(rt, table, name):
    """Backwards, a predecessor ends at the module: rules whose last pattern module is `name`."""
    key = ("last", id(table), name)
    got = rt._tables.get(key)
    if got is None:
        every = {id(r): r for rules in table.values() for r in rules}.values()
        got = sorted((r for r in every if r.pred[-1].name in (name, "*")), key=lambda r: (r.group != rt.group, r.order))
        rt._tables[key] = got
    return got


def max_depth(rt, kind: str) -> int:
    value = rt.namespace.get(f"__maximum_depth_{kind}__", 1)
    return max(1, int(value))


def decompose(rt, s: list, kind: str) -> tuple[list, bool]:
    s, applied = rewrite(rt, s, kind, max_depth(rt, kind))
    check_size(rt, s)
    return s, applied


def check_size(rt, s):
    if len(s) > rt.max_modules:
        raise LimitReached(f"the string grew to {len(s)} modules, over the limit of {rt.max_modules}")


def call_hook(rt, name: str, lstring):
    """Calls Start/StartEach/EndEach/End with as many of (lstring, scene) as it takes."""
    hook = rt.namespace.get(name)
    if not callable(hook):
        return None
    try:
        nparams = len(inspect.signature(hook).parameters)
    except (TypeError, ValueError):
        nparams = 0
    result = hook(*([lstring, None][:nparams]))
    if result is None or name in ("Start", "StartEach"):
        return None
    return Lstring(to_modules(result))


def derive(rt) -> Lstring:
    return derive_from(rt, rt.axiom(), 0, rt.derivation_length)


def derive_from(rt, s, start: int, steps: int) -> Lstring:
    """L-Py's `__derive` with its default options: every step runs even when no rule applies
    ("Early return when no matching" is Disabled by default), `Stop()` ends the loop early.
    Before a step whose production rules read turtle queries, the turtle fills them."""
    if start == 0:
        rt.iteration = 0
        call_hook(rt, "Start", s)
    done = 0
    for it in range(start, start + steps):
        rt.iteration = it
        call_hook(rt, "StartEach", s)
        if has_query(rt):
            s = fill_queries(rt, s)  # L-Py's __step: the turtle fills ?P, ?H … first
        s, _ = rewrite(rt, s, "production")
        check_size(rt, s)
        s, _ = decompose(rt, s, "decomposition")
        s = Lstring(s)
        replaced = call_hook(rt, "EndEach", s)
        if replaced is not None:
            s = replaced
        done = it + 1 - start
        if rt.stop_requested:
            break
    rt.steps_done = done
    if not rt.stop_requested:
        rt.iteration = start + steps
        replaced = call_hook(rt, "End", s)
        if replaced is not None:
            s = replaced
    return Lstring(s)


def interpret(rt, s) -> Lstring:
    saved = rt.forward_dir
    rt.forward_dir = True
    s, _ = decompose(rt, list(s), "interpretation")
    rt.forward_dir = saved
    return Lstring(s)
