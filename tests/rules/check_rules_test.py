#!/usr/bin/env python3
"""The house-rule checker against cases written by hand (ctest rules.checker): it must find a function of
101 lines and pass one of 100, see through comments, strings, lambdas and default arguments, and refuse
includes that run up the folders' order."""
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import check_rules as cr  # noqa: E402


def function(name, lines, header="int {}(int a, const std::vector<int>& v = {{}})"):
    """A function whose text spans exactly `lines` lines, braces included."""
    body = ["  a += 1;  // }"] * (lines - 2)
    return "\n".join([header.format(name) + " {"] + body + ["}"]) + "\n"


class Lengths(unittest.TestCase):
    def test_101_lines_is_a_breach_and_100_is_not(self):
        text = function("short_one", 100) + "\n" + function("long_one", 101)
        found = cr.long_functions_in(text)
        self.assertEqual([(f[1], f[2]) for f in found], [("long_one", 101)])

    def test_lambdas_strings_and_nested_blocks_count_toward_their_function(self):
        inner = ["  auto f = [&](int x) {", "    if (x) {", '      s += "{";', "    }", "  };"] * 20
        text = "void outer() {\n" + "\n".join(inner) + "\n}\n"
        self.assertEqual([(f[1], f[2]) for f in cr.long_functions_in(text)], [("outer", 102)])

    def test_classes_namespaces_and_initialisers_are_not_functions(self):
        table = "const std::vector<int> table = {\n" + "  1,\n" * 150 + "};\n"
        cls = "struct S {\n" + "  int a;\n" * 150 + "};\n"
        ns = "namespace x {\n" + function("small", 10) * 20 + "}\n"
        self.assertEqual(cr.long_functions_in(table + cls + ns), [])

    def test_a_member_function_inside_a_class_is_measured(self):
        text = "struct S {\n" + "\n".join("  " + l for l in function("member", 120).splitlines()) + "\n};\n"
        self.assertEqual([(f[1], f[2]) for f in cr.long_functions_in(text)], [("member", 120)])


class Includes(unittest.TestCase):
    def test_the_order(self):
        self.assertIsNone(cr.include_breach("numeric/region/a.hpp", "numeric/synthesis/b.hpp"))
        self.assertIn("comes before", cr.include_breach("numeric/synthesis/a.hpp", "numeric/region/b.hpp"))
        self.assertIn("comes before", cr.include_breach("numeric/io/a.hpp", "symbolic/b.hpp"))
        self.assertIn("no place", cr.include_breach("numeric/newrole/a.hpp", "numeric/io/b.hpp"))
        self.assertIn("consumer", cr.include_breach("commands/a.cpp", "tests/common/run_cli.hpp"))
        self.assertIn("nothing of the C++", cr.include_breach("embedded/src/a.c", "numeric/io/b.hpp"))
        self.assertIsNone(cr.include_breach("tests/x/a.cpp", "commands/calibration/calibrate.hpp"))
        self.assertIsNone(cr.include_breach("commands/a.cpp", "symbolic/b.hpp"))


class Flags(unittest.TestCase):
    def test_a_flag_in_message_text_is_a_breach(self):
        text = r'''throw UsageError("optimize: --positions " + n);
x = words("give {log FILE}");
v.text("--log");  // "--in a comment"
out << "# scalcal export --format px4";
auto r = R"(a raw --literal)";
char c = '\"'; s = "a --b";
'''
        found = cr.flag_breaches_in(text)
        self.assertEqual([line for line, _ in found], [1, 5, 6])


if __name__ == "__main__":
    unittest.main()
