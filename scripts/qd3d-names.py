#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Copyright (c) 2026 The Q3 authors
"""Counts Apple's QuickDraw 3D 1.6 names against include/Q3.

Apple's headers cannot ship with Q3, so the check reads them where a
maintainer has them (Universal Interfaces 3.4's CIncludes, or any folder
holding the 24 QD3D headers):

    scripts/qd3d-names.py --apple /path/to/CIncludes

For each of the 24 headers it lists the names Apple declares in its
portable parts (functions, enumeration constants, macros, typedefs, struct
tags; the parts under a Mac-only or Windows-only condition and the two
viewer headers are left out and counted apart), which of them include/Q3
declares, which docs/porting.md names as not provided (a backticked name,
or a `Prefix_*` pattern, in its "not provided" and "cannot exist" lists),
and the rest: names neither declared nor documented. It exits 1 when any
is left, so a name can only be missing with a reason.

`--self-test` runs the parser on a small header written for the test.
"""

import argparse
import pathlib
import re
import sys

HEADERS = [
    "QD3D.h", "QD3DAcceleration.h", "QD3DCamera.h", "QD3DController.h", "QD3DCustomElements.h",
    "QD3DDrawContext.h", "QD3DErrors.h", "QD3DExtension.h", "QD3DGeometry.h", "QD3DGroup.h", "QD3DIO.h",
    "QD3DLight.h", "QD3DMath.h", "QD3DPick.h", "QD3DRenderer.h", "QD3DSet.h", "QD3DShader.h",
    "QD3DStorage.h", "QD3DString.h", "QD3DStyle.h", "QD3DTransform.h", "QD3DView.h", "QD3DViewer.h",
    "QD3DWinViewer.h",
]
# Whole headers that exist only on one platform.
PLATFORM_HEADERS = {"QD3DViewer.h": "the Mac viewer", "QD3DWinViewer.h": "the Windows viewer"}
# A condition naming one of these guards a Mac-only or Windows-only part, or
# (XDC_OLD) the obsolete X draw context calls Apple's header leaves out.
PLATFORM_CONDITION = re.compile(
    r"TARGET_OS_MAC|TARGET_OS_WIN32|TARGET_API_MAC|WINDOW_SYSTEM_MACINTOSH|WINDOW_SYSTEM_WIN32|OS_MACINTOSH"
    r"|QD3D_NO_DIRECTDRAW|XDC_OLD")

IDENT = r"[A-Za-z_][A-Za-z0-9_]*"


def strip_comments(text):
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    return re.sub(r"//[^\n]*", " ", text)


def portable_lines(text):
    """The lines outside platform conditions, and the count of lines inside."""
    kept, stack = [], []  # stack: whether each open #if is a platform one
    for line in text.splitlines():
        directive = re.match(r"\s*#\s*(if|ifdef|ifndef|elif|else|endif)\b(.*)", line)
        if directive:
            kind, rest = directive.groups()
            if kind in ("if", "ifdef", "ifndef"):
                stack.append(bool(PLATFORM_CONDITION.search(rest)))
            elif kind == "elif":
                if stack:
                    stack[-1] = bool(PLATFORM_CONDITION.search(rest))
            elif kind == "else":
                if stack:
                    stack[-1] = False
            elif kind == "endif" and stack:
                stack.pop()
            continue
        if not any(stack):
            kept.append(line)
    return "\n".join(kept)


def declared_names(text):
    """Every name a header declares: functions, enumerators, macros, typedefs, tags."""
    text = strip_comments(text)
    names = set()
    for match in re.finditer(r"^\s*#\s*define\s+(" + IDENT + r")", text, flags=re.M):
        names.add(match.group(1))
    body = "\n".join(line for line in text.splitlines() if not re.match(r"\s*#", line))
    # Functions: Apple's EXTERN_API_C( type ) Name (...), Q3's Q3_EXTERN_API_C(type) Name(...).
    for match in re.finditer(r"EXTERN_API_C\s*\([^()]*(?:\([^()]*\))?[^()]*\)\s*(" + IDENT + r")\s*\(", body):
        names.add(match.group(1))
    # Callback typedefs: typedef CALLBACK_API_C( type , Name )( ... ).
    for match in re.finditer(r"CALLBACK_API_C\s*\([^,]*,\s*(" + IDENT + r")\s*\)", body):
        names.add(match.group(1))
    for match in re.finditer(r"typedef\s+[^;{(]*?\(\s*\*\s*(" + IDENT + r")\s*\)", body):
        names.add(match.group(1))
    # Enumerations: the constants, the tag and the typedef name.
    for match in re.finditer(r"enum\s*(" + IDENT + r")?\s*\{(.*?)\}", body, flags=re.S):
        if match.group(1):
            names.add(match.group(1))
        for item in match.group(2).split(","):
            constant = re.match(r"\s*(" + IDENT + r")", item)
            if constant:
                names.add(constant.group(1))
    # Struct and union tags, and the names a typedef gives.
    for match in re.finditer(r"\b(?:struct|union)\s+(" + IDENT + r")\s*\{", body):
        names.add(match.group(1))
    for match in re.finditer(r"typedef\s+(?:struct|union|enum)\s*(?:" + IDENT + r")?\s*\{.*?\}\s*(" + IDENT +
                             r")\s*;", body, flags=re.S):
        names.add(match.group(1))
    for match in re.finditer(r"typedef\s+([^;{}()]*?)\b(" + IDENT + r")\s*(?:\[[^\]]*\])?\s*;", body):
        names.add(match.group(2))
    for noise in ("const", "unsigned", "signed", "long", "short", "char", "int", "void", "float", "double",
                  "struct", "enum", "union"):
        names.discard(noise)
    return {name for name in names if not name.startswith("__")}


def documented_not_provided(porting):
    """Names and `Prefix_*` patterns docs/porting.md lists as not provided."""
    exact, prefixes = set(), []
    sections = re.split(r"\n(?=#+ )", porting)
    for section in sections:
        heading = section.splitlines()[0].lower() if section else ""
        relevant = "not declared" in heading or "cannot exist" in heading or "not yet provided" in heading
        paragraphs = section.split("\n\n") if relevant else [
            p for p in section.split("\n\n") if "not provided" in p.lower() or "not declared" in p.lower()]
        for paragraph in paragraphs:
            for token in re.findall(r"`([^`]+)`", paragraph):
                for word in re.findall(IDENT + r"\*?", token):
                    if word.endswith("*"):
                        prefixes.append(word[:-1])
                    else:
                        exact.add(word)
    return exact, prefixes


def count(apple_dir, q3_dir, porting_path):
    q3 = set()
    for header in sorted(pathlib.Path(q3_dir).glob("*.h")):
        q3 |= declared_names(header.read_text(errors="replace"))
    exact, prefixes = documented_not_provided(pathlib.Path(porting_path).read_text())
    missing_total = 0
    totals = [0, 0, 0, 0]
    print(f"{'header':24} {'Apple':>6} {'Q3':>5} {'documented':>10} {'platform':>8} {'missing':>7}")
    for name in HEADERS:
        path = pathlib.Path(apple_dir) / name
        if not path.exists():
            print(f"{name:24} not found in {apple_dir}")
            missing_total += 1
            continue
        text = strip_comments(path.read_text(errors="replace"))
        everything = declared_names(text)
        if name in PLATFORM_HEADERS:
            print(f"{name:24} {len(everything):6} {'':>5} {'':>10} {len(everything):8} {'':>7}  ({PLATFORM_HEADERS[name]})")
            continue
        portable = declared_names(portable_lines(text))
        platform = everything - portable
        declared = portable & q3
        documented = {n for n in portable - q3 if n in exact or any(n.startswith(p) for p in prefixes)}
        missing = sorted(portable - q3 - documented)
        for i, value in enumerate((len(portable), len(declared), len(documented), len(platform))):
            totals[i] += value
        print(f"{name:24} {len(portable):6} {len(declared):5} {len(documented):10} {len(platform):8} {len(missing):7}")
        for n in missing:
            print(f"    missing: {n}")
        missing_total += len(missing)
    print(f"{'together':24} {totals[0]:6} {totals[1]:5} {totals[2]:10} {totals[3]:8} {missing_total:7}")
    return 1 if missing_total else 0


SELF_TEST_HEADER = """
#ifndef __SAMPLE__
#define __SAMPLE__
#define kSampleMacro 3
enum SampleKind { kSampleA = 1, kSampleB };
typedef enum SampleKind SampleKind;
typedef struct SampleData { float x; } SampleData;
typedef unsigned long SampleCount;
typedef CALLBACK_API_C( TQ3Status , SampleMethod )(void *data);
EXTERN_API_C( TQ3Status )
Sample_Portable (SampleData * data);
#if TARGET_OS_MAC
EXTERN_API_C( TQ3Status )
Sample_MacOnly (void);
#else
EXTERN_API_C( TQ3Status )
Sample_Elsewhere (void);
#endif
/* EXTERN_API_C( TQ3Status ) Sample_Commented (void); */
#endif
"""


def self_test():
    text = strip_comments(SELF_TEST_HEADER)
    portable = declared_names(portable_lines(text))
    expected = {"kSampleMacro", "SampleKind", "kSampleA", "kSampleB", "SampleData", "SampleCount", "SampleMethod",
                "Sample_Portable", "Sample_Elsewhere"}
    everything = declared_names(text)
    exact, prefixes = documented_not_provided(
        "# Guide\n\n## Deliberately not declared\n\n- `Sample_MacOnly` and `Q3Mac_*`: Mac only.\n")
    checks = [
        (portable == expected, f"portable names {sorted(portable)}"),
        (everything - portable == {"Sample_MacOnly"}, f"platform names {sorted(everything - portable)}"),
        ("Sample_MacOnly" in exact and "Q3Mac_" in prefixes, f"documented {sorted(exact)} {prefixes}"),
    ]
    failed = [what for ok, what in checks if not ok]
    for what in failed:
        print("self-test failed:", what)
    return 1 if failed else 0


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--apple", help="the folder holding Apple's 24 QD3D headers")
    root = pathlib.Path(__file__).resolve().parent.parent
    parser.add_argument("--q3", default=str(root / "include" / "Q3"))
    parser.add_argument("--porting", default=str(root / "docs" / "porting.md"))
    parser.add_argument("--self-test", action="store_true")
    args = parser.parse_args()
    if args.self_test:
        return self_test()
    if not args.apple:
        parser.error("--apple is required (Apple's headers do not ship with Q3)")
    return count(args.apple, args.q3, args.porting)


if __name__ == "__main__":
    sys.exit(main())
