#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Copyright (c) 2026 The Q3 authors
#
# Writes the binary twins of curves_quadrics.3dmf, attributes.3dmf,
# styles_shaders.3dmf and lights_transforms_groups.3dmf, laid out field by
# field as the 3D Metafile Reference, Apple's metafile parser (MF3D) and the
# QD3D 1.5.4 book describe each class (enumerations and booleans as 32-bit
# values, flags as 32-bit masks): big-endian as Mac QuickDraw 3D wrote them,
# and little-endian. Run from anywhere: python3 tests/data/make_catalog_binary.py
import os
import struct

from mf3d import color_set, floats, header, ints, obj, uns, write_both

here = os.path.dirname(os.path.abspath(__file__))


def container(order, *parts):
    return obj(order, b"cntr", b"".join(parts))


def empty(order, tag):
    return obj(order, tag, b"")


def curves_quadrics_file(order):
    nrbc = obj(order, b"nrbc", uns(order, 3, 4)
               + floats(order, 0, 0, 0, 1, 2, 4, 0, 2, 2, -1, 0, 1, 3, 0, 0, 1)
               + floats(order, 0, 0, 0, 0.5, 1, 1, 1))
    disk = obj(order, b"disk", floats(order, 1, 0, 0, 0, 2, 0, 0, 0, 1, 0, 0.5, 0, 1))
    elps = obj(order, b"elps", floats(order, 2, 0, 0, 0, 1, 0, 0, 0, -1, 0.25, 0.75))
    elpd = obj(order, b"elpd", floats(order, 0, 0, 1, 0, 1, 0, 1, 0, 0, 0, 0, -2))
    cone = obj(order, b"cone", floats(order, 0, 2, 0, 1, 0, 0, 0, 0, 1, 3, 0, 0))
    caps = obj(order, b"caps", uns(order, 2))  # Bottom
    bottom = container(order, empty(order, b"bcas"), color_set(order, 0, 1, 0))
    tors = obj(order, b"tors", floats(order, 0, 0.5, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0.5))
    line = obj(order, b"line", floats(order, 0, 0, 0, 1, 1, 1))
    vasl = container(order, obj(order, b"vasl", uns(order, 2, 0, 1, 0)), color_set(order, 1, 0, 0))
    plyg = obj(order, b"plyg", uns(order, 4) + floats(order, 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0))
    pnt = obj(order, b"pnt ", floats(order, 1, 2, 3))
    return (header(order)
            + container(order, nrbc, color_set(order, 1, 0.5, 0))
            + container(order, disk, color_set(order, 0, 0, 1))
            + elps
            + container(order, elpd, color_set(order, 0.5, 0.5, 0.5))
            + container(order, cone, caps, bottom)
            + tors
            + container(order, line, vasl)
            + container(order, plyg, color_set(order, 0.25, 0.75, 1))
            + container(order, pnt, color_set(order, 1, 1, 1)))


def attributes_file(order):
    trng = obj(order, b"trng", floats(order, 0, 0, 0, 1, 0, 0, 0, 1, 0))
    attributes = container(order, empty(order, b"attr"),
                           obj(order, b"sruv", floats(order, 0.25, 0.75)),
                           obj(order, b"shuv", floats(order, 0.5, 0.125)),
                           obj(order, b"nrml", floats(order, 0, 0, 1)),
                           obj(order, b"camb", floats(order, 0.4)),
                           obj(order, b"kdif", floats(order, 0.2, 0.4, 0.6)),
                           obj(order, b"kspc", floats(order, 1, 1, 0.5)),
                           obj(order, b"cspc", floats(order, 16)),
                           obj(order, b"kxpr", floats(order, 0.5, 0.25, 0.75)),
                           obj(order, b"srtn", floats(order, 1, 0, 0, 0, 1, 0)),
                           obj(order, b"hlst", uns(order, 1)))  # On
    # Five points and four triangles: indices are one byte each (the counts
    # are at most 0xFF), twelve of them, so the points start 4-aligned.
    tmsh = obj(order, b"tmsh", uns(order, 4, 1, 0, 0, 5, 1)
               + bytes([0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4])
               + floats(order, -1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0, 0, 0, 1)
               + floats(order, -1, -1, 0, 1, 1, 1) + uns(order, 0))
    colors = obj(order, b"atar", ints(order, 5) + uns(order, 0, 0, 0, 1) + bytes([1, 0, 1, 1])
                 + floats(order, 1, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 0))
    normals = obj(order, b"atar", ints(order, 3) + uns(order, 0, 2, 0, 0)
                  + floats(order, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0.6, 0.8))
    return header(order, 1) + container(order, trng, attributes) + container(order, tmsh, colors, normals)


def styles_shaders_file(order):
    # Every object is listed in the table of contents (entry type 1: refID,
    # file offset, type), as a Database file's must be.
    objects = [
        (b"sbdv", uns(order, 1) + floats(order, 0.5)),                   # WorldSpace 0.5
        (b"anti", uns(order, 1, 3) + floats(order, 0.75)),               # On, Edges | Filled
        (b"fogg", uns(order, 1, 1) + floats(order, 2, 40, 0.25, 0.5, 0.7, 0.8, 0.9)),  # On, Exponential
        (b"intp", uns(order, 2)),                                        # Pixel
        (b"ofdr", uns(order, 1)),                                        # Clockwise
        (b"pkid", uns(order, 4242)),
        (b"pkpt", uns(order, 5)),                                        # Face | Vertex
        (b"cash", uns(order, 0)),                                        # False
        (b"rcsh", uns(order, 1)),                                        # True
        (b"bckf", uns(order, 1)),                                        # Remove
        (b"fist", uns(order, 1)),                                        # Edges
        (b"lmil", b""),
        (b"nuil", b""),
        (b"phil", b""),
    ]
    body = b""
    entries = b""
    for ref_id, (tag, data) in enumerate(objects, start=1):
        entries += uns(order, ref_id) + struct.pack(order + "Q", 24 + len(body)) + (tag if order == ">" else tag[::-1])
        body += obj(order, tag, data)
    body += obj(order, b"rfrn", uns(order, 6))
    toc_offset = 24 + len(body)
    toc = obj(order, b"toc ", struct.pack(order + "QIiIII", 0, len(objects) + 1, 0, 1, 16, len(objects)) + entries)
    return header(order, 2, toc_offset) + body + toc


def group(order, root, *members):
    return obj(order, b"bgng", root) + b"".join(members) + empty(order, b"endg")


def light(order, tag, data, is_on, brightness, r, g, b):
    return container(order, obj(order, tag, data), obj(order, b"lght", uns(order, is_on) + floats(order, brightness, r, g, b)))


def lights_transforms_groups_file(order):
    lights = group(order, empty(order, b"lghg"),
                   light(order, b"ambn", b"", 1, 0.25, 1, 0.9, 0.8),
                   light(order, b"drct", floats(order, 0, -1, 0) + uns(order, 1), 0, 0.5, 0.2, 0.3, 0.4),
                   light(order, b"pntl", floats(order, 1, 2, 3) + uns(order, 1, 0), 1, 0.75, 1, 1, 1),
                   light(order, b"spot", floats(order, 0, 5, 0, 0, -1, 0) + uns(order, 1, 2) + floats(order, 0.3, 0.6)
                         + uns(order, 3), 1, 1, 0.5, 0.5, 1))
    ordered = group(order, empty(order, b"ordg"),
                    container(order, empty(order, b"high"), color_set(order, 1, 1, 0)),
                    obj(order, b"pnt ", floats(order, 0, 0, 0)))
    proxy = group(order, empty(order, b"iopx"),
                  obj(order, b"pnt ", floats(order, 1, 0, 0)),
                  obj(order, b"line", floats(order, 0, 0, 0, 1, 0, 0)))
    display = group(order, container(order, empty(order, b"dspg"), obj(order, b"dgst", uns(order, 1 | 16))),
                    ordered, proxy)  # Inline | DoNotPick
    outer = group(order, empty(order, b"grup"),
                  obj(order, b"mtrx", floats(order, 1, 0, 0, 0, 0, 2, 0, 0, 0, 0, 3, 0, 4, 5, 6, 1)),
                  obj(order, b"trns", floats(order, 1, -2, 3)),
                  obj(order, b"scal", floats(order, 2, 3, 4)),
                  obj(order, b"rott", uns(order, 1) + floats(order, 1.5)),  # Y
                  empty(order, b"rset"),
                  display,
                  group(order, empty(order, b"info")))
    return header(order) + lights + outer


def main():
    for name, make in [("curves_quadrics", curves_quadrics_file), ("attributes", attributes_file),
                       ("styles_shaders", styles_shaders_file),
                       ("lights_transforms_groups", lights_transforms_groups_file)]:
        write_both(here, name, make)


if __name__ == "__main__":
    main()
