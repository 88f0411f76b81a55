"""`daran --help`, `daran COMMAND --help` and docs/cli.md agree: every
command the tool lists is documented with the same synopsis, and every
shared option it lists is in the doc's option table (no drive needed)."""
import os
import re
import unittest

import cli_support

DOC = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "docs", "cli.md")


def help_commands(text):
    """(name, synopsis) of each line under `Commands:` in --help."""
    commands = []
    section = text.split("Commands:\n", 1)[1].split("\n\n", 1)[0]
    for line in section.splitlines():
        if not line.startswith("  ") or line.startswith("   "):
            continue  # a summary continued under a long synopsis
        head = re.split(r"\s{2,}", line.strip())[0]
        name, _, synopsis = head.partition(" ")
        commands.append((name, synopsis))
    return commands


class HelpMatchesTheDoc(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        result = cli_support.daran(None, "--help")
        assert result.returncode == 0, result.stderr
        cls.help = result.stdout
        with open(DOC, encoding="utf-8") as f:
            cls.doc = f.read()

    def test_every_command_is_documented_with_its_synopsis(self):
        commands = help_commands(self.help)
        self.assertEqual(10, len(commands), commands)
        for name, synopsis in commands:
            with self.subTest(command=name):
                self.assertIn("\n## ", self.doc)
                self.assertRegex(self.doc, r"\n## [^\n]*\b%s\b" % re.escape(name))
                self.assertIn("daran %s %s" % (name, synopsis), self.doc)

    def test_every_command_help_starts_with_the_same_synopsis(self):
        for name, synopsis in help_commands(self.help):
            with self.subTest(command=name):
                result = cli_support.daran(None, name, "--help")
                self.assertEqual(0, result.returncode, result.stderr)
                self.assertTrue(result.stdout.startswith(
                    "Usage: daran [OPTIONS] %s %s\n" % (name, synopsis)), result.stdout)

    def test_every_shared_option_is_in_the_doc(self):
        options = re.findall(r"^  (--[a-z]+)", self.help, re.M)
        self.assertGreaterEqual(len(options), 7)
        for option in options:
            with self.subTest(option=option):
                self.assertIn("`%s" % option, self.doc)


if __name__ == "__main__":
    cli_support.main()
