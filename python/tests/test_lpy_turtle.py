"""L-Py's turtle queries (?P, ?H, ?U, ?L, ?R, ?F) filled by PlantGL's turtle before each step.

Values are worked out by hand from PlantGL's frame (H = (0,0,1), L = (0,-1,0), U = (1,0,0);
`+` turns about U, `&` about L, `/` about H, right-handed)."""

from __future__ import annotations

import ast
import math
import re
import unittest

from lpy_helpers import collection_file, run_text
from meristem_lsystem import run

READ = """
production:
?P(x,y,z) A --> Z(x,y,z)
?H(x,y,z) B --> Z(x,y,z)
?U(x,y,z) C --> Z(x,y,z)
?L(x,y,z) D --> Z(x,y,z)
?R(x,y,z) E --> Z(x,y,z)
endlsystem
"""


def zs(lstring: str) -> list[tuple[float, ...]]:
    return [tuple(float(v) for v in g.split(",")) for g in re.findall(r"Z\(([^)]*)\)", lstring)]


class Queries(unittest.TestCase):
    def derive(self, axiom: str, rules: str = READ, steps: int = 1) -> list[tuple[float, ...]]:
        r = run_text(f"Axiom: {axiom}\nderivation length: {steps}\n{rules}")
        self.assertTrue(r["ok"], r["error"])
        return zs(r["lstring"])

    def assertVectors(self, got, want):
        self.assertEqual(len(got), len(want), got)
        for g, w in zip(got, want):
            for a, b in zip(g, w):
                self.assertAlmostEqual(a, b, places=9, msg=f"{got} != {want}")

    def test_position_and_frame_after_a_turn_and_a_move(self):
        # +(90): H turns about U (1,0,0) to (0,-1,0), L to (0,0,-1); F(2) moves to (0,-2,0)
        got = self.derive("+(90) F(2) ?P(0,0,0) A ?H(0,0,0) B ?U(0,0,0) C ?L(0,0,0) D ?R(0,0,0) E")
        self.assertVectors(got, [(0, -2, 0), (0, -1, 0), (1, 0, 0), (0, 0, -1), (0, 0, 1)])

    def test_pitch_down_then_move(self):
        # after +(90), &(90) turns H and U about L (0,0,-1): H = (-1,0,0), U = (0,-1,0); f(1)
        got = self.derive("+(90) F(2) &(90) f(1) ?P(0,0,0) A ?H(0,0,0) B ?U(0,0,0) C")
        self.assertVectors(got, [(-1, -2, 0), (-1, 0, 0), (0, -1, 0)])

    def test_roll_turns_up_and_left_about_the_heading(self):
        # /(90) about H (0,0,1): U (1,0,0) → (0,1,0), L (0,-1,0) → (1,0,0); then +(90) about the
        # new U turns H to the new L: (1,0,0)
        got = self.derive("/(90) ?U(0,0,0) C ?L(0,0,0) D +(90) ?H(0,0,0) B")
        self.assertVectors(got, [(0, 1, 0), (1, 0, 0), (1, 0, 0)])

    def test_branches_restore_the_state_and_interpretation_rules_move(self):
        # the branch's F(5) is undone by ]; W is drawn as F(3) by its interpretation rule
        rules = READ.replace("endlsystem", "interpretation:\nW --> F(3)\nendlsystem")
        got = self.derive("[ F(5) +(30) ] W ?P(0,0,0) A", rules)
        self.assertVectors(got, [(0, 0, 3)])

    def test_a_query_inside_nested_branches(self):
        # the branches that hold a query are walked, the others only skipped ([ ] restores all)
        got = self.derive("F(1) [ +(90) F(5) ] [ F(2) [ -(90) F(3) ?P(0,0,0) A ] ] F(4) ?P(0,0,0) A")
        self.assertVectors(got, [(0, 3, 3), (0, 0, 5)])

    def test_the_angle_increment_and_default_step_come_from_the_settings(self):
        src = ("context().turtle.setAngleIncrement(90)\ncontext().turtle.setDefaultStep(2)\n"
               "Axiom: + F ?P(0,0,0) A\nderivation length: 1\n" + READ)
        r = run_text(src)
        self.assertTrue(r["ok"], r["error"])
        self.assertVectors(zs(r["lstring"]), [(0, -2, 0)])

    def test_queries_are_filled_after_the_axiom_and_after_each_step(self):
        # each step reads where the previous string ends: one F(1) further each time
        rules = "production:\n?P(x,y,z) A --> F(1) Z(x,y,z) ?P(0,0,0) A\nendlsystem"
        got = self.derive("F(1) ?P(0,0,0) A", rules, steps=3)
        self.assertVectors(got, [(0, 0, 1), (0, 0, 2), (0, 0, 3)])

    def test_oriented_line_to_turns_the_heading_and_line_to_does_not(self):
        got = self.derive("OLineTo(3,0,4) ?H(0,0,0) B ?P(0,0,0) A")
        self.assertVectors(got, [(0.6, 0, 0.8), (3, 0, 4)])
        got = self.derive("LineTo(3,0,4) ?H(0,0,0) B")
        self.assertVectors(got, [(0, 0, 1)])

    def test_set_head_and_move_to(self):
        got = self.derive("@M(1,2,3) SetHead(0,1,0, 0,0,1) ?P(0,0,0) A ?L(0,0,0) D")
        # L = U × H = (0,0,1) × (0,1,0) = (-1,0,0)
        self.assertVectors(got, [(1, 2, 3), (-1, 0, 0)])

    def test_tropism_bends_each_move(self):
        # @Tp(1,0,0) @Ts(0.5): F turns H half way to the tropism first, 45° about (0,1,0)
        s = math.sqrt(0.5)
        got = self.derive("@Tp(1,0,0) @Ts(0.5) F(1) ?H(0,0,0) B ?P(0,0,0) A")
        self.assertVectors(got, [(s, 0, s), (s, 0, s)])

    def test_a_vector_or_no_parameter_and_the_frame(self):
        rules = ("production:\n?P(v) A --> Z(v[0],v[1],v[2])\n?H B --> Z(0)\n"
                 "?F(p,h,u,l) C --> Z(p.z,h.x,h.y,h.z,u.x,l.y)\nendlsystem")
        got = self.derive("F(2) ?P A ?F C", rules)
        self.assertVectors(got, [(0, 0, 2), (2, 0, 0, 1, 1, -1)])

    def test_no_query_rule_no_filling(self):
        # the query is read by no production: L-Py leaves its values as written
        r = run_text("Axiom: F(2) ?P(7,7,7)\nderivation length: 1\nproduction:\nF(x) --> F(x)\nendlsystem")
        self.assertTrue(r["ok"], r["error"])
        self.assertIn("?P(7,7,7)", r["lstring"])


class TurtleOnPatch(unittest.TestCase):
    """diffGeometry's turtle_on_patch: each B(u,v) draws OLineTo(patch(u,v)); the next step's
    ?H is the direction of that line, projected on the patch's unit tangents to advance (u, v)
    by 0.05. Worked out here from the patch alone, without the turtle."""

    def walk(self, patch, start, steps):
        def point(u, v):
            return [float(c) for c in patch.getPointAt(u, v)]

        def unit(vec):
            n = math.sqrt(sum(c * c for c in vec))
            return [c / n for c in vec]

        u, v = start
        previous = point(u, v)
        u += 0.05  # E(…, Vector2((1,0)), 1.5, 0.05) → G → B(u + 0.05, v)
        points = [point(u, v)]
        for _ in range(steps - 1):
            h = unit([a - b for a, b in zip(points[-1], previous)])
            du = sum(a * b for a, b in zip(unit(list(patch.getUTangentAt(u, v))), h))
            dv = sum(a * b for a, b in zip(unit(list(patch.getVTangentAt(u, v))), h))
            u, v = u + du * 0.05, v + dv * 0.05
            previous = points[-1]
            points.append(point(u, v))
        return points

    def test_the_walk_follows_the_patch(self):
        for path in ("models/diffGeometry/turtle_on_patch.lpy",
                     "share/tutorial/12 - curved-space/turtle_on_patch.lpy"):
            found = collection_file(path)
            self.assertIsNotNone(found, path)
            name, text = found
            r = run({name: text}, name, {})
            self.assertTrue(r["ok"], r["error"])
            lines = [tuple(float(c) for c in g.split(",")) for g in re.findall(r"OLineTo\(([^)]*)\)", r["lstring"])]
            # a point every 3 steps (G → B N, B → D ?H, ?H N → G) over 60 steps: 20 per path
            self.assertEqual(len(lines), 40)
            self.assertEqual(len(set(lines)), 40)
            from meristem_lsystem.plantgl_patch import NurbsPatch

            rows = ast.literal_eval(re.search(r"Point4Matrix\((\[\[.*\]\])\)", text).group(1))
            patch = NurbsPatch(rows)
            want = self.walk(patch, (0, 0.45), 5)
            for got, w in zip(lines[:5], want):
                for a, b in zip(got, w):
                    self.assertAlmostEqual(a, b, places=9)


if __name__ == "__main__":
    unittest.main()
