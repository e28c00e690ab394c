#!/usr/bin/env python3
# This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
# See the LICENSE file at the top of the source tree.
"""The field lists of EssentialParams and EssentialReport, written from one table.

The table is the C++ declaration itself: the `#ifndef OPENCV_BINDING_PARSER` structs of
modules/essential/include/opencv2/essential/params.hpp, where each field has its type, its default
and its documentation, grouped by stage. Three more copies of the field list have to exist, because
the tools that read them cannot expand a macro or a template:
- the `#ifdef OPENCV_BINDING_PARSER` structs of the same header, which OpenCV's hdr_parser reads as
  text (it cannot read member initialisers) when the module is built inside OpenCV;
- the field visitors of python/src/params_report.cpp, from which the pybind11 attributes, keywords,
  repr and pickled state of cv_essential are made;
- the classes of python/cv_essential.pyi, the type stubs.
This script writes the three from the table:

    scripts/params_table.py           # rewrite the copies in place
    scripts/params_table.py --check   # exit 1, with a diff, if any copy differs (a ctest entry)

Standard library only.
"""

import argparse
import difflib
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
HEADER = ROOT / "modules/essential/include/opencv2/essential/params.hpp"
VISITORS = ROOT / "python/src/params_report.cpp"
STUBS = ROOT / "python/cv_essential.pyi"

# Python's name for each C++ field type; enums are ints in cv2 and in cv_essential.
PY_TYPES = {
    "std::string": "str",
    "double": "float",
    "int": "int",
    "int64": "int",
    "uint64": "int",
    "bool": "bool",
    "Matx33d": "Array",
    "Vec3d": "Array",
}
ENUM_TYPES = {"ScoreMethod", "SamplingMethod", "EssentialEngine", "EssentialDistance",
              "EssentialSampleBudget"}
# EssentialReport's fields that the visitor leaves out: success is bound by name, and E, R and t
# become numpy arrays (python/src/params_report.cpp binds them by hand).
REPORT_BY_HAND = {"success", "E", "R", "t"}


def strip_comments(text):
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    return re.sub(r"//[^\n]*", "", text)


def table(header_text, struct):
    """[(type, name)] of `struct`'s compiled declaration, in the header's order."""
    m = re.search(r"#ifndef OPENCV_BINDING_PARSER\nstruct CV_EXPORTS %s\n\{\n(.*?)\n\};" % struct,
                  header_text, re.S)
    if not m:
        sys.exit("params_table.py: no compiled declaration of %s in %s" % (struct, HEADER))
    fields = []
    for decl in strip_comments(m.group(1)).split(";"):
        decl = " ".join(decl.split())
        if not decl:
            continue
        d = re.fullmatch(r"([\w:]+) (\w+) = .+", decl)
        if not d:
            sys.exit("params_table.py: %s: cannot read the declaration '%s' (every field is "
                     "'type name = default;')" % (struct, decl))
        fields.append((d.group(1), d.group(2)))
    return fields


def py_type(cpp_type):
    if cpp_type in ENUM_TYPES:
        return "int"
    if cpp_type not in PY_TYPES:
        sys.exit("params_table.py: no Python type for the C++ type %s (add it to PY_TYPES)"
                 % cpp_type)
    return PY_TYPES[cpp_type]


def binding_block(struct, fields):
    # OpenCV 4.6's generator cannot convert an int64 attribute from Python, so int64 fields (the
    # report's pointsScored) are read-only there.
    lines = ["struct CV_EXPORTS_W_SIMPLE %s" % struct, "{", "    CV_WRAP %s();" % struct]
    for t, n in fields:
        lines.append("    %s %s %s;" % ("CV_PROP" if t == "int64" else "CV_PROP_RW", t, n))
    lines.append("};")
    return "\n".join(lines)


def visitor_lines(alias, fields):
    return "\n".join('    f("%s", &%s::%s);' % (n, alias, n) for _, n in fields)


def stub_lines(fields):
    return "\n".join("    %s: %s" % (n, py_type(t)) for t, n in fields)


def replace_once(text, pattern, replacement, where):
    new, count = re.subn(pattern, lambda m: m.group(1) + replacement + m.group(2), text,
                         flags=re.S)
    if count != 1:
        sys.exit("params_table.py: %s: expected one block matching %s, found %d"
                 % (where, pattern, count))
    return new


def generate():
    """{path: (current text, text as the table writes it)}."""
    header = HEADER.read_text()
    params = table(header, "EssentialParams")
    report = table(header, "EssentialReport")
    out = {}

    new = header
    for struct, fields in (("EssentialParams", params), ("EssentialReport", report)):
        new = replace_once(new, r"(#ifdef OPENCV_BINDING_PARSER\n)struct CV_EXPORTS_W_SIMPLE %s\n"
                           r"\{\n.*?\n\};(\n#endif)" % struct, binding_block(struct, fields),
                           HEADER.name)
    out[HEADER] = (header, new)

    visitors = VISITORS.read_text()
    new = replace_once(visitors, r"(void forEachParamField\(F&& f\)\n\{\n).*?(\n\})",
                       visitor_lines("Params", params), VISITORS.name)
    numbers = [(t, n) for t, n in report if n not in REPORT_BY_HAND]
    new = replace_once(new, r"(void forEachReportNumber\(F&& f\)\n\{\n).*?(\n\})",
                       visitor_lines("Report", numbers), VISITORS.name)
    out[VISITORS] = (visitors, new)

    stubs = STUBS.read_text()
    new = replace_once(stubs, r"(class EssentialParams:\n).*?(\n    def __init__)",
                       stub_lines(params), STUBS.name)
    new = replace_once(new, r"(class EssentialReport:\n).*?(\n\n)", stub_lines(report),
                       STUBS.name)
    out[STUBS] = (stubs, new)
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--check", action="store_true",
                    help="do not write; exit 1 with a diff if a copy differs from the table")
    args = ap.parse_args()
    stale = []
    for path, (current, new) in generate().items():
        if current == new:
            continue
        stale.append(path)
        if args.check:
            rel = str(path.relative_to(ROOT))
            sys.stdout.writelines(difflib.unified_diff(current.splitlines(True),
                                                       new.splitlines(True), rel, rel + " (table)"))
        else:
            path.write_text(new)
            print("params_table.py: rewrote %s" % path.relative_to(ROOT))
    if args.check:
        if stale:
            print("params_table.py: %d file(s) differ from the field table in %s; run "
                  "scripts/params_table.py to rewrite them" % (len(stale), HEADER.relative_to(ROOT)))
            return 1
        print("params_table.py: the binding block, the Python visitors and the stubs match %s"
              % HEADER.relative_to(ROOT))
    return 0


if __name__ == "__main__":
    sys.exit(main())
