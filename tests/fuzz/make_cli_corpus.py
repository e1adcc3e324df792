#!/usr/bin/env python3
"""The seed corpus of fuzz_cli_options (tests/fuzz/corpus/cli) and its dictionary
(tests/fuzz/cli.dict): every granpen command line of README.md and docs/*.md, one word a
line (the first the subcommand), and every option name the parsers define.
  python3 tests/fuzz/make_cli_corpus.py     (from the repository root; rewrites both)"""
import glob, hashlib, os, re, shlex

SUBCOMMANDS = "convert import check fit calibration collapse sweep flow momentum plot gap".split()
root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
out = os.path.join(root, "tests/fuzz/corpus/cli")
os.makedirs(out, exist_ok=True)
pattern = re.compile(r"granpen (%s)( [^`|\n]*)?" % "|".join(SUBCOMMANDS))
commands = set()
for doc in [os.path.join(root, "README.md")] + sorted(glob.glob(os.path.join(root, "docs/*.md"))):
    for m in pattern.finditer(open(doc, encoding="utf-8").read()):
        line = m.group(0).split("#")[0].rstrip(" \\")
        try:
            words = shlex.split(line)[1:]
        except ValueError:    # an unbalanced quote in prose
            continue
        # drop the usage lines' optional brackets, keep the words
        words = [w.strip("[]") for w in words if w.strip("[]") and w != "..."]
        commands.add("\n".join(words))
for old in glob.glob(os.path.join(out, "doc_*")):
    os.remove(old)
for c in sorted(commands):
    name = "doc_%s_%s" % (c.split("\n")[0], hashlib.sha1(c.encode()).hexdigest()[:8])
    with open(os.path.join(out, name), "w") as f:
        f.write(c)
options = set()
# the parse functions, and the option groups several of them add (ensemble_args.cpp)
for src in glob.glob(os.path.join(root, "analysis/cli/*_options.cpp")) + \
        glob.glob(os.path.join(root, "analysis/cli/*_args.cpp")):
    options.update(re.findall(r'"(--[A-Za-z0-9_-]+)', open(src).read()))
with open(os.path.join(root, "tests/fuzz/cli.dict"), "w") as f:
    f.write("# libFuzzer dictionary for fuzz_cli_options: subcommands, option names (made by\n"
            "# make_cli_corpus.py), the word separator and values at the edges of the checks\n")
    for s in SUBCOMMANDS + sorted(options) + ["--help", "-h"]:
        f.write('"%s\\x0a"\n' % s)
    for v in ["\\x0a", "0", "-1", "1", "2", "-0", "1e308", "1e-320", "nan", "inf", "-inf", "0x10", "1.5",
              "9999999999999999999", "19", "20", "1000001", "=", ":", "xy", "none", "auto", "voro++", "cgs", "si", "ave/time",
              "force", "ratio", "peak", "kz", "flow", "momentum"]:
        f.write('"%s"\n' % v)
print("%d commands, %d options" % (len(commands), len(options)))
