#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Copyright (c) 2026 The Q3 authors
#
# Writes the binary test files of tests/data, laid out field by field as the
# 3D Metafile Reference describes them, big-endian as Mac QuickDraw 3D wrote
# them and little-endian. Run from anywhere: python3 tests/data/make_binary.py
import os
import struct

from mf3d import floats, header, obj

here = os.path.dirname(os.path.abspath(__file__))


def triangle_file(order):
    # A red triangle with a blue corner.
    red = obj(order, b"cntr", obj(order, b"attr", b"") + obj(order, b"kdif", floats(order, 1, 0, 0)))
    blue = obj(order, b"cntr", obj(order, b"attr", b"") + obj(order, b"kdif", floats(order, 0, 0, 1)))
    vasl = obj(order, b"cntr",
               obj(order, b"vasl", struct.pack(order + "IIIII", 3, 1, 2, 0, 2)) + blue)
    tri = obj(order, b"trng", floats(order, -1, -1, 0, 1, -1, 0, 0, 1, 0))
    return header(order, 0, 0) + obj(order, b"cntr", tri + red + vasl)


def references_file(order, toc_entry_type=1):
    # Two triangles in a display group sharing one attribute set: the second
    # refers to the first's set through the table of contents. Its entries
    # carry the object's type (entry type 1, 16 bytes) as QuickDraw 3D 1.5
    # and later write them, or not (type 0, 12 bytes) as QuickDraw 3D 1.0
    # wrote a normal file's.
    green = obj(order, b"cntr", obj(order, b"attr", b"") + obj(order, b"kdif", floats(order, 0, 1, 0)))
    first_tri = obj(order, b"trng", floats(order, -2, -1, 0, 0, -1, 0, -1, 1, 0))
    second_tri = obj(order, b"trng", floats(order, 0, -1, 0, 2, -1, 0, 1, 1, 0))
    begin = obj(order, b"bgng", obj(order, b"dspg", b""))
    body = begin
    first_container_offset = 24 + len(body)
    first = obj(order, b"cntr", first_tri + green)
    set_offset = first_container_offset + 8 + len(first_tri)
    body += first
    body += obj(order, b"cntr", second_tri + obj(order, b"rfrn", struct.pack(order + "I", 1)))
    body += obj(order, b"endg", b"")
    toc_offset = 24 + len(body)
    entry = struct.pack(order + "IQ", 1, set_offset)
    if toc_entry_type == 1:
        entry += b"attr" if order == ">" else b"rtta"
    toc = obj(order, b"toc ", struct.pack(order + "QIiIII", 0, 2, 0, toc_entry_type, 12 + 4 * toc_entry_type, 1) +
              entry)
    return header(order, 0, toc_offset) + body + toc


def unknown_file(order):
    # An object of a type no QuickDraw 3D class has, between two points.
    point = obj(order, b"pnt ", floats(order, 1, 2, 3))
    mine = obj(order, b"MiNe", b"\x01\x02\x03\x04\x05\x06\x07\x08")
    return header(order, 1, 0) + point + mine + point


for name, data in [("triangle_be.3dmf", triangle_file(">")), ("triangle_le.3dmf", triangle_file("<")),
                   ("references_be.3dmf", references_file(">")),
                   ("references_le.3dmf", references_file("<")),
                   ("references_toc0_be.3dmf", references_file(">", 0)), ("unknown_be.3dmf", unknown_file(">"))]:
    with open(os.path.join(here, name), "wb") as f:
        f.write(data)
