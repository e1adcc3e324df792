#!/usr/bin/env python3
"""The checks LAMMPS's doc build makes of a page that can run without Sphinx, on the
package's .rst pages (docs/*.rst and docs/lammps/*.rst):

1. ASCII only (Modify_requirements.rst: "the .rst file must only use ASCII characters").
2. The page parses without a warning or an error (LAMMPS builds its manual with warnings
   as failures): docutils, with Sphinx's and LAMMPS's roles and directives stood in for
   by inert ones, so that what is checked is the reStructuredText itself (sections, lists,
   tables, inline markup, targets).
3. Every :doc:`...` link names a page of the tree's doc/src or one of the package's pages
   (Sphinx's reference check).
4. Spelling against LAMMPS's word list. `make spelling` (sphinxcontrib-spelling with an
   en_US dictionary) is not installed here, so the dictionary is stood in for by the words
   of LAMMPS's own manual (TREE/doc/src/*.rst, which passes LAMMPS's spell check) plus its
   false-positive list (TREE/doc/utils/sphinx-config/false_positives.txt); a word of the
   prose (not of literals, code or math) found in neither must be in the package's own list
   (docs/lammps/false_positives_GRANPEN.txt: the words a pull request adds to LAMMPS's).
   A typo is a word in none of the three, and fails.

    rst_lammps_checks.py LAMMPS_TREE GRANPEN_ROOT
    rst_lammps_checks.py --self-test LAMMPS_TREE
Exit 0: no finding; 1: findings (each printed as page:line: what); 2: usage.
"""
import glob
import io
import os
import re
import sys
import tempfile

import docutils.core
import docutils.nodes as nodes
from docutils.parsers.rst import Directive, directives, roles

WORD = re.compile(r"[A-Za-z]+(?:'[A-Za-z]+)*")


class Inert(Directive):
    """A Sphinx or LAMMPS directive: its content is kept as a literal block, unchecked."""
    has_content = True
    optional_arguments = 10
    final_argument_whitespace = True
    option_spec = None

    def run(self):
        return [nodes.literal_block("", "\n".join(self.content))]


class InertOptions(dict):
    """Accepts any directive option."""
    def __contains__(self, key):
        return True

    def __getitem__(self, key):
        return directives.unchanged


Inert.option_spec = InertOptions()


def literal_role(name, rawtext, text, lineno, inliner, options=None, content=None):
    return [nodes.literal(rawtext, text)], []


def register_sphinx():
    for d in ("index", "parsed-literal", "code-block", "sourcecode", "versionadded", "versionchanged",
              "deprecated", "seealso", "toctree", "only", "tabs", "tab", "table_from_list",
              "doxygenfunction", "doxygenclass", "cpp:function", "highlight", "centered"):
        directives.register_directive(d, Inert)
    for r in ("doc", "ref", "cpp:func", "cpp:class", "ref", "file", "command", "program", "option",
              "envvar", "term", "abbr", "numref", "py:func", "f:func", "c:func", "samp", "download"):
        roles.register_local_role(r, literal_role)


def prose_words(doctree):
    """(word, line) of the prose: text outside literals, code, math, raw and targets."""
    skip = (nodes.literal, nodes.literal_block, nodes.math, nodes.math_block, nodes.raw,
            nodes.target, nodes.reference, nodes.comment, nodes.substitution_definition)
    out = []
    for text in doctree.traverse(nodes.Text):
        p, inside = text.parent, False
        while p is not None:
            if isinstance(p, skip):
                inside = True
                break
            p = p.parent
        if inside:
            continue
        line = text.parent.line or (text.parent.parent.line if text.parent.parent else None) or 0
        for w in WORD.findall(text.astext()):
            out.append((w, line))
    return out


def known_words(tree, extra_lists):
    words = set()
    for page in glob.glob(os.path.join(tree, "doc", "src", "*.rst")):
        with open(page, encoding="utf-8", errors="replace") as f:
            words.update(w.lower() for w in WORD.findall(f.read()))
    lists = [os.path.join(tree, "doc", "utils", "sphinx-config", "false_positives.txt")] + extra_lists
    for path in lists:
        if os.path.exists(path):
            with open(path, encoding="utf-8", errors="replace") as f:
                words.update(l.strip().lower() for l in f if l.strip() and not l.startswith("#"))
    return words


DOC_LINK = re.compile(r":doc:`(?:[^`<]*<([^>`]+)>|([^`<]+))`")


def check_links(path, text, pages):
    findings = []
    for n, line in enumerate(text.split("\n"), 1):
        for m in DOC_LINK.finditer(line):
            target = (m.group(1) or m.group(2)).strip()
            if target not in pages:
                findings.append(f"{path}:{n}: :doc: link to '{target}', which is no page of LAMMPS or the package")
    return findings


def check_page(path, known, pages):
    findings = []
    raw = open(path, "rb").read()
    for n, line in enumerate(raw.split(b"\n"), 1):
        bad = [c for c in line if c > 127]
        if bad:
            findings.append(f"{path}:{n}: not ASCII: {line.decode('utf-8', 'replace').strip()[:60]}")
    text = raw.decode("utf-8", "replace")
    findings += check_links(path, text, pages)
    warnings = io.StringIO()
    doctree = docutils.core.publish_doctree(
        text, source_path=path,
        settings_overrides={"warning_stream": warnings, "report_level": 2, "halt_level": 5,
                            "file_insertion_enabled": False, "raw_enabled": False})
    for w in warnings.getvalue().splitlines():
        if re.match(r".*:\d+: \((WARNING|ERROR|SEVERE)/", w):
            findings.append(w)
    seen = set()
    for word, line in prose_words(doctree):
        k = word.lower()
        if k in known or k.strip("'s") in known or k in seen:
            continue
        # a possessive or plural of a known word: LAMMPS's spelling filter accepts those too
        if k.endswith("'s") and k[:-2] in known:
            continue
        seen.add(k)
        findings.append(f"{path}:{line}: unknown word '{word}' (a typo, or add it to "
                        "docs/lammps/false_positives_GRANPEN.txt)")
    return findings


def run(tree, pages, extra_lists):
    register_sphinx()
    known = known_words(tree, extra_lists)
    if len(known) < 1000:
        print(f"rst_lammps_checks: {tree}/doc/src gives only {len(known)} words: not a LAMMPS tree")
        return 2
    doc_pages = {os.path.basename(p)[:-4] for p in glob.glob(os.path.join(tree, "doc", "src", "*.rst"))}
    doc_pages |= {os.path.basename(p)[:-4] for p in pages}
    findings = []
    for page in pages:
        findings += check_page(page, known, doc_pages)
    for f in findings:
        print(f)
    if findings:
        print(f"rst_lammps_checks: {len(findings)} findings in {len(pages)} pages")
        return 1
    print(f"ok: {len(pages)} pages are ASCII, parse without warnings, link to existing pages and spell with LAMMPS's word list")
    return 0


def self_test(tree):
    with tempfile.TemporaryDirectory() as d:
        good = os.path.join(d, "good.rst")
        with open(good, "w") as f:
            f.write(".. index:: fix rod/drive\n\nfix rod/drive command\n=====================\n\n"
                    "Syntax\n\"\"\"\"\"\"\n\n.. code-block:: LAMMPS\n\n   fix ID group rod/drive v0\n\n"
                    "The force on the rod, see :doc:`fix move <fix_move>` and :math:`F = k z`.\n")
        typo = os.path.join(d, "typo.rst")
        with open(typo, "w") as f:
            f.write("Title\n=====\n\nThe forse on the rod.\n")
        utf = os.path.join(d, "utf.rst")
        with open(utf, "w", encoding="utf-8") as f:
            f.write("Title\n=====\n\nThe force \u2248 zero.\n")
        link = os.path.join(d, "link.rst")
        with open(link, "w") as f:
            f.write("Title\n=====\n\nSee :doc:`the fix <fix_rod_drove>`.\n")
        broken = os.path.join(d, "broken.rst")
        with open(broken, "w") as f:
            f.write("Title\n=====\n\n* a list\nwithout a blank line after it\n\n`unclosed\n")
        if run(tree, [good], []) != 0:
            print("SELF-TEST FAILED: a good page has findings")
            return 1
        for page, want in ((typo, "unknown word 'forse'"), (utf, "not ASCII"), (broken, "WARNING"),
                            (link, "link to 'fix_rod_drove'")):
            out = io.StringIO()
            stdout, sys.stdout = sys.stdout, out
            try:
                rc = run(tree, [page], [])
            finally:
                sys.stdout = stdout
            if rc != 1 or want not in out.getvalue():
                print(f"SELF-TEST FAILED: {os.path.basename(page)}: no '{want}' in:\n{out.getvalue()}")
                return 1
    print("self-test passed: a typo, a non-ASCII character, broken markup and a broken link found, a good page passes")
    return 0


def main(argv):
    if len(argv) == 3 and argv[1] == "--self-test":
        return self_test(argv[2])
    if len(argv) != 3:
        print(__doc__)
        return 2
    tree, root = argv[1], argv[2]
    pages = sorted(glob.glob(os.path.join(root, "docs", "*.rst")) +
                   glob.glob(os.path.join(root, "docs", "lammps", "*.rst")))
    if not pages:
        print(f"rst_lammps_checks: no .rst page in {root}/docs")
        return 1
    return run(tree, pages, [os.path.join(root, "docs", "lammps", "false_positives_GRANPEN.txt")])


if __name__ == "__main__":
    sys.exit(main(sys.argv))
