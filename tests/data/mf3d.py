# SPDX-License-Identifier: MIT
# Copyright (c) 2026 The Q3 authors
#
# Building blocks for the hand-laid binary test files of tests/data: each
# make_*_binary.py script lays its files out field by field with these, in
# either byte order ("<" little-endian, ">" big-endian as Mac QuickDraw 3D
# wrote them).
import os
import struct


def obj(order, tag, data):
    # An object: its four-character type (a 32-bit value, so reversed in a
    # little-endian file), its size, its data.
    code = tag if order == ">" else tag[::-1]
    return code + struct.pack(order + "I", len(data)) + data


def floats(order, *values):
    return struct.pack(order + "%df" % len(values), *values)


def uns(order, *values):
    return struct.pack(order + "%dI" % len(values), *values)


def ints(order, *values):
    return struct.pack(order + "%di" % len(values), *values)


def header(order, mode=0, toc=0):
    # 3DMF version 1.6; mode 0 Normal, 1 Stream, 2 Database; toc: the file
    # offset of the table of contents, 0 for none.
    tag = b"3DMF" if order == ">" else b"FMD3"
    return tag + struct.pack(order + "I", 16) + struct.pack(order + "HH", 1, 6) + struct.pack(order + "IQ", mode, toc)


def color_set(order, r, g, b):
    # An attribute set holding one diffuse colour.
    return obj(order, b"cntr", obj(order, b"attr", b"") + obj(order, b"kdif", floats(order, r, g, b)))


def write_both(directory, name, make):
    # Writes make(order) as name_be.3dmf and name_le.3dmf.
    for suffix, order in [("_be", ">"), ("_le", "<")]:
        with open(os.path.join(directory, name + suffix + ".3dmf"), "wb") as out:
            out.write(make(order))
