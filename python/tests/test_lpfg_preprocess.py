"""The C preprocessor of L+C: macros, conditionals, includes, comments, kept line numbers."""

import unittest

from lpfg_support import run_lpfg, values, modules
from meristem_lsystem.lpfg.lexer import LpfgError
from meristem_lsystem.lpfg.preprocess import preprocess


def tokens(text, files=None):
    all_files = {"m.l": text}
    all_files.update(files or {})
    return [t[1] for t in preprocess(all_files, "m.l", [])]


class PreprocessorTest(unittest.TestCase):
    def test_object_and_function_like_macros_expand_with_their_arguments(self):
        src = "#define N 3\n#define SQ(x) ((x)*(x))\nSQ(N+1)"
        self.assertEqual(tokens(src), list("((N+1)*(N+1))".replace("N", "3")))

    def test_a_macro_call_may_span_lines(self):
        self.assertEqual(tokens("#define ADD(a,b) a+b\nADD(1,\n2)"), ["1", "+", "2"])

    def test_conditionals_choose_their_branch(self):
        src = "#define A 2\n#if A > 1\nyes\n#else\nno\n#endif\n#ifdef B\nb\n#endif\n#ifndef B\nnb\n#endif"
        self.assertEqual(tokens(src), ["yes", "nb"])

    def test_elif_and_undef(self):
        src = "#define X\n#undef X\n#if defined(X)\na\n#elif 1\nb\n#else\nc\n#endif"
        self.assertEqual(tokens(src), ["b"])

    def test_comments_go_and_lines_keep_their_numbers(self):
        toks = preprocess({"m.l": "/* one\ntwo */ a // three\nb"}, "m.l", [])
        self.assertEqual([(t[1], t[2]) for t in toks], [("a", 2), ("b", 3)])

    def test_own_headers_are_included_and_lpfgs_are_known(self):
        src = '#include <lpfgall.h>\n#include <math.h>\n#include "params.h"\nLEN'
        self.assertEqual(tokens(src, {"params.h": "#define LEN 7\n"}), ["7"])

    def test_a_missing_endif_is_an_error(self):
        with self.assertRaises(LpfgError):
            tokens("#if 1\na\n")

    def test_a_macro_in_a_model_reaches_its_productions(self):
        src = "#include <lpfgall.h>\n#define L(k) (2*k)\nderivation length: 1;\nAxiom: A;\nA(): { produce F(L(3)); }\n"
        self.assertEqual(values(src.replace("A(): {", "module A();\nA(): {")), [6.0])

    def test_the_axiom_and_productions_are_the_models_after_preprocessing(self):
        src = "#define STEPS 2\nderivation length: STEPS;\nAxiom: F(1);\nF(x): { produce F(x) F(x); }\n"
        self.assertEqual(len(modules(run_lpfg(src))), 4)


if __name__ == "__main__":
    unittest.main()
