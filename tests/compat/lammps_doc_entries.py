#!/usr/bin/env python3
"""Add the GRANPEN package's entries to a scratch copy of a LAMMPS doc/src tree.

LAMMPS's doc checks (doc/utils/check-styles.py, check-packages.py) require every style to
be listed in the index pages (fix.rst, Commands_fix.rst, compute.rst, Commands_compute.rst,
Commands_all.rst) and every package in Packages.rst and Packages_details.rst. A package
offered upstream adds those lines; this script adds them to a copy, so that the checks can
run on the package as LAMMPS's CI would. The entries are written from the package's own
doc pages (docs/*.rst: the style names from their `.. index::` lines, the one-line
descriptions below), in LAMMPS's layout and in alphabetical order; the package's section of
Packages_details.rst is docs/lammps/Packages_details_GRANPEN.rst, inserted as it is.

    lammps_doc_entries.py GRANPEN_ROOT DOC_SRC_COPY
"""
import glob
import os
import re
import sys

DESCRIPTIONS = {
    "fix rod/drive": "drive a rigid rod of spheres into a granular bed at constant speed",
    "compute rod/drag": "drag force, contacts and depth of a rod driven by fix rod/drive",
    "compute bed/surface": "surface height and packing fraction of a granular bed",
    "compute flow/azimuthal": "azimuthally averaged flow fields about a rod's axis",
    "compute momentum/vbin": "grain counts and momentum by vertical-speed class",
    "create_rod": "create a rod of overlapping spheres",
    "restore_contact_history": "carry a restart's granular contact histories over to a new pair style",
}


def styles(root):
    found = []
    for page in sorted(glob.glob(os.path.join(root, "docs", "*.rst"))):
        with open(page) as f:
            first = f.readline().strip()
        m = re.match(r"^\.\. index:: (fix|compute)?\s*(\S+)$", first)
        if m:
            found.append((m.group(1) or "command", m.group(2), os.path.basename(page)[:-4]))
    return found


def insert_sorted(path, prefix_re, line, key):
    """Insert line among the lines matching prefix_re, by key (the style name)."""
    with open(path) as f:
        lines = f.read().split("\n")
    idx = [i for i, l in enumerate(lines) if re.match(prefix_re, l)]
    if not idx:
        raise SystemExit(f"{path}: no list matching {prefix_re!r}")
    at = idx[-1] + 1
    for i in idx:
        m = re.search(r":doc:`([^ <`]+)", lines[i])
        if m and m.group(1) > key:
            at = i
            break
    lines.insert(at, line)
    with open(path, "w") as f:
        f.write("\n".join(lines))


def main():
    root, doc = sys.argv[1], sys.argv[2]
    for kind, name, page in styles(root):
        desc = DESCRIPTIONS.get(f"{kind} {name}" if kind != "command" else name, "GRANPEN style")
        if kind == "fix":
            insert_sorted(os.path.join(doc, "fix.rst"), r"^\* :doc:`", f"* :doc:`{name} <{page}>` - {desc}", name)
            insert_sorted(os.path.join(doc, "Commands_fix.rst"), r"^   \* :doc:`", f"   * :doc:`{name} <{page}>`", name)
        elif kind == "compute":
            insert_sorted(os.path.join(doc, "compute.rst"), r"^\* :doc:`", f"* :doc:`{name} <{page}>` - {desc}", name)
            insert_sorted(os.path.join(doc, "Commands_compute.rst"), r"^   \* :doc:`", f"   * :doc:`{name} <{page}>`", name)
        else:
            insert_sorted(os.path.join(doc, "Commands_all.rst"), r"^   \* :doc:`", f"   * :doc:`{name} <{page}>`", name)
    # the package: a row of the package table (Packages_list.rst in 29Sep2021, Packages.rst in
    # some trees: whichever holds GRANULAR's row), an entry and a section in Packages_details.rst
    row = ("   * - :ref:`GRANPEN <PKG-GRANPEN>`\n     - rod penetration into granular beds\n"
           "     - :doc:`fix rod/drive <fix_rod_drive>`\n     - PACKAGES/granpen\n     - ext\n")
    granular_row = "   * - :ref:`GRANULAR <PKG-GRANULAR>`"
    tables = 0
    for name in ("Packages_list.rst", "Packages.rst"):
        path = os.path.join(doc, name)
        if not os.path.exists(path):
            continue
        with open(path) as f:
            text = f.read()
        if granular_row in text:
            with open(path, "w") as f:
                f.write(text.replace(granular_row, row + granular_row, 1))
            tables += 1
    if tables == 0:
        raise SystemExit(f"{doc}: no package table with a GRANULAR row (Packages_list.rst, Packages.rst)")
    det = os.path.join(doc, "Packages_details.rst")
    with open(det) as f:
        text = f.read()
    for anchor in ("   * :ref:`GRANULAR <PKG-GRANULAR>`", ".. _PKG-GRANULAR:"):
        if anchor not in text:
            raise SystemExit(f"{det}: no {anchor!r} to insert GRANPEN before")
    text = text.replace("   * :ref:`GRANULAR <PKG-GRANULAR>`",
                        "   * :ref:`GRANPEN <PKG-GRANPEN>`\n   * :ref:`GRANULAR <PKG-GRANULAR>`", 1)
    with open(os.path.join(root, "docs", "lammps", "Packages_details_GRANPEN.rst")) as f:
        section = f.read().rstrip("\n") + "\n\n----------\n\n"
    text = text.replace(".. _PKG-GRANULAR:", section + ".. _PKG-GRANULAR:", 1)
    with open(det, "w") as f:
        f.write(text)
    print(f"added {len(styles(root))} styles and the GRANPEN package to {doc}")


if __name__ == "__main__":
    main()
